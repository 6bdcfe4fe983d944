// simxr's objects behind the OpenXR handles, the registry that tells live handles from stale
// ones, and the small helpers every entry point shares. All entry points hold runtime_mutex()
// for their whole duration (OpenXR allows calls from several threads; simxr is not about speed).
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

// openxr_platform.h needs Vulkan's types declared first.
#include <vulkan/vulkan.h>

#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>

#include "simxr/script.h"
#include "simxr/vulkan_device.h"

namespace monoplane::simxr {

struct Session;
struct ActionSet;
struct Action;

// Interned paths (spec 6.2: an XrPath is an atom for a well-formed path string, valid for the
// instance's lifetime). XrPath n names strings[n - 1]; 0 is XR_NULL_PATH.
struct PathTable {
    std::vector<std::string> strings;
    std::unordered_map<std::string, XrPath> atoms;

    XrPath intern(const std::string& path);
    const std::string* find(XrPath path) const;  // nullptr for unknown atoms
};

struct QueuedEvent {
    XrEventDataBuffer data;
    Session* session = nullptr;  // for state changes: whose state becomes `state` on delivery
    std::optional<XrSessionState> state;
};

struct Instance {
    Script script;
    std::deque<QueuedEvent> events;
    PathTable paths;
    bool vulkan_enable2 = false;           // XR_KHR_vulkan_enable2 was enabled
    bool composition_layer_depth = false;  // XR_KHR_composition_layer_depth was enabled
    bool eye_gaze_interaction = false;     // XR_EXT_eye_gaze_interaction was enabled
    bool system_requested = false;         // xrGetSystem succeeded
    bool requirements_queried = false;     // xrGetVulkanGraphicsRequirements2KHR was called
    PFN_vkGetInstanceProcAddr vk_get_instance_proc_addr = nullptr;
    VkInstance vk_instance = VK_NULL_HANDLE;                  // from xrGetVulkanGraphicsDevice2KHR
    VkPhysicalDevice named_physical_device = VK_NULL_HANDLE;  // what that call returned
    Session* session = nullptr;                               // simxr allows one session at a time
    // The script's lose_instance_at_s has come: every call but the destroy functions (and
    // xrPollEvent while events are queued) returns XR_ERROR_INSTANCE_LOST (dispatch.cpp).
    bool lost = false;
    std::vector<ActionSet*> action_sets;
    // Suggested bindings per interaction profile path (the latest call for a profile wins).
    std::map<XrPath, std::vector<std::pair<Action*, std::string>>> suggested_bindings;
};

struct Swapchain {
    enum class ImageState { available, acquired, waited };
    Session* session = nullptr;
    XrSwapchainCreateInfo info{};
    VkFormat format = VK_FORMAT_UNDEFINED;
    bool depth = false;
    std::vector<VkImage> images;
    std::vector<VkDeviceMemory> memory;
    std::vector<ImageState> states;
    std::deque<uint32_t> in_flight;  // acquired, oldest first (spec: wait and release in order)
    uint32_t next_to_acquire = 0;
    std::optional<uint32_t> last_released;
    bool acquired_once = false;  // XR_SWAPCHAIN_CREATE_STATIC_IMAGE_BIT allows one acquire ever
};

struct Space {
    Session* session = nullptr;
    XrReferenceSpaceType type = XR_REFERENCE_SPACE_TYPE_LOCAL;
    XrPosef pose_in_reference{{0, 0, 0, 1}, {0, 0, 0}};  // or poseInActionSpace
    bool action_space = false;
    // Action spaces: the pose action (null once it is destroyed) and the subaction path.
    const Action* action = nullptr;
    XrPath subaction_path = XR_NULL_PATH;
};

struct ActionSet {
    Instance* instance = nullptr;
    std::string name;
    std::string localized_name;
    std::vector<Action*> actions;
    bool attached = false;
};

struct Action {
    ActionSet* set = nullptr;
    std::string name;
    std::string localized_name;
    XrActionType type = XR_ACTION_TYPE_BOOLEAN_INPUT;
    std::vector<XrPath> subaction_paths;
};

struct Session {
    Instance* instance = nullptr;
    VulkanDevice vulkan;
    XrSessionState state = XR_SESSION_STATE_UNKNOWN;         // as delivered by xrPollEvent
    XrSessionState queued_state = XR_SESSION_STATE_UNKNOWN;  // after all queued events
    bool running = false;  // between a successful xrBeginSession and xrEndSession
    bool exit_requested = false;
    bool loss_pending = false;
    // Virtual clock: frame n is displayed at base_time + n * period.
    XrTime base_time = 0;
    XrDuration period = 0;
    std::int64_t missed_slot_every = 0;         // Script::missed_slot_every
    std::int64_t frames_waited = 0;             // n of the next xrWaitFrame
    std::deque<std::int64_t> waited_not_begun;  // frame indices
    std::optional<std::int64_t> begun_frame;
    XrTime latest_wait_time = 0;  // predicted display time of the latest xrWaitFrame
    std::vector<Swapchain*> swapchains;
    std::vector<Space*> spaces;
    // Actions.
    std::vector<ActionSet*> attached_sets;
    // Chosen by the first xrSyncActions of the running session (spec 11.4); empty and
    // XR_NULL_PATH until then.
    bool profile_chosen = false;
    // Of the script's controller profile and, with an eye tracker, of the eye gaze profile.
    std::vector<std::pair<Action*, std::string>> bindings;
    XrPath interaction_profile = XR_NULL_PATH;  // the controllers'
    XrPath gaze_profile = XR_NULL_PATH;         // /user/eyes_ext's, once bound
    std::vector<ActionSet*> synced_sets;        // active in the latest xrSyncActions while focused
    XrTime sync_time = 0;
    std::map<std::string, float> values, previous_values;  // component path -> value
    std::map<std::string, XrTime> last_change;

