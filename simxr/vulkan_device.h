// The application's Vulkan device as simxr uses it (from XrGraphicsBindingVulkan2KHR): function
// pointers loaded through the application's instance, and one-shot command submission on the
// binding's queue. XR_KHR_vulkan_enable2 lets the runtime use that queue inside xrEndFrame and
// the swapchain calls; the application synchronizes its own use of it.
#pragma once

#include <functional>

#include <vulkan/vulkan.h>

namespace monoplane::simxr {

// A zeroed Vulkan structure with its sType set.
template <class T>
T vk_struct(VkStructureType type) {
    T structure{};
    structure.sType = type;
    return structure;
}

#define SIMXR_INSTANCE_FUNCTIONS(X)        \
    X(vkGetDeviceProcAddr)                 \
    X(vkGetPhysicalDeviceMemoryProperties) \
    X(vkGetPhysicalDeviceImageFormatProperties)

#define SIMXR_DEVICE_FUNCTIONS(X)    \
    X(vkGetDeviceQueue)              \
    X(vkCreateCommandPool)           \
    X(vkDestroyCommandPool)          \
    X(vkAllocateCommandBuffers)      \
    X(vkFreeCommandBuffers)          \
    X(vkBeginCommandBuffer)          \
    X(vkEndCommandBuffer)            \
    X(vkCmdPipelineBarrier)          \
    X(vkCmdCopyImageToBuffer)        \
    X(vkQueueSubmit)                 \
    X(vkCreateFence)                 \
    X(vkDestroyFence)                \
    X(vkWaitForFences)               \
    X(vkCreateImage)                 \
    X(vkDestroyImage)                \
    X(vkGetImageMemoryRequirements)  \
    X(vkBindImageMemory)             \
    X(vkCreateBuffer)                \
    X(vkDestroyBuffer)               \
    X(vkGetBufferMemoryRequirements) \
    X(vkBindBufferMemory)            \
    X(vkAllocateMemory)              \
    X(vkFreeMemory)                  \
    X(vkMapMemory)                   \
    X(vkUnmapMemory)

struct VulkanBinding {
    VkInstance instance = VK_NULL_HANDLE;
    VkPhysicalDevice physical_device = VK_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;
    uint32_t queue_family_index = 0;
    uint32_t queue_index = 0;
};

class VulkanDevice {
  public:
    // Loads the functions and creates a command pool; false if any step fails.
    bool init(PFN_vkGetInstanceProcAddr get_instance_proc_addr, const VulkanBinding& binding);
    // Destroys what init created. The caller has waited for its own submissions (each is waited).
    void destroy();

    // Records with `record`, submits to the binding's queue and waits for the fence.
    bool submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const;

    // A memory type among `type_bits` with all `properties`, or UINT32_MAX.
    uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags properties) const;

    const VulkanBinding& binding() const { return binding_; }
    VkDevice device() const { return binding_.device; }

#define SIMXR_DECLARE(name) PFN_##name name = nullptr;
    SIMXR_INSTANCE_FUNCTIONS(SIMXR_DECLARE)
    SIMXR_DEVICE_FUNCTIONS(SIMXR_DECLARE)
#undef SIMXR_DECLARE

  private:
    VulkanBinding binding_;
    VkQueue queue_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
};

}  // namespace monoplane::simxr
