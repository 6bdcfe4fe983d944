#include "simxr/vulkan_device.h"

#include <cstdint>

namespace monoplane::simxr {

bool VulkanDevice::init(PFN_vkGetInstanceProcAddr get_instance_proc_addr,
                        const VulkanBinding& binding) {
    binding_ = binding;
    bool all_found = true;
#define SIMXR_LOAD_INSTANCE(name)                                                         \
    name = reinterpret_cast<PFN_##name>(get_instance_proc_addr(binding.instance, #name)); \
    all_found = all_found && name != nullptr;
    SIMXR_INSTANCE_FUNCTIONS(SIMXR_LOAD_INSTANCE)
#undef SIMXR_LOAD_INSTANCE
    if (!all_found) return false;
#define SIMXR_LOAD_DEVICE(name)                                                      \
    name = reinterpret_cast<PFN_##name>(vkGetDeviceProcAddr(binding.device, #name)); \
    all_found = all_found && name != nullptr;
    SIMXR_DEVICE_FUNCTIONS(SIMXR_LOAD_DEVICE)
#undef SIMXR_LOAD_DEVICE
    if (!all_found) return false;

    vkGetDeviceQueue(binding.device, binding.queue_family_index, binding.queue_index, &queue_);
    auto pool_info = vk_struct<VkCommandPoolCreateInfo>(VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO);
    pool_info.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
    pool_info.queueFamilyIndex = binding.queue_family_index;
    return vkCreateCommandPool(binding.device, &pool_info, nullptr, &pool_) == VK_SUCCESS;
}

void VulkanDevice::destroy() {
    if (pool_ != VK_NULL_HANDLE) vkDestroyCommandPool(binding_.device, pool_, nullptr);
    pool_ = VK_NULL_HANDLE;
}

bool VulkanDevice::submit_and_wait(const std::function<void(VkCommandBuffer)>& record) const {
    auto allocate =
        vk_struct<VkCommandBufferAllocateInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO);
    allocate.commandPool = pool_;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    VkCommandBuffer commands = VK_NULL_HANDLE;
    if (vkAllocateCommandBuffers(binding_.device, &allocate, &commands) != VK_SUCCESS) return false;

    auto begin = vk_struct<VkCommandBufferBeginInfo>(VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO);
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vkBeginCommandBuffer(commands, &begin);
    record(commands);
    vkEndCommandBuffer(commands);

    auto fence_info = vk_struct<VkFenceCreateInfo>(VK_STRUCTURE_TYPE_FENCE_CREATE_INFO);
    VkFence fence = VK_NULL_HANDLE;
    bool ok = vkCreateFence(binding_.device, &fence_info, nullptr, &fence) == VK_SUCCESS;
    if (ok) {
        auto submit = vk_struct<VkSubmitInfo>(VK_STRUCTURE_TYPE_SUBMIT_INFO);
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &commands;
        ok = vkQueueSubmit(queue_, 1, &submit, fence) == VK_SUCCESS &&
             vkWaitForFences(binding_.device, 1, &fence, VK_TRUE, UINT64_MAX) == VK_SUCCESS;
        vkDestroyFence(binding_.device, fence, nullptr);
    }
    vkFreeCommandBuffers(binding_.device, pool_, 1, &commands);
    return ok;
}

uint32_t VulkanDevice::memory_type(uint32_t type_bits, VkMemoryPropertyFlags properties) const {
    VkPhysicalDeviceMemoryProperties memory{};
    vkGetPhysicalDeviceMemoryProperties(binding_.physical_device, &memory);
    for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        if ((type_bits & (1u << i)) != 0 &&
            (memory.memoryTypes[i].propertyFlags & properties) == properties) {
            return i;
        }
    }
    return UINT32_MAX;
}

}  // namespace monoplane::simxr
