// Instance, system and view configuration: what an application asks before it has a session.
#include <cstdio>
#include <cstring>
#include <iterator>
#include <string_view>

#include "simxr/entry_points.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {
namespace {

constexpr XrVersion kRuntimeVersion = XR_MAKE_VERSION(0, 1, 0);
// The largest image any Vulkan 1.3 device must support in practice; simxr itself has no limit.
constexpr uint32_t kMaxSwapchainSize = 16384;
// spec 10.5: at least 16 layers must be supported.
constexpr uint32_t kMaxLayerCount = 16;

struct Extension {
    std::string_view name;
    uint32_t version;
};
// What xrEnumerateInstanceExtensionProperties lists; xrCreateInstance refuses any other.
constexpr Extension kExtensions[] = {
    {XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME, XR_KHR_vulkan_enable2_SPEC_VERSION},
    {XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME, XR_KHR_composition_layer_depth_SPEC_VERSION},
    {XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME, XR_EXT_eye_gaze_interaction_SPEC_VERSION},
};

XrResult check_system(XrInstance handle, XrSystemId system, Instance** instance) {
    *instance = lookup<Instance>(handle);
    if (*instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (system != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    return XR_SUCCESS;
}

// check_system, and `type` must be the one view configuration simxr has.
XrResult check_stereo_system(XrInstance handle, XrSystemId system, XrViewConfigurationType type,
                             Instance** instance) {
    if (XrResult result = check_system(handle, system, instance); result != XR_SUCCESS) {
        return result;
    }
    if (type != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) {
        return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    }
    return XR_SUCCESS;
}

template <class T>
void copy_text(T& destination, std::string_view text) {
    const std::size_t length = std::min(text.size(), sizeof(destination) - 1);
    std::memcpy(destination, text.data(), length);
    destination[length] = '\0';
}

}  // namespace

XrResult XRAPI_CALL xrEnumerateApiLayerProperties(uint32_t capacity, uint32_t* count,
                                                  XrApiLayerProperties* properties) {
    return fill_array<XrApiLayerProperties>(capacity, count, properties, {});
}

XrResult XRAPI_CALL xrEnumerateInstanceExtensionProperties(const char* layer_name,
                                                           uint32_t capacity, uint32_t* count,
                                                           XrExtensionProperties* properties) {
    if (layer_name != nullptr) return XR_ERROR_API_LAYER_NOT_PRESENT;
    if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *count = static_cast<uint32_t>(std::size(kExtensions));
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < std::size(kExtensions)) return XR_ERROR_SIZE_INSUFFICIENT;
    if (properties == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    for (std::size_t i = 0; i < std::size(kExtensions); ++i) {
        if (properties[i].type != XR_TYPE_EXTENSION_PROPERTIES) return XR_ERROR_VALIDATION_FAILURE;
        copy_text(properties[i].extensionName, kExtensions[i].name);
        properties[i].extensionVersion = kExtensions[i].version;
    }
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrCreateInstance(const XrInstanceCreateInfo* info, XrInstance* instance) {
    std::lock_guard lock(runtime_mutex());
    if (!has_type(info, XR_TYPE_INSTANCE_CREATE_INFO) || instance == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    const XrVersion api = info->applicationInfo.apiVersion;
    if (XR_VERSION_MAJOR(api) != 1 || XR_VERSION_MINOR(api) != 0) {
        return XR_ERROR_API_VERSION_UNSUPPORTED;
    }
    if (info->applicationInfo.applicationName[0] == '\0') return XR_ERROR_NAME_INVALID;
    // API layers are the loader's business (it loads them and refuses missing ones); the create
    // info reaches the runtime with the application's layer names still in it, so they are ignored.
    bool vulkan_enable2 = false;
    bool composition_layer_depth = false;
    bool eye_gaze_interaction = false;
    for (uint32_t i = 0; i < info->enabledExtensionCount; ++i) {
        const std::string_view name = info->enabledExtensionNames[i];
        if (name == XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME) {
            vulkan_enable2 = true;
        } else if (name == XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME) {
            composition_layer_depth = true;
        } else if (name == XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME) {
            eye_gaze_interaction = true;
        } else {
            return XR_ERROR_EXTENSION_NOT_PRESENT;
        }
    }
    // The loader allows one instance at a time as well; simxr's state is per process.
    if (!live_objects<Instance>().empty()) return XR_ERROR_LIMIT_REACHED;

    auto script = load_script_from_environment();
    if (!script) {
        std::fprintf(stderr, "simxr: %s\n", script.error().message.c_str());
        return XR_ERROR_RUNTIME_FAILURE;
    }
    auto object = std::make_unique<Instance>();
    object->script = std::move(script).value();
    object->vulkan_enable2 = vulkan_enable2;
    object->composition_layer_depth = composition_layer_depth;
    object->eye_gaze_interaction = eye_gaze_interaction;
    *instance = register_object<XrInstance>(std::move(object));
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrDestroyInstance(XrInstance handle) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (instance->session != nullptr) destroy_session(instance->session);
    while (!instance->action_sets.empty()) destroy_action_set(instance->action_sets.back());
    unregister_object(instance);
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrGetInstanceProperties(XrInstance handle, XrInstanceProperties* properties) {
    std::lock_guard lock(runtime_mutex());
    if (lookup<Instance>(handle) == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(properties, XR_TYPE_INSTANCE_PROPERTIES)) return XR_ERROR_VALIDATION_FAILURE;
    properties->runtimeVersion = kRuntimeVersion;
    copy_text(properties->runtimeName, "monoplane simxr");
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrGetSystem(XrInstance handle, const XrSystemGetInfo* info,
                                XrSystemId* system) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_SYSTEM_GET_INFO) || system == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    // spec (xrGetSystem): a form factor the runtime does not support is
    // XR_ERROR_FORM_FACTOR_UNSUPPORTED, also one outside the enum (OpenXR-CTS passes
    // XR_FORM_FACTOR_MAX_ENUM); rejecting unknown enum values is the validation layer's job.
    if (info->formFactor != XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY) {
        return XR_ERROR_FORM_FACTOR_UNSUPPORTED;
    }
    instance->system_requested = true;
    *system = kSystemId;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrGetSystemProperties(XrInstance handle, XrSystemId system,
                                          XrSystemProperties* properties) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = nullptr;
    if (XrResult result = check_system(handle, system, &instance); result != XR_SUCCESS) {
        return result;
    }
    if (!has_type(properties, XR_TYPE_SYSTEM_PROPERTIES)) return XR_ERROR_VALIDATION_FAILURE;
    properties->systemId = kSystemId;
    properties->vendorId = 0;
    copy_text(properties->systemName, "monoplane simxr: " + instance->script.hmd.name);
    properties->graphicsProperties.maxSwapchainImageWidth = kMaxSwapchainSize;
    properties->graphicsProperties.maxSwapchainImageHeight = kMaxSwapchainSize;
    properties->graphicsProperties.maxLayerCount = kMaxLayerCount;
    properties->trackingProperties.orientationTracking = XR_TRUE;
    properties->trackingProperties.positionTracking = XR_TRUE;
    // XR_EXT_eye_gaze_interaction: whether the script's headset tracks the eyes.
    if (auto* gaze = static_cast<XrSystemEyeGazeInteractionPropertiesEXT*>(const_cast<void*>(
            find_in_chain(properties->next, XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT)))) {
        gaze->supportsEyeGazeInteraction =
            instance->eye_gaze_interaction && instance->script.gaze.tracker ? XR_TRUE : XR_FALSE;
    }
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrEnumerateEnvironmentBlendModes(XrInstance handle, XrSystemId system,
                                                     XrViewConfigurationType view_configuration,
                                                     uint32_t capacity, uint32_t* count,
                                                     XrEnvironmentBlendMode* modes) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = nullptr;
    if (XrResult result = check_stereo_system(handle, system, view_configuration, &instance);
        result != XR_SUCCESS) {
        return result;
    }
    return fill_array<XrEnvironmentBlendMode>(capacity, count, modes,
                                              {XR_ENVIRONMENT_BLEND_MODE_OPAQUE});
}

XrResult XRAPI_CALL xrEnumerateViewConfigurations(XrInstance handle, XrSystemId system,
                                                  uint32_t capacity, uint32_t* count,
                                                  XrViewConfigurationType* types) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = nullptr;
    if (XrResult result = check_system(handle, system, &instance); result != XR_SUCCESS) {
        return result;
    }
    return fill_array<XrViewConfigurationType>(capacity, count, types,
                                               {XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO});
}

XrResult XRAPI_CALL xrGetViewConfigurationProperties(XrInstance handle, XrSystemId system,
                                                     XrViewConfigurationType type,
                                                     XrViewConfigurationProperties* properties) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = nullptr;
    if (XrResult result = check_stereo_system(handle, system, type, &instance);
        result != XR_SUCCESS) {
        return result;
    }
    if (!has_type(properties, XR_TYPE_VIEW_CONFIGURATION_PROPERTIES)) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    properties->viewConfigurationType = type;
    properties->fovMutable = XR_FALSE;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrEnumerateViewConfigurationViews(XrInstance handle, XrSystemId system,
                                                      XrViewConfigurationType type,
                                                      uint32_t capacity, uint32_t* count,
                                                      XrViewConfigurationView* views) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = nullptr;
    if (XrResult result = check_stereo_system(handle, system, type, &instance);
        result != XR_SUCCESS) {
        return result;
    }
    if (count == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *count = 2;
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < 2) return XR_ERROR_SIZE_INSUFFICIENT;
    if (views == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    const auto width = static_cast<uint32_t>(instance->script.hmd.width);
    const auto height = static_cast<uint32_t>(instance->script.hmd.height);
    for (uint32_t i = 0; i < 2; ++i) {
        if (views[i].type != XR_TYPE_VIEW_CONFIGURATION_VIEW) return XR_ERROR_VALIDATION_FAILURE;
        // The profile's render-target size is both the recommendation and the limit: a
        // simulated display has no more pixels than the profile says.
        views[i].recommendedImageRectWidth = width;
        views[i].maxImageRectWidth = width;
        views[i].recommendedImageRectHeight = height;
        views[i].maxImageRectHeight = height;
        views[i].recommendedSwapchainSampleCount = 1;
        views[i].maxSwapchainSampleCount = 1;
    }
    return XR_SUCCESS;
}

}  // namespace monoplane::simxr