    // Frame n's slot: n periods after the base, plus one for every missed slot before it.
    XrTime predicted_display_time(std::int64_t frame) const {
        const std::int64_t missed = missed_slot_every > 0 ? frame / missed_slot_every : 0;
        return base_time + (frame + missed) * period;
    }
    // The virtual clock's present: the latest predicted display time handed out.
    XrTime now() const { return frames_waited > 0 ? latest_wait_time : base_time; }
    // Seconds since frame 0's predicted display time.
    double script_time(XrTime time) const { return static_cast<double>(time - base_time) * 1e-9; }
};

std::mutex& runtime_mutex();

// Live objects of one kind; a handle is the object's address. Registering owns the object.
template <class Object>
std::unordered_map<Object*, std::unique_ptr<Object>>& live_objects() {
    static std::unordered_map<Object*, std::unique_ptr<Object>> objects;
    return objects;
}

template <class Object, class Handle>
Object* lookup(Handle handle) {
    auto* object = reinterpret_cast<Object*>(handle);
    return live_objects<Object>().contains(object) ? object : nullptr;
}

template <class Handle, class Object>
Handle register_object(std::unique_ptr<Object> object) {
    Object* raw = object.get();
    live_objects<Object>().emplace(raw, std::move(object));
    return reinterpret_cast<Handle>(raw);
}

template <class Object>
void unregister_object(Object* object) {
    live_objects<Object>().erase(object);
}

// spec (XrPosef): an orientation whose norm is more than 1% away from 1 is XR_ERROR_POSE_INVALID.
bool is_unit_quaternion(const XrQuaternionf& q);

// A subaction path given to a call about `action`: XR_NULL_PATH or one the action was created
// with; XR_ERROR_PATH_INVALID for a value that is no path atom, XR_ERROR_PATH_UNSUPPORTED for a
// path the action was not created with (spec 11.3, XrActionStateGetInfo, XrHapticActionInfo,
// XrActionSpaceCreateInfo).
XrResult check_subaction_path(const Instance& instance, const Action& action, XrPath path);

// Destroys what a session owns (spec: destroying a parent destroys its children).
void destroy_swapchain(Swapchain* swapchain);
void destroy_session(Session* session);
void destroy_action_set(ActionSet* set);

// Runtime-side exit (xrRequestExitSession, the script's exit_after_s): spec 9.3, a running
// session steps down through VISIBLE and SYNCHRONIZED to STOPPING.
void begin_exit(Session& session);

// Queues a session state change, delivered by xrPollEvent (events.cpp).
void queue_state_change(Session& session, XrSessionState state, XrTime time);
void queue_event(Instance& instance, const void* event, std::size_t size, Session* session);
// The instance is lost from now on (the script's lose_instance_at_s): queues
// XrEventDataInstanceLossPending with this lossTime and marks it lost.
void lose_instance(Instance& instance, XrTime time);
// Whether the live instance (simxr has at most one) is lost. Call with runtime_mutex() held.
bool instance_lost();
// Drops queued events that name a session about to be destroyed.
void drop_events_of(Instance& instance, const Session* session);

// Spec 2.11 (the two-call idiom): capacity 0 asks for the count; a capacity smaller than the
// count is XR_ERROR_SIZE_INSUFFICIENT.
template <class T>
XrResult fill_array(uint32_t capacity, uint32_t* count_output, T* output,
                    const std::vector<T>& items) {
    if (count_output == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    *count_output = static_cast<uint32_t>(items.size());
    if (capacity == 0) return XR_SUCCESS;
    if (capacity < items.size()) return XR_ERROR_SIZE_INSUFFICIENT;
    if (output == nullptr) return XR_ERROR_VALIDATION_FAILURE;
    for (std::size_t i = 0; i < items.size(); ++i) output[i] = items[i];
    return XR_SUCCESS;
}

// The same for strings: capacity counts the terminating null character.
XrResult fill_string(uint32_t capacity, uint32_t* count_output, char* output,
                     const std::string& text);

// Spec: a structure whose `type` is wrong is XR_ERROR_VALIDATION_FAILURE.
template <class T>
bool has_type(const T* structure, XrStructureType type) {
    return structure != nullptr && structure->type == type;
}

// The structure of this type in a `next` chain, or nullptr.
const void* find_in_chain(const void* next, XrStructureType type);

// A zeroed OpenXR structure with its type set.
template <class T>
T xr_struct(XrStructureType type) {
    T structure{};
    structure.type = type;
    return structure;
}

// simxr's only system.
constexpr XrSystemId kSystemId = 1;

}  // namespace monoplane::simxr
