// xrGetInstanceProcAddr: the loader asks for every core function of the API version (and the
// application for extension functions); names simxr does not implement get
// XR_ERROR_FUNCTION_UNSUPPORTED and a null pointer, as the spec requires.
#include <cstring>
#include <string_view>
#include <utility>

#include "simxr/entry_points.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {
namespace {

struct Entry {
    std::string_view name;
    PFN_xrVoidFunction function;
    bool needs_vulkan_enable2;
};

// After the instance is lost (the script's lose_instance_at_s) a call fails as a real
// runtime's does once its service is gone: XR_ERROR_INSTANCE_LOST. The stale-handle checks of the
// function itself come after, as the spec lists the loss first among a call's failures.
template <auto function>
struct UnlessLost;
template <class... Args, XrResult(XRAPI_PTR* function)(Args...)>
struct UnlessLost<function> {
    static XrResult XRAPI_CALL call(Args... args) {
        {
            std::lock_guard lock(runtime_mutex());
            if (instance_lost()) return XR_ERROR_INSTANCE_LOST;
        }
        return function(args...);
    }
};

template <auto function>
Entry entry(std::string_view name, bool needs_vulkan_enable2) {
    return {name, reinterpret_cast<PFN_xrVoidFunction>(&UnlessLost<function>::call),
            needs_vulkan_enable2};
}

Entry always_entry(std::string_view name, PFN_xrVoidFunction function) {
    return {name, function, false};
}

// SIMXR_CORE: fails once the instance is lost. SIMXR_ALWAYS: what an application still needs
// then, to hear of the loss (xrPollEvent), word it, and destroy what it holds.
#define SIMXR_CORE(name) entry<&name>(#name, false)
#define SIMXR_VULKAN2(name) entry<&name>(#name, true)
#define SIMXR_ALWAYS(name) always_entry(#name, reinterpret_cast<PFN_xrVoidFunction>(&name))

const Entry kEntries[] = {
    SIMXR_ALWAYS(xrGetInstanceProcAddr),
    SIMXR_ALWAYS(xrEnumerateApiLayerProperties),
    SIMXR_ALWAYS(xrEnumerateInstanceExtensionProperties),
    SIMXR_ALWAYS(xrCreateInstance),
    SIMXR_ALWAYS(xrDestroyInstance),
    SIMXR_CORE(xrGetInstanceProperties),
    SIMXR_ALWAYS(xrPollEvent),
    SIMXR_ALWAYS(xrResultToString),
    SIMXR_ALWAYS(xrStructureTypeToString),
    SIMXR_CORE(xrGetSystem),
    SIMXR_CORE(xrGetSystemProperties),
    SIMXR_CORE(xrEnumerateEnvironmentBlendModes),
    SIMXR_CORE(xrCreateSession),
    SIMXR_ALWAYS(xrDestroySession),
    SIMXR_CORE(xrEnumerateReferenceSpaces),
    SIMXR_CORE(xrCreateReferenceSpace),
    SIMXR_CORE(xrGetReferenceSpaceBoundsRect),
    SIMXR_CORE(xrCreateActionSpace),
    SIMXR_CORE(xrLocateSpace),
    SIMXR_ALWAYS(xrDestroySpace),
    SIMXR_CORE(xrEnumerateViewConfigurations),
    SIMXR_CORE(xrGetViewConfigurationProperties),
    SIMXR_CORE(xrEnumerateViewConfigurationViews),
    SIMXR_CORE(xrEnumerateSwapchainFormats),
    SIMXR_CORE(xrCreateSwapchain),
    SIMXR_ALWAYS(xrDestroySwapchain),
    SIMXR_CORE(xrEnumerateSwapchainImages),
    SIMXR_CORE(xrAcquireSwapchainImage),
    SIMXR_CORE(xrWaitSwapchainImage),
    SIMXR_CORE(xrReleaseSwapchainImage),
    SIMXR_CORE(xrBeginSession),
    SIMXR_CORE(xrEndSession),
    SIMXR_CORE(xrRequestExitSession),
    SIMXR_CORE(xrWaitFrame),
    SIMXR_CORE(xrBeginFrame),
    SIMXR_CORE(xrEndFrame),
    SIMXR_CORE(xrLocateViews),
    SIMXR_CORE(xrStringToPath),
    SIMXR_CORE(xrPathToString),
    SIMXR_CORE(xrCreateActionSet),
    SIMXR_ALWAYS(xrDestroyActionSet),
    SIMXR_CORE(xrCreateAction),
    SIMXR_ALWAYS(xrDestroyAction),
    SIMXR_CORE(xrSuggestInteractionProfileBindings),
    SIMXR_CORE(xrAttachSessionActionSets),
    SIMXR_CORE(xrGetCurrentInteractionProfile),
    SIMXR_CORE(xrGetActionStateBoolean),
    SIMXR_CORE(xrGetActionStateFloat),
    SIMXR_CORE(xrGetActionStateVector2f),
    SIMXR_CORE(xrGetActionStatePose),
    SIMXR_CORE(xrSyncActions),
    SIMXR_CORE(xrEnumerateBoundSourcesForAction),
    SIMXR_CORE(xrGetInputSourceLocalizedName),
    SIMXR_CORE(xrApplyHapticFeedback),
    SIMXR_CORE(xrStopHapticFeedback),
    SIMXR_VULKAN2(xrGetVulkanGraphicsRequirements2KHR),
    SIMXR_VULKAN2(xrCreateVulkanInstanceKHR),
    SIMXR_VULKAN2(xrGetVulkanGraphicsDevice2KHR),
    SIMXR_VULKAN2(xrCreateVulkanDeviceKHR),
};

#undef SIMXR_CORE
#undef SIMXR_ALWAYS
#undef SIMXR_VULKAN2

// spec (xrGetInstanceProcAddr): with XR_NULL_HANDLE only these may be queried.
bool allowed_without_instance(std::string_view name) {
    return name == "xrEnumerateInstanceExtensionProperties" ||
           name == "xrEnumerateApiLayerProperties" || name == "xrCreateInstance";
}

}  // namespace

