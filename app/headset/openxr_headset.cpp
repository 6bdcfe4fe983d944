#include "app/headset/openxr_headset.h"

#include <vulkan/vulkan.h>
// openxr_platform.h declares the Vulkan binding only when asked to and after vulkan.h.
#define XR_USE_GRAPHICS_API_VULKAN
// And XR_KHR_convert_timespec_time only with timespec asked for.
#define XR_USE_TIMESPEC
#include <time.h>

#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <limits>

#include "app/headset/eye_depth_writer.h"
#include "app/headset/xr_validation.h"

// OpenXR's structures are initialised the way its specification shows, `XrFoo foo{XR_TYPE_FOO}`:
// the remaining members are zeroed, which is what is wanted, not an omission.
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"

namespace monoplane::headset {
namespace {

std::string result_text(XrInstance instance, XrResult result) {
    char text[XR_MAX_RESULT_STRING_SIZE] = {};
    if (instance == XR_NULL_HANDLE || XR_FAILED(xrResultToString(instance, result, text))) {
        return "XrResult " + std::to_string(static_cast<int>(result));
    }
    return text;
}

Error xr_error(XrInstance instance, const char* call, XrResult result) {
    return Error{std::string(call) + " failed: " + result_text(instance, result)};
}

// The runtime is gone for this session: the instance or the session was lost (Monado's client
// answers XR_ERROR_INSTANCE_LOST to every call once its service's IPC connection broke).
bool is_loss(XrResult result) {
    return result == XR_ERROR_INSTANCE_LOST || result == XR_ERROR_SESSION_LOST;
}

rig::Pose to_pose(const XrPosef& p) {
    rig::Pose pose;
    pose.position = {p.position.x, p.position.y, p.position.z};
    pose.orientation =
        glm::dquat(p.orientation.w, p.orientation.x, p.orientation.y, p.orientation.z);
    return pose;
}

rig::Tangents to_tangents(const XrFovf& fov) {
    rig::Tangents t;
    t.left = std::tan(static_cast<double>(fov.angleLeft));
    t.right = std::tan(static_cast<double>(fov.angleRight));
    t.up = std::tan(static_cast<double>(fov.angleUp));
    t.down = std::tan(static_cast<double>(fov.angleDown));
    return t;
}

SessionPhase to_phase(XrSessionState state) {
    switch (state) {
        case XR_SESSION_STATE_IDLE:
            return SessionPhase::Idle;
        case XR_SESSION_STATE_READY:
            return SessionPhase::Ready;
        case XR_SESSION_STATE_SYNCHRONIZED:
            return SessionPhase::Synchronized;
        case XR_SESSION_STATE_VISIBLE:
            return SessionPhase::Visible;
        case XR_SESSION_STATE_FOCUSED:
            return SessionPhase::Focused;
        case XR_SESSION_STATE_STOPPING:
            return SessionPhase::Stopping;
        case XR_SESSION_STATE_LOSS_PENDING:
            return SessionPhase::LossPending;
        case XR_SESSION_STATE_EXITING:
            return SessionPhase::Exiting;
        default:
            return SessionPhase::None;
    }
}

// The formats the eyes can be copied into without changing their sRGB encoding (the renderer's
// display images are R8G8B8A8_SRGB); a blit converts the channel order where needed.
constexpr std::array kSwapchainFormats = {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_SRGB};

bool offers(const std::vector<XrExtensionProperties>& extensions, const char* name) {
    return std::any_of(
        extensions.begin(), extensions.end(),
        [name](const XrExtensionProperties& e) { return std::strcmp(e.extensionName, name) == 0; });
}

}  // namespace

const char* session_phase_name(SessionPhase phase) {
    switch (phase) {
        case SessionPhase::None:
            return "none";
        case SessionPhase::Idle:
            return "idle";
        case SessionPhase::Ready:
            return "ready";
        case SessionPhase::Synchronized:
            return "synchronized";
        case SessionPhase::Visible:
            return "visible";
        case SessionPhase::Focused:
            return "focused";
        case SessionPhase::Stopping:
            return "stopping";
        case SessionPhase::LossPending:
            return "loss pending";
        case SessionPhase::Exiting:
            return "exiting";
    }
    return "invalid";
}

const char* control_name(Control control) {
    switch (control) {
        case Control::Switch:
            return "switch";
        case Control::Confirm:
            return "confirm";
        case Control::Pause:
            return "pause";
    }
    return "invalid";
}

const std::vector<ProfileBindings>& controller_bindings() {
    // Trigger switches (either hand), the main face button or pad click confirms, the menu
    // button pauses. The simple controller has only select and menu: select on the right hand
    // switches, on the left confirms.
    static const std::vector<ProfileBindings> bindings = {
        {"/interaction_profiles/khr/simple_controller",
         {{Control::Switch, "/user/hand/right/input/select/click"},
          {Control::Confirm, "/user/hand/left/input/select/click"},
          {Control::Pause, "/user/hand/left/input/menu/click"}}},
        {"/interaction_profiles/htc/vive_controller",
         {{Control::Switch, "/user/hand/left/input/trigger/click"},
          {Control::Switch, "/user/hand/right/input/trigger/click"},
          {Control::Confirm, "/user/hand/left/input/trackpad/click"},
          {Control::Confirm, "/user/hand/right/input/trackpad/click"},
          {Control::Pause, "/user/hand/left/input/menu/click"}}},
        {"/interaction_profiles/valve/index_controller",
         {{Control::Switch, "/user/hand/left/input/trigger/click"},
          {Control::Switch, "/user/hand/right/input/trigger/click"},
          {Control::Confirm, "/user/hand/left/input/a/click"},
          {Control::Confirm, "/user/hand/right/input/a/click"},
          {Control::Pause, "/user/hand/left/input/b/click"}}},
        {"/interaction_profiles/oculus/touch_controller",
         {{Control::Switch, "/user/hand/left/input/trigger/value"},
          {Control::Switch, "/user/hand/right/input/trigger/value"},
          {Control::Confirm, "/user/hand/left/input/x/click"},
          {Control::Confirm, "/user/hand/right/input/a/click"},
          {Control::Pause, "/user/hand/left/input/menu/click"}}},
    };
    return bindings;
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
    // xrCreateInstance with these extensions and the validation's layers, then its messenger.
    Result<void> create_instance(const std::vector<const char*>& extensions);
    // The XR_KHR_vulkan_enable2 functions, from the instance.
    Result<void> load_vulkan_functions();
    // The primary stereo configuration's two views (recommended and maximum image sizes).
    Result<std::array<XrViewConfigurationView, 2>> view_configuration() const;
    Result<void> create_actions();
    Result<void> create_swapchains(const vk_core::Context& ctx, double scale, vk::Extent2D& extent,
                                   vk::Format& format, vk::Format& depth_format);
    Result<void> create_swapchain(Swapchain& swapchain, XrSwapchainUsageFlags usage,
                                  std::int64_t format, vk::Extent2D extent);
    Result<vk::Image> acquire(Swapchain& swapchain);
};

OpenXrHeadset::OpenXrHeadset(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}

OpenXrHeadset::~OpenXrHeadset() {
    destroy_session();
    impl_->validation.detach();
    if (impl_->instance != XR_NULL_HANDLE) xrDestroyInstance(impl_->instance);
}

namespace {

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

Result<std::unique_ptr<OpenXrHeadset>> OpenXrHeadset::create(bool validation, bool layer_depth) {
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
    xrGetSystemProperties(impl->instance, impl->system, &system_properties);
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

Result<void> OpenXrHeadset::Impl::create_actions() {
    XrActionSetCreateInfo set_info{XR_TYPE_ACTION_SET_CREATE_INFO};
    std::strcpy(set_info.actionSetName, "study");
    std::strcpy(set_info.localizedActionSetName, "Study");
    MONOPLANE_TRY(check("xrCreateActionSet", xrCreateActionSet(instance, &set_info, &action_set)));
    const std::array<std::pair<const char*, const char*>, 3> names = {
        {{"switch", "Switch between the two versions"},
         {"confirm", "Choose the version shown"},
         {"pause", "Pause"}}};
    for (std::size_t i = 0; i < names.size(); ++i) {
        XrActionCreateInfo info{XR_TYPE_ACTION_CREATE_INFO};
        info.actionType = XR_ACTION_TYPE_BOOLEAN_INPUT;
        std::strcpy(info.actionName, names[i].first);
        std::strcpy(info.localizedActionName, names[i].second);
        MONOPLANE_TRY(check("xrCreateAction", xrCreateAction(action_set, &info, &actions[i])));
    }
    for (const ProfileBindings& profile : controller_bindings()) {
        std::vector<XrActionSuggestedBinding> suggested;
        for (const ControlBinding& b : profile.bindings) {
            XrPath path = XR_NULL_PATH;
            MONOPLANE_TRY(check("xrStringToPath", xrStringToPath(instance, b.path, &path)));
            suggested.push_back({actions[static_cast<std::size_t>(b.control)], path});
        }
        XrInteractionProfileSuggestedBinding suggestion{
            XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
        MONOPLANE_TRY(check("xrStringToPath", xrStringToPath(instance, profile.profile,
                                                             &suggestion.interactionProfile)));
        suggestion.countSuggestedBindings = static_cast<std::uint32_t>(suggested.size());
        suggestion.suggestedBindings = suggested.data();
        const XrResult result = xrSuggestInteractionProfileBindings(instance, &suggestion);
        // A runtime without this controller type may refuse its profile; the others still work.
        if (XR_FAILED(result)) {
            std::cerr << "note: the runtime does not take bindings for " << profile.profile << " ("
                      << result_text(instance, result) << ")\n";
        }
    }
    XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    attach.countActionSets = 1;
    attach.actionSets = &action_set;
    return check("xrAttachSessionActionSets", xrAttachSessionActionSets(session, &attach));
}

Result<void> OpenXrHeadset::Impl::create_swapchain(Swapchain& swapchain,
                                                   XrSwapchainUsageFlags usage, std::int64_t format,
                                                   vk::Extent2D extent) {
    XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
    info.usageFlags = usage;
    info.format = format;
    info.sampleCount = 1;
    info.width = extent.width;
    info.height = extent.height;
    info.faceCount = 1;
    info.arraySize = 1;
    info.mipCount = 1;
    MONOPLANE_TRY(check("xrCreateSwapchain", xrCreateSwapchain(session, &info, &swapchain.handle)));
    std::uint32_t count = 0;
    MONOPLANE_TRY(check("xrEnumerateSwapchainImages",
                        xrEnumerateSwapchainImages(swapchain.handle, 0, &count, nullptr)));
    swapchain.images.assign(count, {XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR});
    return check("xrEnumerateSwapchainImages",
                 xrEnumerateSwapchainImages(
                     swapchain.handle, count, &count,
                     reinterpret_cast<XrSwapchainImageBaseHeader*>(swapchain.images.data())));
}

Result<std::array<XrViewConfigurationView, 2>> OpenXrHeadset::Impl::view_configuration() const {
    std::uint32_t count = 0;
    MONOPLANE_TRY(check(
        "xrEnumerateViewConfigurationViews",
        xrEnumerateViewConfigurationViews(
            instance, system, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 0, &count, nullptr)));
    if (count != 2) return Error{"the headset does not have two views"};
    std::array<XrViewConfigurationView, 2> config{};
    for (auto& c : config) c.type = XR_TYPE_VIEW_CONFIGURATION_VIEW;
    MONOPLANE_TRY(check("xrEnumerateViewConfigurationViews",
                        xrEnumerateViewConfigurationViews(instance, system,
                                                          XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO,
                                                          2, &count, config.data())));
    return config;
}

Result<vk::Extent2D> OpenXrHeadset::recommended_eye_extent() const {
    Result<std::array<XrViewConfigurationView, 2>> views = impl_->view_configuration();
    MONOPLANE_TRY(views);
    return vk::Extent2D((*views)[0].recommendedImageRectWidth,
                        (*views)[0].recommendedImageRectHeight);
}

Result<void> OpenXrHeadset::Impl::create_swapchains(const vk_core::Context& ctx, double scale,
                                                    vk::Extent2D& extent, vk::Format& format,
                                                    vk::Format& depth_format) {
    Result<std::array<XrViewConfigurationView, 2>> views = view_configuration();
    MONOPLANE_TRY(views);
    const std::array<XrViewConfigurationView, 2>& config = *views;
    const auto scaled = [scale](std::uint32_t size, std::uint32_t max) {
        const auto s = static_cast<std::uint32_t>(std::lround(size * scale));
        return std::clamp<std::uint32_t>(s, 16, max);
    };
    extent =
        vk::Extent2D(scaled(config[0].recommendedImageRectWidth, config[0].maxImageRectWidth),
                     scaled(config[0].recommendedImageRectHeight, config[0].maxImageRectHeight));

    std::uint32_t count = 0;
    MONOPLANE_TRY(check("xrEnumerateSwapchainFormats",
                        xrEnumerateSwapchainFormats(session, 0, &count, nullptr)));
    std::vector<std::int64_t> formats(count);
    xrEnumerateSwapchainFormats(session, count, &count, formats.data());
    std::int64_t chosen = 0;
    for (VkFormat wanted : kSwapchainFormats) {
        if (std::find(formats.begin(), formats.end(), wanted) != formats.end()) {
            chosen = wanted;
            break;
        }
    }
    if (chosen == 0) return Error{"the OpenXR runtime offers no 8-bit sRGB swapchain format"};
    format = static_cast<vk::Format>(chosen);
    static_cast<void>(ctx);

    for (Swapchain& swapchain : swapchains) {
        // Transfer usage: the eyes are blitted in, the mirror is blitted out.
        MONOPLANE_TRY(create_swapchain(swapchain,
                                       XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT |
                                           XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT |
                                           XR_SWAPCHAIN_USAGE_TRANSFER_SRC_BIT,
                                       chosen, extent));
    }

    // The eyes' depth, the same size as their colour (XR_KHR_composition_layer_depth pairs a
    // view's depth sub-image with its colour one). The runtime lists colour and depth formats
    // together; the first of eye_depth_formats() it offers is taken.
    depth_format = vk::Format::eUndefined;
    if (!depth_extension) return Ok{};
    for (vk::Format wanted : eye_depth_formats()) {
        if (std::find(formats.begin(), formats.end(), static_cast<std::int64_t>(wanted)) !=
            formats.end()) {
            depth_format = wanted;
            break;
        }
    }
    if (depth_format == vk::Format::eUndefined) {
        std::cerr << "note: the OpenXR runtime offers no depth swapchain format monoplane writes; "
                     "the eyes' depth is not submitted\n";
        return Ok{};
    }
    for (Swapchain& swapchain : depth_swapchains) {
        // Drawn as an attachment (eye_depth_writer.h) and nothing else.
        MONOPLANE_TRY(create_swapchain(swapchain, XR_SWAPCHAIN_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                       static_cast<std::int64_t>(depth_format), extent));
    }
    return Ok{};
}

Result<void> OpenXrHeadset::create_session(const vk_core::Context& ctx, double resolution_scale) {
    Impl& x = *impl_;
    XrGraphicsBindingVulkan2KHR binding{XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR};
    binding.instance = static_cast<VkInstance>(*ctx.instance());
    binding.physicalDevice = static_cast<VkPhysicalDevice>(*ctx.physical_device());
    binding.device = static_cast<VkDevice>(*ctx.device());
    binding.queueFamilyIndex = ctx.queue_family();
    binding.queueIndex = 0;
    XrSessionCreateInfo info{XR_TYPE_SESSION_CREATE_INFO};
    info.next = &binding;
    info.systemId = x.system;
    MONOPLANE_TRY(x.check("xrCreateSession", xrCreateSession(x.instance, &info, &x.session)));
    x.device = binding.device;
    phase_ = SessionPhase::Idle;

    // LOCAL: the origin where the participant's head was when the session began, so the scene's
    // viewpoint is where they sit (a seated study).
    XrReferenceSpaceCreateInfo space{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    space.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    space.poseInReferenceSpace.orientation.w = 1.0f;
    MONOPLANE_TRY(
        x.check("xrCreateReferenceSpace", xrCreateReferenceSpace(x.session, &space, &x.local)));
    MONOPLANE_TRY(x.create_actions());
    return x.create_swapchains(ctx, resolution_scale, eye_extent_, swapchain_format_,
                               depth_format_);
}

Result<bool> OpenXrHeadset::poll_events() {
    Impl& x = *impl_;
    for (;;) {
        XrEventDataBuffer event{XR_TYPE_EVENT_DATA_BUFFER};
        const XrResult result = xrPollEvent(x.instance, &event);
        if (result == XR_EVENT_UNAVAILABLE) break;
        MONOPLANE_TRY(x.check("xrPollEvent", result));
        if (event.type == XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING) {
            phase_ = SessionPhase::LossPending;
            x.lost = true;
            running_ = false;
            return false;
        }
        if (event.type != XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) continue;
        const auto& changed = reinterpret_cast<const XrEventDataSessionStateChanged&>(event);
        phase_ = to_phase(changed.state);
        if (changed.state == XR_SESSION_STATE_READY) {
            XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
            begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
            MONOPLANE_TRY(x.check("xrBeginSession", xrBeginSession(x.session, &begin)));
            running_ = true;
        } else if (changed.state == XR_SESSION_STATE_STOPPING) {
            MONOPLANE_TRY(x.check("xrEndSession", xrEndSession(x.session)));
            running_ = false;
        } else if (changed.state == XR_SESSION_STATE_EXITING ||
                   changed.state == XR_SESSION_STATE_LOSS_PENDING) {
            x.lost = x.lost || changed.state == XR_SESSION_STATE_LOSS_PENDING;
            running_ = false;
            return false;
        }
    }
    return true;
}

Result<HeadsetFrame> OpenXrHeadset::begin_frame() {
    Impl& x = *impl_;
    XrFrameWaitInfo wait{XR_TYPE_FRAME_WAIT_INFO};
    XrFrameState state{XR_TYPE_FRAME_STATE};
    MONOPLANE_TRY(x.check("xrWaitFrame", xrWaitFrame(x.session, &wait, &state)));
    XrFrameBeginInfo begin{XR_TYPE_FRAME_BEGIN_INFO};
    MONOPLANE_TRY(x.check("xrBeginFrame", xrBeginFrame(x.session, &begin)));

    HeadsetFrame frame;
    frame.index = ++x.frame_index;
    frame.display_time_ns = state.predictedDisplayTime;
    frame.display_period_ns = state.predictedDisplayPeriod;
    frame.should_render = state.shouldRender == XR_TRUE;
    XrViewLocateInfo locate{XR_TYPE_VIEW_LOCATE_INFO};
    locate.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    locate.displayTime = state.predictedDisplayTime;
    locate.space = x.local;
    XrViewState view_state{XR_TYPE_VIEW_STATE};
    std::uint32_t count = 0;
    for (auto& v : x.views) v = {XR_TYPE_VIEW};
    MONOPLANE_TRY(x.check("xrLocateViews", xrLocateViews(x.session, &locate, &view_state, 2, &count,
                                                         x.views.data())));
    const XrViewStateFlags needed =
        XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT;
    frame.views_valid = count == 2 && (view_state.viewStateFlags & needed) == needed;
    x.views_located = frame.views_valid;
    for (int e = 0; e < 2; ++e) {
        frame.views[e].pose = to_pose(x.views[e].pose);
        frame.views[e].tangents = to_tangents(x.views[e].fov);
    }
    return frame;
}

Result<std::vector<ControlPress>> OpenXrHeadset::sync_controls() {
    Impl& x = *impl_;
    XrActiveActionSet active{x.action_set, XR_NULL_PATH};
    XrActionsSyncInfo sync{XR_TYPE_ACTIONS_SYNC_INFO};
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    const XrResult result = xrSyncActions(x.session, &sync);
    MONOPLANE_TRY(x.check("xrSyncActions", result));
    std::vector<ControlPress> presses;
    if (result == XR_SESSION_NOT_FOCUSED) return presses;  // input belongs to another app now
    for (std::size_t i = 0; i < x.actions.size(); ++i) {
        XrActionStateGetInfo get{XR_TYPE_ACTION_STATE_GET_INFO};
        get.action = x.actions[i];
        XrActionStateBoolean state{XR_TYPE_ACTION_STATE_BOOLEAN};
        MONOPLANE_TRY(
            x.check("xrGetActionStateBoolean", xrGetActionStateBoolean(x.session, &get, &state)));
        // A press is the moment the button goes down; holding it does not repeat.
        if (state.isActive && state.changedSinceLastSync && state.currentState) {
            presses.push_back({static_cast<Control>(i), state.lastChangeTime});
        }
    }
    return presses;
}

Result<vk::Image> OpenXrHeadset::Impl::acquire(Swapchain& swapchain) {
    std::uint32_t index = 0;
    XrSwapchainImageAcquireInfo acquire{XR_TYPE_SWAPCHAIN_IMAGE_ACQUIRE_INFO};
    MONOPLANE_TRY(check("xrAcquireSwapchainImage",
                        xrAcquireSwapchainImage(swapchain.handle, &acquire, &index)));
    XrSwapchainImageWaitInfo wait{XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO};
    wait.timeout = XR_INFINITE_DURATION;
    MONOPLANE_TRY(check("xrWaitSwapchainImage", xrWaitSwapchainImage(swapchain.handle, &wait)));
    swapchain.acquired = true;
    return vk::Image(swapchain.images[index].image);
}

Result<vk::Image> OpenXrHeadset::acquire_eye_image(int eye) {
    return impl_->acquire(impl_->swapchains[static_cast<std::size_t>(eye)]);
}

Result<vk::Image> OpenXrHeadset::acquire_eye_depth_image(int eye) {
    Impl::Swapchain& swapchain = impl_->depth_swapchains[static_cast<std::size_t>(eye)];
    if (swapchain.handle == XR_NULL_HANDLE) return Error{"no depth swapchains in this session"};
    return impl_->acquire(swapchain);
}

Result<void> OpenXrHeadset::end_frame(const HeadsetFrame& frame,
                                      const std::optional<DepthEncoding>& depth) {
    Impl& x = *impl_;
    // Releases the acquired images of two swapchains; true if both were acquired.
    const auto release = [&x](std::array<Impl::Swapchain, 2>& pair) -> Result<bool> {
        bool both = true;
        for (Impl::Swapchain& swapchain : pair) {
            if (!swapchain.acquired) {
                both = false;
                continue;
            }
            XrSwapchainImageReleaseInfo info{XR_TYPE_SWAPCHAIN_IMAGE_RELEASE_INFO};
            MONOPLANE_TRY(x.check("xrReleaseSwapchainImage",
                                  xrReleaseSwapchainImage(swapchain.handle, &info)));
            swapchain.acquired = false;
        }
        return both;
    };
    Result<bool> rendered = release(x.swapchains);
    MONOPLANE_TRY(rendered);
    Result<bool> depth_written = release(x.depth_swapchains);
    MONOPLANE_TRY(depth_written);
    // XR_KHR_composition_layer_depth (XrCompositionLayerDepthInfoKHR): depth goes "to the next
    // chain for all XrCompositionLayerProjectionView structures in the given layer", here with
    // the colour's rectangle on the depth swapchain. minDepth and maxDepth are the window depths
    // of the near and far planes, nearZ and farZ their distances, in (0, +inf] and unequal. The
    // encoding d = near / distance puts infinity at window depth 0 and `near` at 1: minDepth 0
    // with nearZ = +inf, maxDepth 1 with farZ = near (nearZ > farZ is reversed depth).
    const bool with_depth = *depth_written && depth.has_value();
    std::array<XrCompositionLayerDepthInfoKHR, 2> depth_infos{};
    std::array<XrCompositionLayerProjectionView, 2> views{};
    XrCompositionLayerProjection layer{XR_TYPE_COMPOSITION_LAYER_PROJECTION};
    const XrCompositionLayerBaseHeader* layers[] = {
        reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer)};
    for (int e = 0; e < 2; ++e) {
        views[e] = {XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW};
        views[e].pose = x.views[e].pose;
        views[e].fov = x.views[e].fov;
        views[e].subImage.swapchain = x.swapchains[e].handle;
        views[e].subImage.imageRect.extent = {static_cast<std::int32_t>(eye_extent_.width),
                                              static_cast<std::int32_t>(eye_extent_.height)};
        if (!with_depth) continue;
        XrCompositionLayerDepthInfoKHR& info = depth_infos[e];
        info = {XR_TYPE_COMPOSITION_LAYER_DEPTH_INFO_KHR};
        info.subImage = views[e].subImage;
        info.subImage.swapchain = x.depth_swapchains[e].handle;
        info.minDepth = 0.0f;
        info.maxDepth = 1.0f;
        info.nearZ = std::numeric_limits<float>::infinity();
        info.farZ = static_cast<float>(depth->near);
        views[e].next = &info;
    }
    layer.space = x.local;
    layer.viewCount = 2;
    layer.views = views.data();
    XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
    end.displayTime = frame.display_time_ns;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    // Nothing is submitted for a frame the runtime said not to render, or without tracking.
    const bool submit = *rendered && frame.should_render && x.views_located;
    end.layerCount = submit ? 1 : 0;
    end.layers = submit ? layers : nullptr;
    return x.check("xrEndFrame", xrEndFrame(x.session, &end));
}

Result<std::string> OpenXrHeadset::interaction_profile() const {
    const Impl& x = *impl_;
    if (x.session == XR_NULL_HANDLE) return Error{"no OpenXR session: nothing is bound yet"};
    for (const char* hand : {"/user/hand/left", "/user/hand/right"}) {
        XrPath path = XR_NULL_PATH;
        MONOPLANE_TRY(x.check("xrStringToPath", xrStringToPath(x.instance, hand, &path)));
        XrInteractionProfileState state{XR_TYPE_INTERACTION_PROFILE_STATE};
        MONOPLANE_TRY(x.check("xrGetCurrentInteractionProfile",
                              xrGetCurrentInteractionProfile(x.session, path, &state)));
        if (state.interactionProfile == XR_NULL_PATH) continue;
        char text[XR_MAX_PATH_LENGTH] = {};
        std::uint32_t length = 0;
        MONOPLANE_TRY(x.check("xrPathToString", xrPathToString(x.instance, state.interactionProfile,
                                                               sizeof text, &length, text)));
        return std::string(text);
    }
    return std::string();
}

std::optional<std::int64_t> OpenXrHeadset::runtime_time(const timespec& monotonic) const {
    const Impl& x = *impl_;
    if (x.timespec_to_time == nullptr || x.lost) return std::nullopt;
    XrTime time = 0;
    if (XR_FAILED(x.timespec_to_time(x.instance, &monotonic, &time))) return std::nullopt;
    return time;
}

Result<void> OpenXrHeadset::request_exit() {
    Impl& x = *impl_;
    if (!running_) return Ok{};
    return x.check("xrRequestExitSession", xrRequestExitSession(x.session));
}

bool OpenXrHeadset::lost() const {
    return impl_->lost;
}

void OpenXrHeadset::destroy_session() {
    Impl& x = *impl_;
    // The runtime may free a swapchain's images at once: the GPU must be done with them. A lost
    // device has nothing left to wait for.
    if (x.device != VK_NULL_HANDLE) static_cast<void>(vkDeviceWaitIdle(x.device));
    x.device = VK_NULL_HANDLE;
    for (auto* pair : {&x.swapchains, &x.depth_swapchains}) {
        for (Impl::Swapchain& swapchain : *pair) {
            if (swapchain.handle != XR_NULL_HANDLE) xrDestroySwapchain(swapchain.handle);
            swapchain = {};
        }
    }
    if (x.local != XR_NULL_HANDLE) xrDestroySpace(x.local);
    x.local = XR_NULL_HANDLE;
    if (x.session != XR_NULL_HANDLE) {
        // A lost session cannot be ended, only destroyed (spec: XR_ERROR_SESSION_LOST).
        if (running_ && !x.lost) xrEndSession(x.session);
        xrDestroySession(x.session);
    }
    x.session = XR_NULL_HANDLE;
    // Action sets belong to the instance and go with it.
    running_ = false;
}

}  // namespace monoplane::headset
