// XR_KHR_vulkan_enable2: the runtime states its Vulkan requirements, creates the application's
// VkInstance and VkDevice on its behalf (adding nothing: simxr needs no Vulkan extension) and
// names the physical device the session must use.
#include <cstdio>
#include <string>
#include <vector>

#include "simxr/entry_points.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {
namespace {

XrResult check_instance_and_system(XrInstance handle, XrSystemId system, Instance** instance) {
    *instance = lookup<Instance>(handle);
    if (*instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (system != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    return XR_SUCCESS;
}

// The application's loader entry point if it gave one, else the Vulkan loader simxr links.
PFN_vkGetInstanceProcAddr instance_proc_addr(const Instance& instance) {
    return instance.vk_get_instance_proc_addr != nullptr ? instance.vk_get_instance_proc_addr
                                                         : &vkGetInstanceProcAddr;
}

}  // namespace

XrResult XRAPI_CALL xrGetVulkanGraphicsRequirements2KHR(
    XrInstance handle, XrSystemId system, XrGraphicsRequirementsVulkanKHR* requirements) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = nullptr;
    if (XrResult result = check_instance_and_system(handle, system, &instance);
        result != XR_SUCCESS) {
        return result;
    }
    if (!has_type(requirements, XR_TYPE_GRAPHICS_REQUIREMENTS_VULKAN2_KHR)) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    requirements->minApiVersionSupported = XR_MAKE_VERSION(1, 0, 0);
    requirements->maxApiVersionSupported = XR_MAKE_VERSION(1, 3, 0);
    instance->requirements_queried = true;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrCreateVulkanInstanceKHR(XrInstance handle,
                                              const XrVulkanInstanceCreateInfoKHR* info,
                                              VkInstance* vulkan_instance,
                                              VkResult* vulkan_result) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_VULKAN_INSTANCE_CREATE_INFO_KHR) || info->createFlags != 0 ||
        info->pfnGetInstanceProcAddr == nullptr || info->vulkanCreateInfo == nullptr ||
        vulkan_instance == nullptr || vulkan_result == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (info->systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    auto create = reinterpret_cast<PFN_vkCreateInstance>(
        info->pfnGetInstanceProcAddr(VK_NULL_HANDLE, "vkCreateInstance"));
    if (create == nullptr) return XR_ERROR_RUNTIME_FAILURE;
    *vulkan_result = create(info->vulkanCreateInfo, info->vulkanAllocator, vulkan_instance);
    if (*vulkan_result != VK_SUCCESS) return XR_ERROR_RUNTIME_FAILURE;
    instance->vk_get_instance_proc_addr = info->pfnGetInstanceProcAddr;
    instance->vk_instance = *vulkan_instance;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrGetVulkanGraphicsDevice2KHR(XrInstance handle,
                                                  const XrVulkanGraphicsDeviceGetInfoKHR* info,
                                                  VkPhysicalDevice* physical_device) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_VULKAN_GRAPHICS_DEVICE_GET_INFO_KHR) ||
        info->vulkanInstance == VK_NULL_HANDLE || physical_device == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (info->systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    const PFN_vkGetInstanceProcAddr get = instance_proc_addr(*instance);
    auto enumerate = reinterpret_cast<PFN_vkEnumeratePhysicalDevices>(
        get(info->vulkanInstance, "vkEnumeratePhysicalDevices"));
    auto properties_of = reinterpret_cast<PFN_vkGetPhysicalDeviceProperties>(
        get(info->vulkanInstance, "vkGetPhysicalDeviceProperties"));
    if (enumerate == nullptr || properties_of == nullptr) return XR_ERROR_RUNTIME_FAILURE;
    uint32_t count = 0;
    enumerate(info->vulkanInstance, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    enumerate(info->vulkanInstance, &count, devices.data());
    devices.resize(count);

    const std::string& wanted = instance->script.physical_device;
    std::string listed;
    for (VkPhysicalDevice device : devices) {
        VkPhysicalDeviceProperties properties{};
        properties_of(device, &properties);
        const std::string name = properties.deviceName;
        if (name.find(wanted) == std::string::npos) {
            listed += (listed.empty() ? "" : ", ") + name;
            continue;
        }
        instance->vk_instance = info->vulkanInstance;
        instance->named_physical_device = device;
        *physical_device = device;
        return XR_SUCCESS;
    }
    std::fprintf(stderr,
                 "simxr: %s: no Vulkan device name contains physical_device = \"%s\" "
                 "(devices: %s)\n",
                 instance->script.source.c_str(), wanted.c_str(), listed.c_str());
    return XR_ERROR_RUNTIME_FAILURE;
}

XrResult XRAPI_CALL xrCreateVulkanDeviceKHR(XrInstance handle,
                                            const XrVulkanDeviceCreateInfoKHR* info,
                                            VkDevice* vulkan_device, VkResult* vulkan_result) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_VULKAN_DEVICE_CREATE_INFO_KHR) || info->createFlags != 0 ||
        info->pfnGetInstanceProcAddr == nullptr || info->vulkanCreateInfo == nullptr ||
        vulkan_device == nullptr || vulkan_result == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (info->systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    // spec (XrVulkanDeviceCreateInfoKHR): the physical device must be the one
    // xrGetVulkanGraphicsDevice2KHR returned.
    if (info->vulkanPhysicalDevice == VK_NULL_HANDLE ||
        info->vulkanPhysicalDevice != instance->named_physical_device) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    auto create = reinterpret_cast<PFN_vkCreateDevice>(
        info->pfnGetInstanceProcAddr(instance->vk_instance, "vkCreateDevice"));
    if (create == nullptr) return XR_ERROR_RUNTIME_FAILURE;
    *vulkan_result = create(info->vulkanPhysicalDevice, info->vulkanCreateInfo,
                            info->vulkanAllocator, vulkan_device);
    if (*vulkan_result != VK_SUCCESS) return XR_ERROR_RUNTIME_FAILURE;
    instance->vk_get_instance_proc_addr = info->pfnGetInstanceProcAddr;
    return XR_SUCCESS;
}

}  // namespace monoplane::simxr
