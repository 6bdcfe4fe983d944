// What the OpenXrHeadset's files share (openxr_headset.cpp and its openxr_*.cpp siblings): the
// OpenXR and Vulkan handles of one headset behind OpenXrHeadset's pointer, and how an OpenXR
// call's failure becomes an Error. Only those files include it; nothing of OpenXR's headers
// reaches openxr_headset.h.
#pragma once

#include <vulkan/vulkan.h>
// openxr_platform.h declares the Vulkan binding only when asked to and after vulkan.h.
#define XR_USE_GRAPHICS_API_VULKAN
// And XR_KHR_convert_timespec_time only with timespec asked for.
#define XR_USE_TIMESPEC
#include <time.h>

#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "app/headset/openxr_headset.h"
#include "app/headset/xr_validation.h"

// OpenXR's structures are initialised the way its specification shows, `XrFoo foo{XR_TYPE_FOO}`:
// the remaining members are zeroed, which is what is wanted, not an omission. This holds in every
// file that includes this one.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace monoplane::headset {

inline std::string result_text(XrInstance instance, XrResult result) {
    char text[XR_MAX_RESULT_STRING_SIZE] = {};
    if (instance == XR_NULL_HANDLE || XR_FAILED(xrResultToString(instance, result, text))) {
        return "XrResult " + std::to_string(static_cast<int>(result));
    }
    return text;
}

inline Error xr_error(XrInstance instance, const char* call, XrResult result) {
    return Error{std::string(call) + " failed: " + result_text(instance, result)};
}

// The runtime is gone for this session: the instance or the session was lost (Monado's client
// answers XR_ERROR_INSTANCE_LOST to every call once its service's IPC connection broke).
inline bool is_loss(XrResult result) {
    return result == XR_ERROR_INSTANCE_LOST || result == XR_ERROR_SESSION_LOST;
}

struct OpenXrHeadset::Impl {
    XrInstance instance = XR_NULL_HANDLE;
    XrValidation validation;
    XrSystemId system = XR_NULL_SYSTEM_ID;
    XrSession session = XR_NULL_HANDLE;
    VkDevice device = VK_NULL_HANDLE;  // the session's: its swapchain images live there
    // The runtime lost the instance or the session (OpenXrHeadset::lost). Mutable: any call,
    // const ones included, may be the one that hears it.
    mutable bool lost = false;
    XrSpace local = XR_NULL_HANDLE;
    XrActionSet action_set = XR_NULL_HANDLE;
    std::array<XrAction, 3> actions{};  // indexed by Control
    // XR_EXT_eye_gaze_interaction: enabled, and the system tracks the eyes (OpenXrHeadset::
    // tracks_eye_gaze); then the gaze pose action, its space and the VIEW space it is located in.
    bool eye_gaze = false;
    // The runtime offered XR_EXT_eye_gaze_interaction and create enabled it (asked for), whether
    // or not the system tracks the eyes (OpenXrHeadset::offers_eye_gaze).
    bool eye_gaze_offered = false;
    XrAction gaze_action = XR_NULL_HANDLE;
    XrSpace gaze_space = XR_NULL_HANDLE;
    XrSpace view = XR_NULL_HANDLE;
    Result<void> create_gaze_action();
    struct Swapchain {
        XrSwapchain handle = XR_NULL_HANDLE;
        std::vector<XrSwapchainImageVulkan2KHR> images;
        bool acquired = false;
    };
    std::array<Swapchain, 2> swapchains;
    // XR_KHR_composition_layer_depth: enabled on the instance, and the eyes' depth swapchains
    // (none without the extension or a depth format in common).
    bool depth_extension = false;
    std::array<Swapchain, 2> depth_swapchains;
    std::array<XrView, 2> views{};
    bool views_located = false;
    std::int64_t frame_index = -1;

    PFN_xrGetVulkanGraphicsRequirements2KHR get_requirements = nullptr;
    PFN_xrCreateVulkanInstanceKHR create_vk_instance = nullptr;
    PFN_xrGetVulkanGraphicsDevice2KHR get_vk_device = nullptr;
    PFN_xrCreateVulkanDeviceKHR create_vk_device = nullptr;
    // XR_KHR_convert_timespec_time, where offered: the runtime's time of a CLOCK_MONOTONIC time
    // (an answer key's press).
    PFN_xrConvertTimespecTimeToTimeKHR timespec_to_time = nullptr;

    Result<void> check(const char* call, XrResult result) const {
        if (!XR_FAILED(result)) return Ok{};
        if (is_loss(result)) lost = true;
        return xr_error(instance, call, result);
    }
    // xrCreateInstance with these extensions and the validation's layers, then its messenger
    // (this and load_vulkan_functions: openxr_headset.cpp).
    Result<void> create_instance(const std::vector<const char*>& extensions);
    // The XR_KHR_vulkan_enable2 functions, from the instance.
    Result<void> load_vulkan_functions();
    // The action set, its actions and their suggested bindings (openxr_controls.cpp).
    Result<void> create_actions();
    // The primary stereo configuration's two views (recommended and maximum image sizes); it
    // and the swapchains' functions are in openxr_swapchains.cpp.
    Result<std::array<XrViewConfigurationView, 2>> view_configuration() const;
    Result<void> create_swapchains(const vk_core::Context& ctx, double scale, vk::Extent2D& extent,
                                   vk::Format& format, vk::Format& depth_format);
    Result<void> create_swapchain(Swapchain& swapchain, XrSwapchainUsageFlags usage,
                                  std::int64_t format, vk::Extent2D extent);
    Result<vk::Image> acquire(Swapchain& swapchain);
};

}  // namespace monoplane::headset
