// An OpenXR session's life cycle: created on the Context's device with its LOCAL space, actions
// and swapchains; begun and ended as the runtime's state events ask; asked to exit; destroyed.
#include "app/headset/openxr_headset_impl.h"

namespace monoplane::headset {
namespace {

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
    for (XrSpace* space : {&x.local, &x.gaze_space, &x.view}) {
        if (*space != XR_NULL_HANDLE) xrDestroySpace(*space);
        *space = XR_NULL_HANDLE;
    }
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
