// Actions (spec chapter 11): action sets and actions, suggested bindings for the interaction
// profile the script simulates, and their states, latched by xrSyncActions from the script's
// presses at the predicted display time of the latest xrWaitFrame.
#include <algorithm>
#include <string_view>

#include "simxr/entry_points.h"
#include "simxr/interaction_profiles.h"
#include "simxr/runtime_state.h"

namespace monoplane::simxr {
namespace {

constexpr std::string_view kTopLevelPaths[] = {"/user/hand/left", "/user/hand/right", "/user/head",
                                               "/user/gamepad"};
// spec 11.3.2: booleans bound to a value read as pressed above a runtime-chosen threshold.
constexpr float kPressThreshold = 0.5f;

// /user/eyes_ext only where XR_EXT_eye_gaze_interaction is enabled.
bool is_top_level_path(const Instance& instance, const std::string& path) {
    if (instance.eye_gaze_interaction && path == kEyesUserPath) return true;
    return std::ranges::find(kTopLevelPaths, path) != std::end(kTopLevelPaths);
}

// The profile a suggestion names: a core one, or the eye gaze profile where its extension is
// enabled; nullptr for any other (XR_ERROR_PATH_UNSUPPORTED).
const InteractionProfile* suggestable_profile(const Instance& instance, std::string_view path) {
    if (instance.eye_gaze_interaction && path == kEyeGazeProfilePath) {
        return &eye_gaze_interaction_profile();
    }
    return find_interaction_profile(path);
}

// spec 11.2: action and action set names are one well-formed path segment.
XrResult check_name(const char* name, const char* localized_name) {
    const std::string_view text(name);
    if (text.empty()) return XR_ERROR_NAME_INVALID;
    for (char c : text) {
        const bool allowed =
            (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
        if (!allowed) return XR_ERROR_PATH_FORMAT_INVALID;
    }
    if (localized_name[0] == '\0') return XR_ERROR_LOCALIZED_NAME_INVALID;
    return XR_SUCCESS;
}

void forget_action(Action* action) {
    Instance& instance = *action->set->instance;
    for (auto& [profile, bindings] : instance.suggested_bindings) {
        std::erase_if(bindings, [action](const auto& binding) { return binding.first == action; });
    }
    if (instance.session != nullptr) {
        std::erase_if(instance.session->bindings,
                      [action](const auto& binding) { return binding.first == action; });
        // spec 7.3 (xrCreateActionSpace): an action space goes with its action; simxr keeps the
        // handle valid but unlocatable until the application destroys it.
        for (Space* space : instance.session->spaces) {
            if (space->action == action) space->action = nullptr;
        }
    }
}

bool is_attached_to(const Session& session, const ActionSet* set) {
    return std::ranges::find(session.attached_sets, set) != session.attached_sets.end();
}

// What every xrGetActionState* call checks; fills `components` with the bound component paths
// that pass the subaction filter and `active` with the action's isActive.
XrResult resolve_state_query(const Session& session, const XrActionStateGetInfo* info,
                             XrActionType expected, std::vector<const std::string*>& components,
                             bool& active) {
    if (!has_type(info, XR_TYPE_ACTION_STATE_GET_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    const Action* action = lookup<Action>(info->action);
    if (action == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (action->type != expected) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (!is_attached_to(session, action->set)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (XrResult r = check_subaction_path(*session.instance, *action, info->subactionPath);
        r != XR_SUCCESS) {
        return r;
    }
    std::string prefix;
    if (info->subactionPath != XR_NULL_PATH) {
        prefix = *session.instance->paths.find(info->subactionPath) + "/";
    }
    for (const auto& [bound_action, component] : session.bindings) {
        if (bound_action == action && component.starts_with(prefix)) {
            components.push_back(&component);
        }
    }
    active = !components.empty() &&
             std::ranges::find(session.synced_sets, action->set) != session.synced_sets.end();
    return XR_SUCCESS;
}

ActionUse use_of(XrActionType type) {
    switch (type) {
        case XR_ACTION_TYPE_BOOLEAN_INPUT:
            return ActionUse::boolean;
        case XR_ACTION_TYPE_FLOAT_INPUT:
            return ActionUse::scalar;
        case XR_ACTION_TYPE_VECTOR2F_INPUT:
            return ActionUse::vector2;
        case XR_ACTION_TYPE_POSE_INPUT:
            return ActionUse::pose;
        default:
            return ActionUse::vibration;
    }
}

float value_in(const std::map<std::string, float>& values, const std::string& component) {
    const auto found = values.find(component);
    return found == values.end() ? 0.0f : found->second;
}

// spec (XrActiveActionSet): a subaction path that none of the set's actions was created with is
// XR_ERROR_PATH_UNSUPPORTED; a value that is no path atom is XR_ERROR_PATH_INVALID.
XrResult check_active_subaction_path(const Instance& instance, const ActionSet& set, XrPath path) {
    if (path == XR_NULL_PATH) return XR_SUCCESS;
    if (instance.paths.find(path) == nullptr) return XR_ERROR_PATH_INVALID;
    const bool declared = std::ranges::any_of(set.actions, [path](const Action* action) {
        return std::ranges::find(action->subaction_paths, path) != action->subaction_paths.end();
    });
    return declared ? XR_SUCCESS : XR_ERROR_PATH_UNSUPPORTED;
}

// The suggested bindings of `profile` whose action sets the session attached, added to its own;
// whether there were any.
bool bind_suggested(Session& session, XrPath profile) {
    const Instance& instance = *session.instance;
    const auto found = instance.suggested_bindings.find(profile);
    if (found == instance.suggested_bindings.end()) return false;
    bool any = false;
    for (const auto& binding : found->second) {
        if (!is_attached_to(session, binding.first->set)) continue;
        session.bindings.push_back(binding);
        any = true;
    }
    return any;
}

// spec 11.4: the runtime chooses the interaction profile, and may change it, only in
// xrSyncActions, and tells only running sessions. simxr's controllers are the script's profile
// from the start, so the first sync of a running session chooses it for good: its suggested
// bindings become the session's, and an application that suggested nothing for it gets no
// bindings, XR_NULL_PATH as the current profile and no event (the event is only sent for a
// profile the application suggested bindings for).
void choose_interaction_profile(Session& session) {
    session.profile_chosen = true;
    Instance& instance = *session.instance;
    const XrPath profile = instance.paths.intern(instance.script.interaction_profile);
    if (bind_suggested(session, profile)) session.interaction_profile = profile;
    // An eye tracker is plugged in from the start too: /user/eyes_ext gets the gaze profile.
    if (instance.eye_gaze_interaction && instance.script.gaze.tracker) {
        const XrPath gaze = instance.paths.intern(std::string(kEyeGazeProfilePath));
        if (bind_suggested(session, gaze)) session.gaze_profile = gaze;
    }
    if (session.bindings.empty()) return;
    auto event = xr_struct<XrEventDataInteractionProfileChanged>(
        XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED);
    event.session = reinterpret_cast<XrSession>(&session);
    queue_event(instance, &event, sizeof(event), &session);
}

}  // namespace

XrResult check_subaction_path(const Instance& instance, const Action& action, XrPath path) {
    if (path == XR_NULL_PATH) return XR_SUCCESS;
    if (instance.paths.find(path) == nullptr) return XR_ERROR_PATH_INVALID;
    const bool declared =
        std::ranges::find(action.subaction_paths, path) != action.subaction_paths.end();
    return declared ? XR_SUCCESS : XR_ERROR_PATH_UNSUPPORTED;
}

void destroy_action_set(ActionSet* set) {
    for (Action* action : set->actions) {
        forget_action(action);
        unregister_object(action);
    }
    Instance& instance = *set->instance;
    std::erase(instance.action_sets, set);
    if (instance.session != nullptr) {
        std::erase(instance.session->attached_sets, set);
        std::erase(instance.session->synced_sets, set);
    }
    unregister_object(set);
}

XrResult XRAPI_CALL xrCreateActionSet(XrInstance handle, const XrActionSetCreateInfo* info,
                                      XrActionSet* set_handle) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_ACTION_SET_CREATE_INFO) || set_handle == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (XrResult r = check_name(info->actionSetName, info->localizedActionSetName);
        r != XR_SUCCESS) {
        return r;
    }
    // spec 11.2: both names are unique among the instance's live action sets.
    for (const ActionSet* existing : instance->action_sets) {
        if (existing->name == info->actionSetName) return XR_ERROR_NAME_DUPLICATED;
    }
    for (const ActionSet* existing : instance->action_sets) {
        if (existing->localized_name == info->localizedActionSetName) {
            return XR_ERROR_LOCALIZED_NAME_DUPLICATED;
        }
    }
    auto set = std::make_unique<ActionSet>();
    set->instance = instance;
    set->name = info->actionSetName;
    set->localized_name = info->localizedActionSetName;
    instance->action_sets.push_back(set.get());
    *set_handle = register_object<XrActionSet>(std::move(set));
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrDestroyActionSet(XrActionSet handle) {
    std::lock_guard lock(runtime_mutex());
    ActionSet* set = lookup<ActionSet>(handle);
    if (set == nullptr) return XR_ERROR_HANDLE_INVALID;
    destroy_action_set(set);
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrCreateAction(XrActionSet set_handle, const XrActionCreateInfo* info,
                                   XrAction* action_handle) {
    std::lock_guard lock(runtime_mutex());
    ActionSet* set = lookup<ActionSet>(set_handle);
    if (set == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_ACTION_CREATE_INFO) || action_handle == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    // spec: an attached action set is immutable.
    if (set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    if (XrResult r = check_name(info->actionName, info->localizedActionName); r != XR_SUCCESS) {
        return r;
    }
    // spec 11.3: both names are unique among the set's live actions.
    for (const Action* existing : set->actions) {
        if (existing->name == info->actionName) return XR_ERROR_NAME_DUPLICATED;
    }
    for (const Action* existing : set->actions) {
        if (existing->localized_name == info->localizedActionName) {
            return XR_ERROR_LOCALIZED_NAME_DUPLICATED;
        }
    }
    switch (info->actionType) {
        case XR_ACTION_TYPE_BOOLEAN_INPUT:
        case XR_ACTION_TYPE_FLOAT_INPUT:
        case XR_ACTION_TYPE_VECTOR2F_INPUT:
        case XR_ACTION_TYPE_POSE_INPUT:
        case XR_ACTION_TYPE_VIBRATION_OUTPUT:
            break;
        default:
            return XR_ERROR_VALIDATION_FAILURE;
    }
    auto action = std::make_unique<Action>();
    action->set = set;
    action->name = info->actionName;
    action->localized_name = info->localizedActionName;
    action->type = info->actionType;
    // spec 11.3 (XrActionCreateInfo): each subaction path is one of the top level user paths
    // and listed once, else XR_ERROR_PATH_UNSUPPORTED; a value that is no path atom at all is
    // XR_ERROR_PATH_INVALID.
    for (uint32_t i = 0; i < info->countSubactionPaths; ++i) {
        const XrPath path = info->subactionPaths[i];
        const std::string* text = set->instance->paths.find(path);
        if (text == nullptr) return XR_ERROR_PATH_INVALID;
        if (!is_top_level_path(*set->instance, *text) ||
            std::ranges::find(action->subaction_paths, path) != action->subaction_paths.end()) {
            return XR_ERROR_PATH_UNSUPPORTED;
        }
        action->subaction_paths.push_back(path);
    }
    set->actions.push_back(action.get());
    *action_handle = register_object<XrAction>(std::move(action));
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrDestroyAction(XrAction handle) {
    std::lock_guard lock(runtime_mutex());
    Action* action = lookup<Action>(handle);
    if (action == nullptr) return XR_ERROR_HANDLE_INVALID;
    forget_action(action);
    std::erase(action->set->actions, action);
    unregister_object(action);
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrSuggestInteractionProfileBindings(
    XrInstance handle, const XrInteractionProfileSuggestedBinding* suggested) {
    std::lock_guard lock(runtime_mutex());
    Instance* instance = lookup<Instance>(handle);
    if (instance == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(suggested, XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING) ||
        suggested->countSuggestedBindings == 0 || suggested->suggestedBindings == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    const std::string* profile_path = instance->paths.find(suggested->interactionProfile);
    if (profile_path == nullptr) return XR_ERROR_PATH_INVALID;
    // spec 11.4: an interaction profile or binding path outside the spec's allowlist is
    // XR_ERROR_PATH_UNSUPPORTED; every one inside it must be accepted, whether or not simxr
    // simulates that hardware (only the script's profile is ever bound).
    const InteractionProfile* profile = suggestable_profile(*instance, *profile_path);
    if (profile == nullptr) return XR_ERROR_PATH_UNSUPPORTED;
    std::vector<std::pair<Action*, std::string>> bindings;
    for (uint32_t i = 0; i < suggested->countSuggestedBindings; ++i) {
        const XrActionSuggestedBinding& binding = suggested->suggestedBindings[i];
        Action* action = lookup<Action>(binding.action);
        if (action == nullptr || action->set->instance != instance) {
            return XR_ERROR_HANDLE_INVALID;
        }
        // spec: an action whose set is attached can no longer get suggestions.
        if (action->set->attached) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
        const std::string* path = instance->paths.find(binding.binding);
        if (path == nullptr) return XR_ERROR_PATH_INVALID;
        if (!is_binding_path(*profile, *path)) return XR_ERROR_PATH_UNSUPPORTED;
        // A valid path the action's type cannot read is accepted and left unbound (spec 11.4).
        for (const Component* component : bound_components(*profile, *path, use_of(action->type))) {
            bindings.emplace_back(action, component->path);
        }
    }
    // spec: a later call for the same profile replaces the earlier suggestion.
    instance->suggested_bindings[suggested->interactionProfile] = std::move(bindings);
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrAttachSessionActionSets(XrSession handle,
                                              const XrSessionActionSetsAttachInfo* info) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO) || info->countActionSets == 0 ||
        info->actionSets == nullptr) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    if (!session->attached_sets.empty()) return XR_ERROR_ACTIONSETS_ALREADY_ATTACHED;
    std::vector<ActionSet*> sets;
    for (uint32_t i = 0; i < info->countActionSets; ++i) {
        ActionSet* set = lookup<ActionSet>(info->actionSets[i]);
        if (set == nullptr) return XR_ERROR_HANDLE_INVALID;
        sets.push_back(set);
    }
    for (ActionSet* set : sets) set->attached = true;
    // The interaction profile and bindings follow in xrSyncActions (choose_interaction_profile).
    session->attached_sets = sets;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrGetCurrentInteractionProfile(XrSession handle, XrPath top_level_path,
                                                   XrInteractionProfileState* state) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(state, XR_TYPE_INTERACTION_PROFILE_STATE)) return XR_ERROR_VALIDATION_FAILURE;
    const std::string* path = session->instance->paths.find(top_level_path);
    if (path == nullptr) return XR_ERROR_PATH_INVALID;
    if (!is_top_level_path(*session->instance, *path)) return XR_ERROR_PATH_UNSUPPORTED;
    if (session->attached_sets.empty()) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (*path == kEyesUserPath) {
        state->interactionProfile = session->gaze_profile;
        return XR_SUCCESS;
    }
    // The plugged-in profile serves its own user paths only (an Xbox controller is at
    // /user/gamepad, not at the hands).
    const std::string* current = session->instance->paths.find(session->interaction_profile);
    const InteractionProfile* profile =
        current == nullptr ? nullptr : find_interaction_profile(*current);
    const bool serves = profile != nullptr &&
                        std::ranges::find(profile->user_paths, *path) != profile->user_paths.end();
    state->interactionProfile = serves ? session->interaction_profile : XR_NULL_PATH;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrSyncActions(XrSession handle, const XrActionsSyncInfo* info) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_ACTIONS_SYNC_INFO) ||
        (info->countActiveActionSets > 0 && info->activeActionSets == nullptr)) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    std::vector<ActionSet*> sets;
    for (uint32_t i = 0; i < info->countActiveActionSets; ++i) {
        ActionSet* set = lookup<ActionSet>(info->activeActionSets[i].actionSet);
        if (set == nullptr) return XR_ERROR_HANDLE_INVALID;
        if (!is_attached_to(*session, set)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
        if (XrResult r = check_active_subaction_path(*session->instance, *set,
                                                     info->activeActionSets[i].subactionPath);
            r != XR_SUCCESS) {
            return r;
        }
        sets.push_back(set);
    }
    if (session->running && !session->profile_chosen && !session->attached_sets.empty()) {
        choose_interaction_profile(*session);
    }
    // spec 11.5.2: without input focus every action is inactive and the call says why.
    if (session->state != XR_SESSION_STATE_FOCUSED) {
        session->synced_sets.clear();
        return XR_SESSION_NOT_FOCUSED;
    }
    const Script& script = session->instance->script;
    const XrTime time = session->latest_wait_time;
    session->previous_values = session->values;
    session->values.clear();
    for (const auto& [action, component] : session->bindings) {
        const float value =
            input_pressed_at(script, component, time - session->base_time) ? 1.0f : 0.0f;
        session->values[component] = value;
        if (value != value_in(session->previous_values, component)) {
            session->last_change[component] = time;
        }
    }
    session->synced_sets = sets;
    session->sync_time = time;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrGetActionStateBoolean(XrSession handle, const XrActionStateGetInfo* info,
                                            XrActionStateBoolean* state) {
    std::lock_guard lock(runtime_mutex());
    const Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(state, XR_TYPE_ACTION_STATE_BOOLEAN)) return XR_ERROR_VALIDATION_FAILURE;
    std::vector<const std::string*> components;
    bool active = false;
    if (XrResult r =
            resolve_state_query(*session, info, XR_ACTION_TYPE_BOOLEAN_INPUT, components, active);
        r != XR_SUCCESS) {
        return r;
    }
    bool current = false;
    bool previous = false;
    XrTime last_change = 0;
    for (const std::string* component : components) {
        current = current || value_in(session->values, *component) >= kPressThreshold;
        previous = previous || value_in(session->previous_values, *component) >= kPressThreshold;
        if (auto found = session->last_change.find(*component);
            found != session->last_change.end()) {
            last_change = std::max(last_change, found->second);
        }
    }
    state->isActive = active ? XR_TRUE : XR_FALSE;
    state->currentState = active && current ? XR_TRUE : XR_FALSE;
    state->changedSinceLastSync = active && current != previous ? XR_TRUE : XR_FALSE;
    state->lastChangeTime = active ? last_change : 0;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrGetActionStateFloat(XrSession handle, const XrActionStateGetInfo* info,
                                          XrActionStateFloat* state) {
    std::lock_guard lock(runtime_mutex());
    const Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(state, XR_TYPE_ACTION_STATE_FLOAT)) return XR_ERROR_VALIDATION_FAILURE;
    std::vector<const std::string*> components;
    bool active = false;
    if (XrResult r =
            resolve_state_query(*session, info, XR_ACTION_TYPE_FLOAT_INPUT, components, active);
        r != XR_SUCCESS) {
        return r;
    }
    float current = 0.0f;
    float previous = 0.0f;
    XrTime last_change = 0;
    for (const std::string* component : components) {
        current = std::max(current, value_in(session->values, *component));
        previous = std::max(previous, value_in(session->previous_values, *component));
        if (auto found = session->last_change.find(*component);
            found != session->last_change.end()) {
            last_change = std::max(last_change, found->second);
        }
    }
    state->isActive = active ? XR_TRUE : XR_FALSE;
    state->currentState = active ? current : 0.0f;
    state->changedSinceLastSync = active && current != previous ? XR_TRUE : XR_FALSE;
    state->lastChangeTime = active ? last_change : 0;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrGetActionStateVector2f(XrSession handle, const XrActionStateGetInfo* info,
                                             XrActionStateVector2f* state) {
    std::lock_guard lock(runtime_mutex());
    const Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(state, XR_TYPE_ACTION_STATE_VECTOR2F)) return XR_ERROR_VALIDATION_FAILURE;
    std::vector<const std::string*> components;
    bool active = false;
    if (XrResult r =
            resolve_state_query(*session, info, XR_ACTION_TYPE_VECTOR2F_INPUT, components, active);
        r != XR_SUCCESS) {
        return r;
    }
    // Bound to an identifier's x and y (spec 11.4); a scripted "press" of an axis holds it at 1.
    // Of several bound sources the longest vector wins (spec 11.5.1). bound_components gives a
    // vector2f action its components as (x, y) pairs, kept adjacent through attach and filter.
    XrVector2f current{0.0f, 0.0f};
    XrVector2f previous{0.0f, 0.0f};
    XrTime last_change = 0;
    auto length2 = [](XrVector2f v) { return v.x * v.x + v.y * v.y; };
    for (std::size_t i = 0; i + 1 < components.size(); i += 2) {
        const std::string& x = *components[i];
        const std::string& y = *components[i + 1];
        const XrVector2f now{value_in(session->values, x), value_in(session->values, y)};
        const XrVector2f before{value_in(session->previous_values, x),
                                value_in(session->previous_values, y)};
        if (length2(now) > length2(current)) current = now;
        if (length2(before) > length2(previous)) previous = before;
        for (const std::string* component : {&x, &y}) {
            if (auto found = session->last_change.find(*component);
                found != session->last_change.end()) {
                last_change = std::max(last_change, found->second);
            }
        }
    }
    const bool changed = current.x != previous.x || current.y != previous.y;
    state->isActive = active ? XR_TRUE : XR_FALSE;
    state->currentState = active ? current : XrVector2f{0.0f, 0.0f};
    state->changedSinceLastSync = active && changed ? XR_TRUE : XR_FALSE;
    state->lastChangeTime = active ? last_change : 0;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL xrGetActionStatePose(XrSession handle, const XrActionStateGetInfo* info,
                                         XrActionStatePose* state) {
    std::lock_guard lock(runtime_mutex());
    const Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(state, XR_TYPE_ACTION_STATE_POSE)) return XR_ERROR_VALIDATION_FAILURE;
    std::vector<const std::string*> components;
    bool active = false;
    if (XrResult r =
            resolve_state_query(*session, info, XR_ACTION_TYPE_POSE_INPUT, components, active);
        r != XR_SUCCESS) {
        return r;
    }
    state->isActive = active ? XR_TRUE : XR_FALSE;
    return XR_SUCCESS;
}

XrResult XRAPI_CALL
xrEnumerateBoundSourcesForAction(XrSession handle, const XrBoundSourcesForActionEnumerateInfo* info,
                                 uint32_t capacity, uint32_t* count, XrPath* sources) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_BOUND_SOURCES_FOR_ACTION_ENUMERATE_INFO)) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    const Action* action = lookup<Action>(info->action);
    if (action == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!is_attached_to(*session, action->set)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    std::vector<XrPath> bound;
    for (const auto& [bound_action, component] : session->bindings) {
        if (bound_action != action) continue;
        // A source suggested twice for one action is still one source.
        const XrPath source = session->instance->paths.intern(component);
        if (std::ranges::find(bound, source) == bound.end()) bound.push_back(source);
    }
    return fill_array(capacity, count, sources, bound);
}

XrResult XRAPI_CALL xrGetInputSourceLocalizedName(XrSession handle,
                                                  const XrInputSourceLocalizedNameGetInfo* info,
                                                  uint32_t capacity, uint32_t* count,
                                                  char* buffer) {
    std::lock_guard lock(runtime_mutex());
    Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_INPUT_SOURCE_LOCALIZED_NAME_GET_INFO)) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    // spec (XrInputSourceLocalizedNameGetInfo): whichComponents must not be 0.
    if (info->whichComponents == 0) return XR_ERROR_VALIDATION_FAILURE;
    const std::string* path = session->instance->paths.find(info->sourcePath);
    if (path == nullptr) return XR_ERROR_PATH_INVALID;
    if (session->attached_sets.empty()) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    // The name comes from the plugged-in profile (the only one whose sources are ever bound); a
    // source of no profile simxr knows is named by its path.
    const std::string* current = session->instance->paths.find(session->interaction_profile);
    const InteractionProfile* profile = find_interaction_profile(
        current != nullptr ? *current : session->instance->script.interaction_profile);
    if (session->gaze_profile != XR_NULL_PATH && path->starts_with(kEyesUserPath)) {
        profile = &eye_gaze_interaction_profile();
    }
    if (profile == nullptr || user_path_of(*profile, *path).empty()) {
        return fill_string(capacity, count, buffer, *path);
    }
    const XrInputSourceLocalizedNameFlags which = info->whichComponents;
    return fill_string(
        capacity, count, buffer,
        localized_source_name(*profile, *path,
                              (which & XR_INPUT_SOURCE_LOCALIZED_NAME_USER_PATH_BIT) != 0,
                              (which & XR_INPUT_SOURCE_LOCALIZED_NAME_INTERACTION_PROFILE_BIT) != 0,
                              (which & XR_INPUT_SOURCE_LOCALIZED_NAME_COMPONENT_BIT) != 0));
}

XrResult XRAPI_CALL xrApplyHapticFeedback(XrSession handle, const XrHapticActionInfo* info,
                                          const XrHapticBaseHeader* feedback) {
    std::lock_guard lock(runtime_mutex());
    const Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    // spec 11.6: the one haptic structure of core OpenXR is XrHapticVibration.
    if (!has_type(info, XR_TYPE_HAPTIC_ACTION_INFO) || feedback == nullptr ||
        feedback->type != XR_TYPE_HAPTIC_VIBRATION) {
        return XR_ERROR_VALIDATION_FAILURE;
    }
    const Action* action = lookup<Action>(info->action);
    if (action == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (action->type != XR_ACTION_TYPE_VIBRATION_OUTPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (!is_attached_to(*session, action->set)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (XrResult r = check_subaction_path(*session->instance, *action, info->subactionPath);
        r != XR_SUCCESS) {
        return r;
    }
    return session->state == XR_SESSION_STATE_FOCUSED ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
}

XrResult XRAPI_CALL xrStopHapticFeedback(XrSession handle, const XrHapticActionInfo* info) {
    std::lock_guard lock(runtime_mutex());
    const Session* session = lookup<Session>(handle);
    if (session == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (!has_type(info, XR_TYPE_HAPTIC_ACTION_INFO)) return XR_ERROR_VALIDATION_FAILURE;
    const Action* action = lookup<Action>(info->action);
    if (action == nullptr) return XR_ERROR_HANDLE_INVALID;
    if (action->type != XR_ACTION_TYPE_VIBRATION_OUTPUT) return XR_ERROR_ACTION_TYPE_MISMATCH;
    if (!is_attached_to(*session, action->set)) return XR_ERROR_ACTIONSET_NOT_ATTACHED;
    if (XrResult r = check_subaction_path(*session->instance, *action, info->subactionPath);
        r != XR_SUCCESS) {
        return r;
    }
    return session->state == XR_SESSION_STATE_FOCUSED ? XR_SUCCESS : XR_SESSION_NOT_FOCUSED;
}

}  // namespace monoplane::simxr