std::mutex& runtime_mutex() {
    static std::mutex mutex;
    return mutex;
}

XrResult fill_string(uint32_t capacity, uint32_t* count_output, char* output,
                     const std::string& text) {
    if (count_output == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *count_output = static_cast<uint32_t>(text.size() + 1);
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < text.size() + 1) return XR_ERROR_SIZE_INSUFFICIENT;
    if (output == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    std::memcpy(output, text.c_str(), text.size() + 1);
    return XR_SUCCESS;
}

const void* find_in_chain(const void* next, XrStructureType type) {
    for (auto* header = static_cast<const XrBaseInStructure*>(next); header != nullptr;
         header = header->next) {
        if (header->type == type) return header;
    }
    return nullptr;
}

XrResult XRAPI_CALL xrGetInstanceProcAddr(XrInstance instance, const char* name,
                                          PFN_xrVoidFunction* function) {
    if (function == nullptr || name == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *function = nullptr;
    std::lock_guard lock(runtime_mutex());
    const Instance* object = nullptr;
    if (instance == XR_NULL_HANDLE) {
        if (!allowed_without_instance(name)) return XR_ERROR_HANDLE_INVALID;
    } else {
        object = lookup<Instance>(instance);
        if (object == nullptr) return XR_ERROR_HANDLE_INVALID;
    }
    for (const Entry& entry : kEntries) {
        if (entry.name != name) continue;
        // spec: functions of extensions the instance did not enable are unsupported.
        if (entry.needs_vulkan_enable2 && (object == nullptr || !object->vulkan_enable2)) break;
        *function = entry.function;
        return XR_SUCCESS;
    }
    return XR_ERROR_FUNCTION_UNSUPPORTED;
}

}  // namespace monoplane::simxr
