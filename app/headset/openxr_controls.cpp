// The participant's controls on an OpenXR session: the controller mapping per interaction
// profile, the action set suggested for it, the presses read at each xrSyncActions, and the
// profile the runtime bound.
#include <cstring>
#include <iostream>
#include <string>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "app/headset/openxr_headset_impl.h"

namespace monoplane::headset {

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
    if (eye_gaze) MONOPLANE_TRY(create_gaze_action());
    XrSessionActionSetsAttachInfo attach{XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO};
    attach.countActionSets = 1;
    attach.actionSets = &action_set;
    MONOPLANE_TRY(check("xrAttachSessionActionSets", xrAttachSessionActionSets(session, &attach)));
    if (!eye_gaze) return Ok{};
    // The gaze located in the VIEW space: a direction in the head's frame, whatever the head.
    XrActionSpaceCreateInfo gaze_info{XR_TYPE_ACTION_SPACE_CREATE_INFO};
    gaze_info.action = gaze_action;
    gaze_info.poseInActionSpace.orientation.w = 1.0f;
    MONOPLANE_TRY(
        check("xrCreateActionSpace", xrCreateActionSpace(session, &gaze_info, &gaze_space)));
    XrReferenceSpaceCreateInfo view_info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
    view_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    view_info.poseInReferenceSpace.orientation.w = 1.0f;
    return check("xrCreateReferenceSpace", xrCreateReferenceSpace(session, &view_info, &view));
}

// XR_EXT_eye_gaze_interaction: a pose action in the study's set, bound to the gaze (created once
// per instance, like the set; only the spaces are per session).
Result<void> OpenXrHeadset::Impl::create_gaze_action() {
    if (gaze_action == XR_NULL_HANDLE) {
        XrActionCreateInfo info{XR_TYPE_ACTION_CREATE_INFO};
        info.actionType = XR_ACTION_TYPE_POSE_INPUT;
        std::strcpy(info.actionName, "gaze");
        std::strcpy(info.localizedActionName, "Where the participant looks");
        MONOPLANE_TRY(check("xrCreateAction", xrCreateAction(action_set, &info, &gaze_action)));
    }
    XrActionSuggestedBinding binding{gaze_action, XR_NULL_PATH};
    MONOPLANE_TRY(
        check("xrStringToPath",
              xrStringToPath(instance, "/user/eyes_ext/input/gaze_ext/pose", &binding.binding)));
    XrInteractionProfileSuggestedBinding suggestion{XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING};
    MONOPLANE_TRY(check("xrStringToPath",
                        xrStringToPath(instance, "/interaction_profiles/ext/eye_gaze_interaction",
                                       &suggestion.interactionProfile)));
    suggestion.countSuggestedBindings = 1;
    suggestion.suggestedBindings = &binding;
    return check("xrSuggestInteractionProfileBindings",
                 xrSuggestInteractionProfileBindings(instance, &suggestion));
}

bool OpenXrHeadset::tracks_eye_gaze() const {
    return impl_->eye_gaze;
}

bool OpenXrHeadset::offers_eye_gaze() const {
    return impl_->eye_gaze_offered;
}

Result<std::optional<GazeSample>> OpenXrHeadset::locate_gaze(std::int64_t display_time_ns) {
    Impl& x = *impl_;
    if (!x.eye_gaze || x.gaze_space == XR_NULL_HANDLE) return std::optional<GazeSample>();
    XrSpaceLocation location{XR_TYPE_SPACE_LOCATION};
    MONOPLANE_TRY(x.check("xrLocateSpace (gaze)",
                          xrLocateSpace(x.gaze_space, x.view, display_time_ns, &location)));
    constexpr XrSpaceLocationFlags kTracked =
        XR_SPACE_LOCATION_ORIENTATION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT;
    GazeSample sample;
    sample.valid = (location.locationFlags & kTracked) == kTracked;
    if (sample.valid) {
        const XrQuaternionf& q = location.pose.orientation;
        const glm::dquat orientation(q.w, q.x, q.y, q.z);
        sample.direction = glm::normalize(orientation * glm::dvec3(0.0, 0.0, -1.0));
    }
    return std::optional<GazeSample>(sample);
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

}  // namespace monoplane::headset
