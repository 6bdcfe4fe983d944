// OpenXrHeadset's instance: the runtime's extensions, the XrInstance with its validation, the
// headset's system, and the functions the instance lends (XR_KHR_vulkan_enable2,
// XR_KHR_convert_timespec_time). The session and what runs in it are in the openxr_*.cpp files.
#include "app/headset/openxr_headset.h"

#include <algorithm>
#include <cstring>
#include <memory>

#include "app/headset/openxr_headset_impl.h"

namespace monoplane::headset {
namespace {

bool offers(const std::vector<XrExtensionProperties>& extensions, const char* name) {
    return std::any_of(
        extensions.begin(), extensions.end(),
        [name](const XrExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

// The runtime's instance extensions, or what to do when there is no runtime.
Result<std::vector<XrExtensionProperties>> runtime_extensions() {
    std::uint32_t count = 0;
    const XrResult result = xrEnumerateInstanceExtensionProperties(nullptr, 0, &count, nullptr);
    if (XR_FAILED(result)) {
        return Error{"no OpenXR runtime is available (" + result_text(XR_NULL_HANDLE, result) +
                     "): install and start one (SteamVR, Monado, Meta Quest Link) and make it "
                     "the active runtime, or set XR_RUNTIME_JSON to its manifest; for a dry run "
                     "without a headset use --headset simulated (docs/headsets.md)"};
    }
    std::vector<XrExtensionProperties> extensions(count, {XR_TYPE_EXTENSION_PROPERTIES});
    xrEnumerateInstanceExtensionProperties(nullptr, count, &count, extensions.data());
    return extensions;
}

}  // namespace

OpenXrHeadset::OpenXrHeadset(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

OpenXrHeadset::~OpenXrHeadset() {
    destroy_session();
    impl_->validation.detach();
    if (impl_->instance != XR_NULL_HANDLE) xrDestroyInstance(impl_->instance);
}

Result<void> OpenXrHeadset::Impl::create_instance(const std::vector<const char*>& extensions) {
    XrInstanceCreateInfo create{XR_TYPE_INSTANCE_CREATE_INFO};
    std::strncpy(create.applicationInfo.applicationName, "monoplane",
                 XR_MAX_APPLICATION_NAME_SIZE - 1);
    create.applicationInfo.applicationVersion = 1;
    std::strncpy(create.applicationInfo.engineName, "monoplane", XR_MAX_ENGINE_NAME_SIZE - 1);
    create.applicationInfo.engineVersion = 1;
    create.applicationInfo.apiVersion = XR_CURRENT_API_VERSION;
    create.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    create.enabledExtensionNames = extensions.data();
    create.enabledApiLayerCount = static_cast<std::uint32_t>(validation.layers().size());
    create.enabledApiLayerNames = validation.layers().data();
    const XrResult result = xrCreateInstance(&create, &instance);
    if (XR_FAILED(result)) {
        return Error{"the OpenXR runtime refused to create an instance (" +
                     result_text(XR_NULL_HANDLE, result) + ")"};
    }
    if (Result<void> attached = validation.attach(instance); !attached) {
        xrDestroyInstance(instance);
        instance = XR_NULL_HANDLE;
        return attached.error();
    }
    return Ok{};
}

Result<void> OpenXrHeadset::Impl::load_vulkan_functions() {
    const auto load = [&](const char* name, auto& function) {
        return XR_SUCCEEDED(xrGetInstanceProcAddr(
            instance, name, reinterpret_cast<PFN_xrVoidFunction*>(&function)));
    };
    if (!load("xrGetVulkanGraphicsRequirements2KHR", get_requirements) ||
        !load("xrCreateVulkanInstanceKHR", create_vk_instance) ||
        !load("xrGetVulkanGraphicsDevice2KHR", get_vk_device) ||
        !load("xrCreateVulkanDeviceKHR", create_vk_device)) {
        return Error{"the OpenXR runtime lacks the functions of XR_KHR_vulkan_enable2"};
    }
    return Ok{};
}

Result<std::unique_ptr<OpenXrHeadset>> OpenXrHeadset::create(bool validation, bool layer_depth,
                                                             bool eye_gaze) {
    auto impl = std::make_unique<Impl>();
    Result<std::vector<XrExtensionProperties>> extensions = runtime_extensions();
    MONOPLANE_TRY(extensions);
    if (!offers(*extensions, XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME)) {
        return Error{"the active OpenXR runtime does not support Vulkan (" +
                     std::string(XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME) + " is missing)"};
    }
    Result<XrValidation> planned = XrValidation::plan(validation);
    MONOPLANE_TRY(planned);
    impl->validation = std::move(planned.value());
    std::vector<const char*> enabled = {XR_KHR_VULKAN_ENABLE2_EXTENSION_NAME};
    // Optional: without it the layer goes without depth and the runtime reprojects as it can.
    impl->depth_extension =
        layer_depth && offers(*extensions, XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME);
    if (impl->depth_extension) enabled.push_back(XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME);
    // Optional: without it an answer key's time is that of the frame which read it.
    const bool timespec = offers(*extensions, XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME);
    if (timespec) enabled.push_back(XR_KHR_CONVERT_TIMESPEC_TIME_EXTENSION_NAME);
    // Asked for only: gaze is personal data, recorded where the protocol wants it.
    const bool gaze_extension =
        eye_gaze && offers(*extensions, XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME);
    if (gaze_extension) enabled.push_back(XR_EXT_EYE_GAZE_INTERACTION_EXTENSION_NAME);
    for (const char* name : impl->validation.extensions()) enabled.push_back(name);
    MONOPLANE_TRY(impl->create_instance(enabled));

    XrInstanceProperties properties{XR_TYPE_INSTANCE_PROPERTIES};
    xrGetInstanceProperties(impl->instance, &properties);
    XrSystemGetInfo system_info{XR_TYPE_SYSTEM_GET_INFO};
    system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    const XrResult result = xrGetSystem(impl->instance, &system_info, &impl->system);
    if (XR_FAILED(result)) {
        const std::string why = result_text(impl->instance, result);
        impl->validation.detach();
        xrDestroyInstance(impl->instance);
        impl->instance = XR_NULL_HANDLE;
        return Error{std::string("the OpenXR runtime '") + properties.runtimeName +
                     "' has no headset (" + why + "): connect and switch on the headset"};
    }
    XrSystemProperties system_properties{XR_TYPE_SYSTEM_PROPERTIES};
    XrSystemEyeGazeInteractionPropertiesEXT gaze_properties{
        XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT};
    if (gaze_extension) system_properties.next = &gaze_properties;
    xrGetSystemProperties(impl->instance, impl->system, &system_properties);
    impl->eye_gaze = gaze_extension && gaze_properties.supportsEyeGazeInteraction == XR_TRUE;
    impl->eye_gaze_offered = gaze_extension;
    MONOPLANE_TRY(impl->load_vulkan_functions());
    if (timespec && XR_FAILED(xrGetInstanceProcAddr(
                        impl->instance, "xrConvertTimespecTimeToTimeKHR",
                        reinterpret_cast<PFN_xrVoidFunction*>(&impl->timespec_to_time)))) {
        impl->timespec_to_time = nullptr;
    }

    std::unique_ptr<OpenXrHeadset> headset(new OpenXrHeadset(std::move(impl)));
    headset->runtime_name_ = std::string(properties.runtimeName) + " " +
                             std::to_string(XR_VERSION_MAJOR(properties.runtimeVersion)) + "." +
                             std::to_string(XR_VERSION_MINOR(properties.runtimeVersion)) + "." +
                             std::to_string(XR_VERSION_PATCH(properties.runtimeVersion));
    headset->system_name_ = system_properties.systemName;
    return headset;
}

const vk_core::ValidationMessages& OpenXrHeadset::validation_messages() const {
    return impl_->validation.messages();
}

std::optional<std::int64_t> OpenXrHeadset::runtime_time(const timespec& monotonic) const {
    const Impl& x = *impl_;
    if (x.timespec_to_time == nullptr || x.lost) return std::nullopt;
    XrTime time = 0;
    if (XR_FAILED(x.timespec_to_time(x.instance, &monotonic, &time))) return std::nullopt;
    return time;
}

}  // namespace monoplane::headset
