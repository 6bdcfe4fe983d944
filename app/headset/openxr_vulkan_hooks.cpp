// The Vulkan instance and device of an OpenXR session, made by the runtime
// (XR_KHR_vulkan_enable2): the hooks vk_core::Context::create calls instead of its own
// vkCreateInstance, physical device choice and vkCreateDevice.
#include <iostream>
#include <string>

#include "app/headset/openxr_headset_impl.h"

namespace monoplane::headset {

vk_core::ContextCreationHooks OpenXrHeadset::vulkan_hooks() {
    Impl* impl = impl_.get();
    vk_core::ContextCreationHooks hooks;
    hooks.create_instance = [impl](const VkInstanceCreateInfo& info) -> Result<VkInstance> {
        // The spec requires the requirements to be queried before a session is created; monoplane
        // needs Vulkan 1.3, so a runtime whose maximum is lower cannot work with it.
        XrGraphicsRequirementsVulkan2KHR requirements{XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN2_KHR};
        XrResult result = impl->get_requirements(impl->instance, impl->system, &requirements);
        if (XR_FAILED(result)) {
            return xr_error(impl->instance, "xrGetVulkanGraphicsRequirements2KHR", result);
        }
        if (requirements.maxApiVersionSupported < XR_MAKE_VERSION(1, 3, 0)) {
            std::cerr << "warning: the OpenXR runtime was tested with Vulkan up to "
                      << XR_VERSION_MAJOR(requirements.maxApiVersionSupported) << "."
                      << XR_VERSION_MINOR(requirements.maxApiVersionSupported)
                      << "; monoplane uses 1.3\n";
        }
        XrVulkanInstanceCreateInfoKHR create{XR_TYPE_VULKAN_INSTANCE_CREATE_INFO_KHR};
        create.systemId = impl->system;
        create.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
        create.vulkanCreateInfo = &info;
        VkInstance instance = VK_NULL_HANDLE;
        VkResult vk_result = VK_SUCCESS;
        result = impl->create_vk_instance(impl->instance, &create, &instance, &vk_result);
        if (XR_FAILED(result)) return xr_error(impl->instance, "xrCreateVulkanInstanceKHR", result);
        if (vk_result != VK_SUCCESS) {
            return Error{"vkCreateInstance through the OpenXR runtime failed: VkResult " +
                         std::to_string(static_cast<int>(vk_result))};
        }
        return instance;
    };
    hooks.physical_device = [impl](VkInstance instance) -> Result<VkPhysicalDevice> {
        XrVulkanGraphicsDeviceGetInfoKHR get{XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR};
        get.systemId = impl->system;
        get.vulkanInstance = instance;
        VkPhysicalDevice device = VK_NULL_HANDLE;
        const XrResult result = impl->get_vk_device(impl->instance, &get, &device);
        if (XR_FAILED(result)) {
            return xr_error(impl->instance, "xrGetVulkanGraphicsDevice2KHR", result);
        }
        return device;
    };
    hooks.create_device = [impl](VkPhysicalDevice physical,
                                 const VkDeviceCreateInfo& info) -> Result<VkDevice> {
        XrVulkanDeviceCreateInfoKHR create{XR_TYPE_VULKAN_DEVICE_CREATE_INFO_KHR};
        create.systemId = impl->system;
        create.pfnGetInstanceProcAddr = &vkGetInstanceProcAddr;
        create.vulkanPhysicalDevice = physical;
        create.vulkanCreateInfo = &info;
        VkDevice device = VK_NULL_HANDLE;
        VkResult vk_result = VK_SUCCESS;
        const XrResult result =
            impl->create_vk_device(impl->instance, &create, &device, &vk_result);
        if (XR_FAILED(result)) return xr_error(impl->instance, "xrCreateVulkanDeviceKHR", result);
        if (vk_result != VK_SUCCESS) {
            return Error{"vkCreateDevice through the OpenXR runtime failed: VkResult " +
                         std::to_string(static_cast<int>(vk_result))};
        }
        return device;
    };
    return hooks;
}

}  // namespace monoplane::headset
