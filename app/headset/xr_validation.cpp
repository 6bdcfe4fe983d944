#include "app/headset/xr_validation.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <string_view>

#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace monoplane::headset {
namespace {

XRAPI_ATTR XrBool32 XRAPI_CALL record_message(XrDebugUtilsMessageSeverityFlagsEXT severity,
                                              XrDebugUtilsMessageTypeFlagsEXT,
                                              const XrDebugUtilsMessengerCallbackDataEXT* data,
                                              void* user_data) {
    auto* messages = static_cast<vk_core::ValidationMessages*>(user_data);
    std::string text = "OpenXR ";
    text += (severity & XR_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) != 0 ? "error" : "warning";
    if (data->functionName != nullptr) text += std::string(" in ") + data->functionName;
    if (data->messageId != nullptr) text += std::string(" [") + data->messageId + "]";
    if (data->message != nullptr) text += std::string(": ") + data->message;
    messages->record(text);
    return XR_FALSE;  // the spec: the callback must return XR_FALSE
}

bool layer_installed(const char* name) {
    std::uint32_t count = 0;
    if (XR_FAILED(xrEnumerateApiLayerProperties(0, &count, nullptr))) return false;
    std::vector<XrApiLayerProperties> layers(count, {XR_TYPE_API_LAYER_PROPERTIES});
    if (XR_FAILED(xrEnumerateApiLayerProperties(count, &count, layers.data()))) return false;
    return std::any_of(layers.begin(), layers.end(), [&](const XrApiLayerProperties& layer) {
        return std::strcmp(layer.layerName, name) == 0;
    });
}

// XR_EXT_debug_utils is offered by the loader itself or by the layer.
bool extension_offered(const char* layer, const char* name) {
    std::uint32_t count = 0;
    if (XR_FAILED(xrEnumerateInstanceExtensionProperties(layer, 0, &count, nullptr))) return false;
    std::vector<XrExtensionProperties> extensions(count, {XR_TYPE_EXTENSION_PROPERTIES});
    if (XR_FAILED(xrEnumerateInstanceExtensionProperties(layer, count, &count, extensions.data())))
        return false;
    return std::any_of(extensions.begin(), extensions.end(), [&](const XrExtensionProperties& e) {
        return std::strcmp(e.extensionName, name) == 0;
    });
}

// Whether XR_ENABLE_API_LAYERS (the loader's list, separated by ':') already names the layer:
// the loader then enables it itself, and naming it again in xrCreateInstance makes Debian 12's
// loader fail with XR_ERROR_API_LAYER_NOT_PRESENT.
bool enabled_by_environment(const char* name) {
    const char* list = std::getenv("XR_ENABLE_API_LAYERS");
    if (list == nullptr) return false;
    std::string_view rest(list);
    while (!rest.empty()) {
        const std::size_t end = rest.find(':');
        if (rest.substr(0, end) == name) return true;
        if (end == std::string_view::npos) break;
        rest.remove_prefix(end + 1);
    }
    return false;
}

}  // namespace

Result<XrValidation> XrValidation::plan(bool requested) {
    XrValidation validation;
    if (!requested) return validation;
    if (!layer_installed(kXrValidationLayer)) {
        return Error{std::string("--validation needs the OpenXR validation layer ") +
                     kXrValidationLayer +
                     ", which the OpenXR loader does not find: install Debian's "
                     "openxr-layer-corevalidation (scripts/install-deps.sh does)"};
    }
    if (!extension_offered(nullptr, XR_EXT_DEBUG_UTILS_EXTENSION_NAME) &&
        !extension_offered(kXrValidationLayer, XR_EXT_DEBUG_UTILS_EXTENSION_NAME)) {
        return Error{std::string("--validation needs ") + XR_EXT_DEBUG_UTILS_EXTENSION_NAME +
                     " to receive the OpenXR validation layer's messages, and neither the "
                     "loader nor the layer offers it"};
    }
    if (!enabled_by_environment(kXrValidationLayer)) validation.layers_ = {kXrValidationLayer};
    validation.extensions_ = {XR_EXT_DEBUG_UTILS_EXTENSION_NAME};
    return validation;
}

Result<void> XrValidation::attach(XrInstance instance) {
    if (!enabled()) return Ok{};
    PFN_xrCreateDebugUtilsMessengerEXT create = nullptr;
    if (XR_FAILED(xrGetInstanceProcAddr(instance, "xrCreateDebugUtilsMessengerEXT",
                                        reinterpret_cast<PFN_xrVoidFunction*>(&create))) ||
        create == nullptr) {
        return Error{
            "the OpenXR loader enabled XR_EXT_debug_utils but has no "
            "xrCreateDebugUtilsMessengerEXT"};
    }
    XrDebugUtilsMessengerCreateInfoEXT info{XR_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
    info.messageSeverities = XR_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                             XR_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageTypes = XR_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                        XR_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                        XR_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT |
                        XR_DEBUG_UTILS_MESSAGE_TYPE_CONFORMANCE_BIT_EXT;
    info.userCallback = &record_message;
    info.userData = messages_.get();
    const XrResult result = create(instance, &info, &messenger_);
    if (XR_FAILED(result)) {
        return Error{"xrCreateDebugUtilsMessengerEXT failed: XrResult " +
                     std::to_string(static_cast<int>(result))};
    }
    instance_ = instance;
    // Debian's layer (OpenXR SDK 1.0.20) hands messages to messengers only once some object has
    // a debug name (its CoreValidLogMessage tests debug_data.Empty()); without one they go to
    // stdout alone and would not fail the command. Naming the instance makes them arrive.
    PFN_xrSetDebugUtilsObjectNameEXT set_name = nullptr;
    xrGetInstanceProcAddr(instance, "xrSetDebugUtilsObjectNameEXT",
                          reinterpret_cast<PFN_xrVoidFunction*>(&set_name));
    if (set_name != nullptr) {
        XrDebugUtilsObjectNameInfoEXT name{XR_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
        name.objectType = XR_OBJECT_TYPE_INSTANCE;
        name.objectHandle = reinterpret_cast<std::uint64_t>(instance);
        name.objectName = "monoplane";
        set_name(instance, &name);
    }
    return Ok{};
}

void XrValidation::detach() {
    if (messenger_ == XR_NULL_HANDLE) return;
    PFN_xrDestroyDebugUtilsMessengerEXT destroy = nullptr;
    if (XR_SUCCEEDED(xrGetInstanceProcAddr(instance_, "xrDestroyDebugUtilsMessengerEXT",
                                           reinterpret_cast<PFN_xrVoidFunction*>(&destroy))) &&
        destroy != nullptr) {
        destroy(messenger_);
    }
    messenger_ = XR_NULL_HANDLE;
    instance_ = XR_NULL_HANDLE;
}

}  // namespace monoplane::headset
