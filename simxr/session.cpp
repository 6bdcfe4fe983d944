// Session creation and its life cycle (spec 9.3 "Session Lifecycle"): IDLE and READY on
// creation, SYNCHRONIZED, VISIBLE and FOCUSED after the first frame is submitted
// (frame_loop.cpp), STOPPING on an exit request, IDLE and EXITING on xrEndSession.
#include "simxr/entry_points.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {
namespace {

// Frame 0's predicted display time. Any positive time would do; a round one reads well in logs.
constexpr XrTime kFirstDisplayTime = 10'000'000'000;

}  // namespace

void begin_exit(Session& session) {
    session.exit_requested = true;
    const XrTime now = session.now();
    if (session.queued_state == XR_SESSION_STATE_FOCUSED) {
        queue_state_change(session, XR_SESSION_STATE_VISIBLE, now);
    }
    // Before its first frame a running session is still READY; STOPPING is only reached from
    // SYNCHRONIZED, so the session passes through it.
    if (session.queued_state == XR_SESSION_STATE_VISIBLE ||
        session.queued_state == XR_SESSION_STATE_READY) {
        queue_state_change(session, XR_SESSION_STATE_SYNCHRONIZED, now);
    }
    queue_state_change(session, XR_SESSION_STATE_STOPPING, now);
}

void destroy_session(Session* session) {
    while (!session->swapchains.empty()) destroy_swapchain(session->swapchains.back());
    for (Space* space : session->spaces) unregister_object(space);
    session->vulkan.destroy();
    drop_events_of(*session->instance, session);
    session->instance->session = nullptr;
    unregister_object(session);
}

XrResult XRAPI_CALL xrCreateSession(XrInstance handle, const XrSessionCreateInfo* info,
                                    XrSession* session_handle) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_SESSION_CREATE_INFO) || info->createFlags != 0 ||
        session_handle == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (info->systemId != kSystemId) return XR_ERROR_SYSTEM_INVALID;
    // spec (XR_KHR_vulkan_enable2): xrCreateSession returns
    // XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING unless xrGetVulkanGraphicsRequirements2KHR was
    // called first.
    if (!instance->requirements_queried) return XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING;
    // spec: no graphics binding, or one whose physical device is not the one
    // xrGetVulkanGraphicsDevice2KHR named, is XR_ERROR_GRAPHICS_DEVICE_INVALID.
    const auto* binding = static_cast<const XrGraphicsBindingVulkan2KHR*>(
        find_in_chain(info->next, XR_TYPE_GRAPHICS_BINDING_VULKAN2_KHR));
    if (binding == nullptr || binding->instance == VK_NULL_HANDLE ||
        binding->device == VK_NULL_HANDLE || binding->physicalDevice == VK_NULL_HANDLE ||
        binding->physicalDevice != instance->named_physical_device) {
        return XR_ERROR_GRAPHICS_DEVICE_INVALID;
    }
    if (instance->session != nullptr) return XR_ERROR_LIMIT_REACHED;

    auto session = std::make_unique<Session>();
    session->instance = instance;
    const PFN_vkGetInstanceProcAddr get = instance->vk_get_instance_proc_addr != nullptr
                                              ? instance->vk_get_instance_proc_addr
                                              : &vkGetInstanceProcAddr;
    const VulkanBinding vulkan{binding->instance, binding->physicalDevice, binding->device,
                               binding->queueFamilyIndex, binding->queueIndex};
    if (!session->vulkan.init(get, vulkan)) {
        session->vulkan.destroy();
        return XR_ERROR_RUNTIME_FAILURE;
    }
    session->base_time = kFirstDisplayTime;
    session->period = instance->script.frame_period_ns();
    session->missed_slot_every = instance->script.missed_slot_every;
    Session* raw = session.get();
    *session_handle = register_object<XrSession>(std::move(session));
    instance->session = raw;
    queue_state_change(*raw, XR_SESSION_STATE_IDLE, raw->now());
    queue_state_change(*raw, XR_SESSION_STATE_READY, raw->now());
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrDestroySession(XrSession handle) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    destroy_session(session);
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrBeginSession(XrSession handle, const XrSessionBeginInfo* info) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_SESSION_BEGIN_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    if (session->loss_pending) return XR_ERROR_SESSION_LOST;
    // spec: xrBeginSession on a running session is XR_ERROR_SESSION_RUNNING, and otherwise
    // XR_ERROR_SESSION_NOT_READY unless the session is READY.
    if (session->running) return XR_ERROR_SESSION_RUNNING;
    if (session->state != XR_SESSION_STATE_READY) return XR_ERROR_SESSION_NOT_READY;
    if (info->primaryViewConfigurationType != XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO) {
        return XR_ERROR_VIEW_CONFIGURATION_TYPE_UNSUPPORTED;
    }
    // SYNCHRONIZED follows the first submitted frame (frame_loop.cpp), not this call.
    session->running = true;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrEndSession(XrSession handle) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (session->loss_pending) return XR_ERROR_SESSION_LOST;
    // spec: xrEndSession needs a running session in the STOPPING state.
    if (!session->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (session->state != XR_SESSION_STATE_STOPPING) return XR_ERROR_SESSION_NOT_STOPPING;
    session->running = false;
    session->waited_not_begun.clear();
    session->begun_frame.reset();
    queue_state_change(*session, XR_SESSION_STATE_IDLE, session->now());
    // STOPPING is only ever reached through an exit request, so the session ends for good.
    queue_state_change(*session, XR_SESSION_STATE_EXITING, session->now());
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrRequestExitSession(XrSession handle) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (session->loss_pending) return XR_ERROR_SESSION_LOST;
    if (!session->running) return XR_ERROR_SESSION_NOT_RUNNING;
    if (!session->exit_requested) begin_exit(*session);
    return XR_SUCCESS;
}

}  // namespace monoplane::simxr
