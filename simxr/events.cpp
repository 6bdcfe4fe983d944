// The event queue. A session's state, as simxr checks it (xrBeginSession needs READY,
// xrEndSession STOPPING, ...), changes when xrPollEvent delivers the change: an application
// only knows a state once it has been told, and acting on an undelivered one is its mistake.
#include <algorithm>
#include <cstring>

#include "simxr/entry_points.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {

void queue_event(Instance& instance, const void* event, std::size_t size, Session* session) {
    QueuedEvent queued{};
    std::memcpy(&queued.data, event, std::min(size, sizeof(queued.data)));
    queued.session = session;
    instance.events.push_back(queued);
}

void queue_state_change(Session& session, XrSessionState state, XrTime time) {
    auto event =
        xr_struct<XrEventDataSessionStateChanged>(XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED);
    event.session = reinterpret_cast<XrSession>(&session);
    event.state = state;
    event.time = time;
    queue_event(*session.instance, &event, sizeof(event), &session);
    session.instance->events.back().state = state;
    session.queued_state = state;
}

void lose_instance(Instance& instance, XrTime time) {
    auto event =
        xr_struct<XrEventDataInstanceLossPending>(XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING);
    // Spec: the instance is lost at lossTime; simxr loses it at once, as a runtime whose
    // service died, so the application meets the loss either in this event or in a failed call.
    event.lossTime = time;
    queue_event(instance, &event, sizeof(event), nullptr);
    instance.lost = true;
}

bool instance_lost() {
    return std::ranges::any_of(live_objects<Instance>(),
                               [](const auto& entry) { return entry.second->lost; });
}

void drop_events_of(Instance& instance, const Session* session) {
    std::erase_if(instance.events,
                  [session](const QueuedEvent& event) { return event.session == session; });
}

XrResult XRAPI_CALL xrPollEvent(XrInstance handle, XrEventDataBuffer* buffer) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(buffer, XR_TYPE_EVENT_DATA_BUFFER)) return XR_ERROR_VALIDATION_FAILURE;
    // A lost instance still delivers what was queued (its loss-pending event among it), then
    // says it is lost.
    if (instance->events.empty())
        return instance->lost ? XR_ERROR_INSTANCE_LOST : XR_EVENT_UNAVAILABLE;
    const QueuedEvent event = instance->events.front();
    instance->events.pop_front();
    if (event.state && event.session != nullptr) event.session->state = *event.state;
    std::memcpy(buffer, &event.data, sizeof(*buffer));
    return XR_SUCCESS;
}

}  // namespace monoplane::simxr
