// Scripted presses reach the application's actions at exactly the frames whose predicted display
// time lies in [t, t + duration).
#include <cstring>
#include <vector>

#include "tests/simxr/runtime_fixture.h"

namespace monoplane::simxr::testing {
namespace {

TEST_F(SimxrTest, ScriptedPressesShowUpAtTheirFrames) {
    start(R"(display_rate_hz = 100
[[input]]
t = 0.05
path = "/user/hand/right/input/select/click"
duration = 0.03
[[input]]
t = 0.12
path = "/user/hand/left/input/menu/click"
)");
    auto set_info = xr_struct<XrActionSetCreateInfo>(XR_TYPE_ACTION_SET_CREATE_INFO);
    std::strcpy(set_info.actionSetName, "study");
    std::strcpy(set_info.localizedActionSetName, "Study");
    XrActionSet set = XR_NULL_HANDLE;
    ASSERT_EQ(xrCreateActionSet(instance_, &set_info, &set), XR_SUCCESS);
    const XrPath hands[2] = {path("/user/hand/left"), path("/user/hand/right")};
    auto action_info = xr_struct<XrActionCreateInfo>(XR_TYPE_ACTION_CREATE_INFO);
    action_info.actionType = XR_ACTION_TYPE_BOOLEAN_INPUT;
    std::strcpy(action_info.actionName, "answer");
    std::strcpy(action_info.localizedActionName, "Answer");
    action_info.countSubactionPaths = 2;
    action_info.subactionPaths = hands;
    XrAction action = XR_NULL_HANDLE;
    ASSERT_EQ(xrCreateAction(set, &action_info, &action), XR_SUCCESS);
    const XrActionSuggestedBinding bindings[2] = {
        {action, path("/user/hand/right/input/select/click")},
        {action, path("/user/hand/left/input/menu")}};  // identifier only: menu/click is implied
    auto suggested = xr_struct<XrInteractionProfileSuggestedBinding>(
        XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING);
    suggested.interactionProfile = path("/interaction_profiles/khr/simple_controller");
    suggested.countSuggestedBindings = 2;
    suggested.suggestedBindings = bindings;
    ASSERT_EQ(xrSuggestInteractionProfileBindings(instance_, &suggested), XR_SUCCESS);
    auto attach = xr_struct<XrSessionActionSetsAttachInfo>(XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO);
    attach.countActionSets = 1;
    attach.actionSets = &set;
    ASSERT_EQ(xrAttachSessionActionSets(session_, &attach), XR_SUCCESS);
    begin_and_focus();  // frame 0

    XrActiveActionSet active{set, XR_NULL_PATH};
    auto sync = xr_struct<XrActionsSyncInfo>(XR_TYPE_ACTIONS_SYNC_INFO);
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    // The first sync of the running session chooses the profile (spec 11.4).
    ASSERT_EQ(xrSyncActions(session_, &sync), XR_SUCCESS);
    poll_states();
    EXPECT_EQ(other_events_, 1);  // XrEventDataInteractionProfileChanged
    auto profile = xr_struct<XrInteractionProfileState>(XR_TYPE_INTERACTION_PROFILE_STATE);
    ASSERT_EQ(xrGetCurrentInteractionProfile(session_, hands[1], &profile), XR_SUCCESS);
    EXPECT_EQ(profile.interactionProfile, suggested.interactionProfile);
    auto query = [&](XrPath subaction) {
        auto get = xr_struct<XrActionStateGetInfo>(XR_TYPE_ACTION_STATE_GET_INFO);
        get.action = action;
        get.subactionPath = subaction;
        auto state = xr_struct<XrActionStateBoolean>(XR_TYPE_ACTION_STATE_BOOLEAN);
        EXPECT_EQ(xrGetActionStateBoolean(session_, &get, &state), XR_SUCCESS);
        EXPECT_TRUE(state.isActive);
        return state;
    };
    for (int frame = 1; frame <= 15; ++frame) {
        const XrFrameState frame_state = empty_frame();
        ASSERT_EQ(xrSyncActions(session_, &sync), XR_SUCCESS) << "frame " << frame;
        const bool select_pressed = frame >= 5 && frame <= 7;  // [0.05, 0.08) at 10 ms
        const bool menu_pressed = frame == 12;                 // one period from 0.12
        const XrActionStateBoolean any = query(XR_NULL_PATH);
        EXPECT_EQ(any.currentState, select_pressed || menu_pressed) << "frame " << frame;
        EXPECT_EQ(any.changedSinceLastSync, frame == 5 || frame == 8 || frame == 12 || frame == 13)
            << "frame " << frame;
        if (frame == 5) {
            EXPECT_EQ(any.lastChangeTime, frame_state.predictedDisplayTime);
        }
        EXPECT_EQ(query(hands[1]).currentState, select_pressed) << "frame " << frame;
        EXPECT_EQ(query(hands[0]).currentState, menu_pressed) << "frame " << frame;
    }
}

// Helpers for the binding tests below.
XrActionSet make_set(XrInstance instance) {
    auto info = xr_struct<XrActionSetCreateInfo>(XR_TYPE_ACTION_SET_CREATE_INFO);
    std::strcpy(info.actionSetName, "study");
    std::strcpy(info.localizedActionSetName, "Study");
    XrActionSet set = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateActionSet(instance, &info, &set), XR_SUCCESS);
    return set;
}

XrAction make_action(XrActionSet set, const char* name, XrActionType type,
                     std::vector<XrPath> subaction_paths = {}) {
    auto info = xr_struct<XrActionCreateInfo>(XR_TYPE_ACTION_CREATE_INFO);
    info.actionType = type;
    std::strcpy(info.actionName, name);
    std::strcpy(info.localizedActionName, name);
    info.countSubactionPaths = static_cast<uint32_t>(subaction_paths.size());
    info.subactionPaths = subaction_paths.data();
    XrAction action = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateAction(set, &info, &action), XR_SUCCESS);
    return action;
}

XrResult suggest(XrInstance instance, XrPath profile,
                 const std::vector<XrActionSuggestedBinding>& bindings) {
    auto suggested = xr_struct<XrInteractionProfileSuggestedBinding>(
        XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING);
    suggested.interactionProfile = profile;
    suggested.countSuggestedBindings = static_cast<uint32_t>(bindings.size());
    suggested.suggestedBindings = bindings.data();
    return xrSuggestInteractionProfileBindings(instance, &suggested);
}

void attach(XrSession session, XrActionSet set) {
    auto info = xr_struct<XrSessionActionSetsAttachInfo>(XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO);
    info.countActionSets = 1;
    info.actionSets = &set;
    ASSERT_EQ(xrAttachSessionActionSets(session, &info), XR_SUCCESS);
}

XrResult sync(XrSession session, XrActionSet set) {
    XrActiveActionSet active{set, XR_NULL_PATH};
    auto info = xr_struct<XrActionsSyncInfo>(XR_TYPE_ACTIONS_SYNC_INFO);
    info.countActiveActionSets = 1;
    info.activeActionSets = &active;
    return xrSyncActions(session, &info);
}

uint32_t bound_source_count(XrSession session, XrAction action) {
    auto info = xr_struct<XrBoundSourcesForActionEnumerateInfo>(
        XR_TYPE_BOUND_SOURCES_FOR_ACTION_ENUMERATE_INFO);
    info.action = action;
    uint32_t count = 99;
    EXPECT_EQ(xrEnumerateBoundSourcesForAction(session, &info, 0, &count, nullptr), XR_SUCCESS);
    return count;
}

// spec 11.4: the runtime chooses the interaction profile, and queues
// XrEventDataInteractionProfileChanged, only in xrSyncActions, and sends that event to running
// sessions only; until then xrGetCurrentInteractionProfile says XR_NULL_PATH and nothing is bound.
TEST_F(SimxrTest, InteractionProfileIsChosenInTheFirstSyncOfARunningSession) {
    start("");
    const XrPath right = path("/user/hand/right");
    const XrPath simple = path("/interaction_profiles/khr/simple_controller");
    const XrActionSet set = make_set(instance_);
    const XrAction press = make_action(set, "press", XR_ACTION_TYPE_BOOLEAN_INPUT);
    ASSERT_EQ(suggest(instance_, simple,
                      {{press, path("/user/hand/left/input/select/click")},
                       {press, path("/user/hand/right/input/select/click")}}),
              XR_SUCCESS);
    attach(session_, set);
    const auto current = [&] {
        auto state = xr_struct<XrInteractionProfileState>(XR_TYPE_INTERACTION_PROFILE_STATE);
        EXPECT_EQ(xrGetCurrentInteractionProfile(session_, right, &state), XR_SUCCESS);
        return state.interactionProfile;
    };
    EXPECT_EQ(current(), XR_NULL_PATH);
    EXPECT_EQ(bound_source_count(session_, press), 0u);
    EXPECT_EQ(sync(session_, set), XR_SESSION_NOT_FOCUSED);  // not running: no event
    poll_states();
    EXPECT_EQ(other_events_, 0);
    EXPECT_EQ(current(), XR_NULL_PATH);

    begin_and_focus();  // running and focused, but no sync since
    EXPECT_EQ(other_events_, 0);
    EXPECT_EQ(current(), XR_NULL_PATH);
    ASSERT_EQ(sync(session_, set), XR_SUCCESS);
    EXPECT_EQ(current(), simple);
    EXPECT_EQ(bound_source_count(session_, press), 2u);
    auto event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
    ASSERT_EQ(xrPollEvent(instance_, &event), XR_SUCCESS);
    ASSERT_EQ(event.type, XR_TYPE_EVENT_DATA_INTERACTION_PROFILE_CHANGED);
    EXPECT_EQ(reinterpret_cast<const XrEventDataInteractionProfileChanged&>(event).session,
              session_);
    // The profile stays; later syncs send nothing more.
    empty_frame();
    ASSERT_EQ(sync(session_, set), XR_SUCCESS);
    event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
    EXPECT_EQ(xrPollEvent(instance_, &event), XR_EVENT_UNAVAILABLE);
    EXPECT_EQ(current(), simple);
}

// spec 11.4: a runtime must accept every binding of every 1.0 interaction profile, also for
// hardware it does not have; simxr stores them and binds only the script's profile (here the
// default khr/simple_controller, which the application suggested nothing for).
TEST_F(SimxrTest, BindingsOfProfilesNotPluggedInAreAcceptedButNotBound) {
    start("");
    const XrPath hands[2] = {path("/user/hand/left"), path("/user/hand/right")};
    const XrActionSet set = make_set(instance_);
    const XrAction grab =
        make_action(set, "grab", XR_ACTION_TYPE_FLOAT_INPUT, {hands[0], hands[1]});
    const XrAction move = make_action(set, "move", XR_ACTION_TYPE_VECTOR2F_INPUT);
    const XrAction press = make_action(set, "press", XR_ACTION_TYPE_BOOLEAN_INPUT);
    const XrAction buzz = make_action(set, "buzz", XR_ACTION_TYPE_VIBRATION_OUTPUT);
    // hello_xr's suggestion for the motion controller, and more of its components.
    EXPECT_EQ(suggest(instance_, path("/interaction_profiles/microsoft/motion_controller"),
                      {{grab, path("/user/hand/left/input/squeeze/click")},
                       {grab, path("/user/hand/right/input/trigger/value")},
                       {move, path("/user/hand/left/input/thumbstick")},  // x and y
                       {move, path("/user/hand/right/input/trackpad")},
                       {press, path("/user/hand/right/input/trackpad/touch")},
                       {buzz, path("/user/hand/left/output/haptic")}}),
              XR_SUCCESS);
    EXPECT_EQ(suggest(instance_, path("/interaction_profiles/microsoft/xbox_controller"),
                      {{press, path("/user/gamepad/input/a/click")},
                       {grab, path("/user/gamepad/input/trigger_left")},  // value implied
                       {move, path("/user/gamepad/input/thumbstick_right")},
                       {buzz, path("/user/gamepad/output/haptic_left")}}),
              XR_SUCCESS);
    EXPECT_EQ(suggest(instance_, path("/interaction_profiles/htc/vive_pro"),
                      {{press, path("/user/head/input/volume_up/click")}}),
              XR_SUCCESS);
    // A valid path the action's type cannot read is accepted too (and left unbound).
    EXPECT_EQ(suggest(instance_, path("/interaction_profiles/google/daydream_controller"),
                      {{press, path("/user/hand/left/input/aim/pose")}}),
              XR_SUCCESS);
    for (const char* profile : {"/interaction_profiles/oculus/go_controller",
                                "/interaction_profiles/valve/index_controller",
                                "/interaction_profiles/oculus/touch_controller"}) {
        EXPECT_EQ(suggest(instance_, path(profile),
                          {{press, path("/user/hand/right/input/system/click")}}),
                  XR_SUCCESS)
            << profile;
    }
    attach(session_, set);
    // Nothing of the plugged-in profile was suggested: no current profile, nothing bound.
    for (const char* top : {"/user/hand/left", "/user/hand/right", "/user/head", "/user/gamepad"}) {
        auto state = xr_struct<XrInteractionProfileState>(XR_TYPE_INTERACTION_PROFILE_STATE);
        ASSERT_EQ(xrGetCurrentInteractionProfile(session_, path(top), &state), XR_SUCCESS);
        EXPECT_EQ(state.interactionProfile, XR_NULL_PATH) << top;
    }
    for (XrAction action : {grab, move, press, buzz}) {
        EXPECT_EQ(bound_source_count(session_, action), 0u);
    }
    begin_and_focus();
    ASSERT_EQ(sync(session_, set), XR_SUCCESS);
    auto get = xr_struct<XrActionStateGetInfo>(XR_TYPE_ACTION_STATE_GET_INFO);
    get.action = grab;
    auto value = xr_struct<XrActionStateFloat>(XR_TYPE_ACTION_STATE_FLOAT);
    ASSERT_EQ(xrGetActionStateFloat(session_, &get, &value), XR_SUCCESS);
    EXPECT_FALSE(value.isActive);
}

// Malformed suggestions keep the spec's codes (docs/simxr.md, "Error codes").
TEST_F(SimxrTest, BindingsOutsideAProfilesAllowlistAreRefused) {
    start("", {.xr_validation = false});  // simxr's own answers, behind the layer's checks
    const XrActionSet set = make_set(instance_);
    const XrAction press = make_action(set, "press", XR_ACTION_TYPE_BOOLEAN_INPUT);
    const XrPath motion = path("/interaction_profiles/microsoft/motion_controller");
    const XrPath xbox = path("/interaction_profiles/microsoft/xbox_controller");
    // Unknown profile; a component of another profile; a user path the profile is not valid
    // for; an identifier it does not have; a component it does not have; not an input path.
    EXPECT_EQ(suggest(instance_, path("/interaction_profiles/microsoft/joystick"),
                      {{press, path("/user/hand/left/input/menu/click")}}),
              XR_ERROR_PATH_UNSUPPORTED);
    for (const char* binding :
         {"/user/hand/left/input/a/click", "/user/gamepad/input/menu/click",
          "/user/hand/left/input/dpad_up", "/user/hand/left/input/thumbstick/touch",
          "/user/hand/left/input", "/user/hand/left"}) {
        EXPECT_EQ(suggest(instance_, motion, {{press, path(binding)}}), XR_ERROR_PATH_UNSUPPORTED)
            << binding;
    }
    EXPECT_EQ(suggest(instance_, xbox, {{press, path("/user/hand/left/input/a/click")}}),
              XR_ERROR_PATH_UNSUPPORTED);
    EXPECT_EQ(suggest(instance_, path("/interaction_profiles/htc/vive_pro"),
                      {{press, path("/user/hand/left/input/system/click")}}),
              XR_ERROR_PATH_UNSUPPORTED);
    // One bad binding refuses the whole suggestion.
    EXPECT_EQ(suggest(instance_, xbox,
                      {{press, path("/user/gamepad/input/a/click")},
                       {press, path("/user/gamepad/input/z/click")}}),
              XR_ERROR_PATH_UNSUPPORTED);
    EXPECT_EQ(suggest(instance_, xbox, {{press, XrPath{0x7fff'ffff}}}), XR_ERROR_PATH_INVALID);
}

// The script may plug in a profile without hands: the Xbox controller is at /user/gamepad.
TEST_F(SimxrTest, AGamepadProfileServesTheGamepadPath) {
    start(R"(display_rate_hz = 100
interaction_profile = "/interaction_profiles/microsoft/xbox_controller"
[[input]]
t = 0.03
path = "/user/gamepad/input/a/click"
[[input]]
t = 0.03
path = "/user/gamepad/input/thumbstick_left/y"
)");
    const XrActionSet set = make_set(instance_);
    const XrAction press = make_action(set, "press", XR_ACTION_TYPE_BOOLEAN_INPUT);
    const XrAction move = make_action(set, "move", XR_ACTION_TYPE_VECTOR2F_INPUT);
    const XrAction buzz = make_action(set, "buzz", XR_ACTION_TYPE_VIBRATION_OUTPUT);
    const XrPath xbox = path("/interaction_profiles/microsoft/xbox_controller");
    ASSERT_EQ(suggest(instance_, xbox,
                      {{press, path("/user/gamepad/input/a")},
                       {move, path("/user/gamepad/input/thumbstick_left")},
                       {buzz, path("/user/gamepad/output/haptic_right")}}),
              XR_SUCCESS);
    attach(session_, set);
    begin_and_focus();                           // frame 0
    ASSERT_EQ(sync(session_, set), XR_SUCCESS);  // chooses the profile
    auto state = xr_struct<XrInteractionProfileState>(XR_TYPE_INTERACTION_PROFILE_STATE);
    ASSERT_EQ(xrGetCurrentInteractionProfile(session_, path("/user/gamepad"), &state), XR_SUCCESS);
    EXPECT_EQ(state.interactionProfile, xbox);
    ASSERT_EQ(xrGetCurrentInteractionProfile(session_, path("/user/hand/left"), &state),
              XR_SUCCESS);
    EXPECT_EQ(state.interactionProfile, XR_NULL_PATH);
    EXPECT_EQ(bound_source_count(session_, move), 2u);  // thumbstick_left/x and /y
    for (int frame = 1; frame <= 5; ++frame) {
        empty_frame();
        ASSERT_EQ(sync(session_, set), XR_SUCCESS);
        auto get = xr_struct<XrActionStateGetInfo>(XR_TYPE_ACTION_STATE_GET_INFO);
        get.action = press;
        auto pressed = xr_struct<XrActionStateBoolean>(XR_TYPE_ACTION_STATE_BOOLEAN);
        ASSERT_EQ(xrGetActionStateBoolean(session_, &get, &pressed), XR_SUCCESS);
        EXPECT_TRUE(pressed.isActive);
        EXPECT_EQ(pressed.currentState, frame == 3) << "frame " << frame;  // [0.03, 0.04)
        get.action = move;
        auto stick = xr_struct<XrActionStateVector2f>(XR_TYPE_ACTION_STATE_VECTOR2F);
        ASSERT_EQ(xrGetActionStateVector2f(session_, &get, &stick), XR_SUCCESS);
        EXPECT_TRUE(stick.isActive);
        EXPECT_EQ(stick.currentState.x, 0.0f);
        EXPECT_EQ(stick.currentState.y, frame == 3 ? 1.0f : 0.0f) << "frame " << frame;
    }
    // Haptics on the gamepad are accepted (and felt by no one).
    auto vibration = xr_struct<XrHapticVibration>(XR_TYPE_HAPTIC_VIBRATION);
    vibration.duration = XR_MIN_HAPTIC_DURATION;
    vibration.frequency = XR_FREQUENCY_UNSPECIFIED;
    vibration.amplitude = 0.5f;
    auto haptic = xr_struct<XrHapticActionInfo>(XR_TYPE_HAPTIC_ACTION_INFO);
    haptic.action = buzz;
    EXPECT_EQ(xrApplyHapticFeedback(session_, &haptic,
                                    reinterpret_cast<const XrHapticBaseHeader*>(&vibration)),
              XR_SUCCESS);
    EXPECT_EQ(xrStopHapticFeedback(session_, &haptic), XR_SUCCESS);
}

// Controllers are simulated as held still in front of the head (docs/simxr.md): their action
// spaces move with VIEW, the left one to the left and the right one to the right, below and in
// front of the eyes; unlocatable until their action set is synced while focused (spec 7.2.1).
TEST_F(SimxrTest, HandSpacesRideWithTheHeadOnceSynced) {
    start(R"([[pose]]
t = 0.0
position = [0.0, 1.6, 0.0]
[[pose]]
t = 1.0
position = [1.0, 1.2, -2.0]
yaw_pitch_roll_deg = [90.0, 0.0, 0.0]
)");
    const XrPath hands[2] = {path("/user/hand/left"), path("/user/hand/right")};
    const XrActionSet set = make_set(instance_);
    const XrAction pose = make_action(set, "hand", XR_ACTION_TYPE_POSE_INPUT, {hands[0], hands[1]});
    ASSERT_EQ(suggest(instance_, path("/interaction_profiles/khr/simple_controller"),
                      {{pose, path("/user/hand/left/input/grip/pose")},
                       {pose, path("/user/hand/right/input/aim")}}),  // pose implied
              XR_SUCCESS);
    auto action_space = [&](XrPath subaction, XrVector3f offset) {
        auto info = xr_struct<XrActionSpaceCreateInfo>(XR_TYPE_ACTION_SPACE_CREATE_INFO);
        info.action = pose;
        info.subactionPath = subaction;
        info.poseInActionSpace = {{0, 0, 0, 1}, offset};
        XrSpace space = XR_NULL_HANDLE;
        EXPECT_EQ(xrCreateActionSpace(session_, &info, &space), XR_SUCCESS);
        return space;
    };
    const XrSpace left = action_space(hands[0], {0, 0, 0});
    const XrSpace right = action_space(hands[1], {0, 0, 0});
    const XrSpace left_ahead = action_space(hands[0], {0, 0, -0.1f});
    auto view_info = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    view_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
    view_info.poseInReferenceSpace = {{0, 0, 0, 1}, {0, 0, 0}};
    XrSpace view = XR_NULL_HANDLE;
    ASSERT_EQ(xrCreateReferenceSpace(session_, &view_info, &view), XR_SUCCESS);
    attach(session_, set);
    begin_and_focus();

    auto locate = [&](XrSpace space, XrSpace base, XrTime time) {
        auto location = xr_struct<XrSpaceLocation>(XR_TYPE_SPACE_LOCATION);
        EXPECT_EQ(xrLocateSpace(space, base, time, &location), XR_SUCCESS);
        return location;
    };
    constexpr XrSpaceLocationFlags kValid =
        XR_SPACE_LOCATION_POSITION_VALID_BIT | XR_SPACE_LOCATION_ORIENTATION_VALID_BIT;
    XrFrameState frame = empty_frame();
    // Not synced yet: unlocatable, except relative to another space on the same hand (spec 7.4).
    EXPECT_EQ(locate(left, view, frame.predictedDisplayTime).locationFlags & kValid, 0u);
    const XrSpaceLocation same_hand = locate(left_ahead, left, frame.predictedDisplayTime);
    EXPECT_EQ(same_hand.locationFlags & kValid, kValid);
    EXPECT_FLOAT_EQ(same_hand.pose.position.z, -0.1f);

    ASSERT_EQ(sync(session_, set), XR_SUCCESS);
    const XrSpaceLocation l0 = locate(left, view, frame.predictedDisplayTime);
    const XrSpaceLocation r0 = locate(right, view, frame.predictedDisplayTime);
    ASSERT_EQ(l0.locationFlags & kValid, kValid);
    ASSERT_EQ(r0.locationFlags & kValid, kValid);
    EXPECT_LT(l0.pose.position.x, 0.0f);
    EXPECT_GT(r0.pose.position.x, 0.0f);
    EXPECT_FLOAT_EQ(l0.pose.position.x, -r0.pose.position.x);
    for (const XrSpaceLocation& hand : {l0, r0}) {
        EXPECT_LT(hand.pose.position.y, 0.0f);  // below the eyes
        EXPECT_LT(hand.pose.position.z, 0.0f);  // in front (-z is forward)
    }
    // Half a second later the head has moved and turned; in VIEW the hand has not.
    for (int i = 0; i < 45; ++i) frame = empty_frame();
    ASSERT_EQ(sync(session_, set), XR_SUCCESS);
    const XrSpaceLocation l1 = locate(left, view, frame.predictedDisplayTime);
    EXPECT_NEAR(l1.pose.position.x, l0.pose.position.x, 1e-5);
    EXPECT_NEAR(l1.pose.position.y, l0.pose.position.y, 1e-5);
    EXPECT_NEAR(l1.pose.position.z, l0.pose.position.z, 1e-5);
    EXPECT_NEAR(l1.pose.orientation.w, 1.0f, 1e-5);
    // The application's offset is in the hand's frame: 10 cm further along its -z.
    const XrSpaceLocation ahead = locate(left_ahead, view, frame.predictedDisplayTime);
    EXPECT_NEAR(ahead.pose.position.z, l0.pose.position.z - 0.1f, 1e-5);
}

TEST_F(SimxrTest, HapticsAndSourceNamesCheckTheirArguments) {
    start("", {.xr_validation = false});  // simxr's own answers, behind the layer's checks
    const XrPath left = path("/user/hand/left");
    const XrActionSet set = make_set(instance_);
    const XrAction buzz = make_action(set, "buzz", XR_ACTION_TYPE_VIBRATION_OUTPUT, {left});
    const XrAction pose = make_action(set, "hand", XR_ACTION_TYPE_POSE_INPUT, {left});
    auto space_info = xr_struct<XrActionSpaceCreateInfo>(XR_TYPE_ACTION_SPACE_CREATE_INFO);
    space_info.action = pose;
    space_info.subactionPath = path("/user/hand/right");  // not one of the action's
    space_info.poseInActionSpace = {{0, 0, 0, 1}, {0, 0, 0}};
    XrSpace space = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateActionSpace(session_, &space_info, &space), XR_ERROR_PATH_UNSUPPORTED);
    space_info.subactionPath = left;
    space_info.poseInActionSpace.orientation = {0, 0, 0, 2};
    EXPECT_EQ(xrCreateActionSpace(session_, &space_info, &space), XR_ERROR_POSE_INVALID);

    auto name_info =
        xr_struct<XrInputSourceLocalizedNameGetInfo>(XR_TYPE_INPUT_SOURCE_LOCALIZED_NAME_GET_INFO);
    name_info.sourcePath = path("/user/hand/left/input/select/click");
    name_info.whichComponents = XR_INPUT_SOURCE_LOCALIZED_NAME_COMPONENT_BIT;
    uint32_t size = 0;
    // spec 11.8: before xrAttachSessionActionSets there are no sources to name.
    EXPECT_EQ(xrGetInputSourceLocalizedName(session_, &name_info, 0, &size, nullptr),
              XR_ERROR_ACTIONSET_NOT_ATTACHED);
    ASSERT_EQ(suggest(instance_, path("/interaction_profiles/khr/simple_controller"),
                      {{buzz, path("/user/hand/left/output/haptic")}}),
              XR_SUCCESS);
    attach(session_, set);
    name_info.whichComponents = 0;
    EXPECT_EQ(xrGetInputSourceLocalizedName(session_, &name_info, 0, &size, nullptr),
              XR_ERROR_VALIDATION_FAILURE);

    begin_and_focus();
    ASSERT_EQ(sync(session_, set), XR_SUCCESS);
    auto vibration = xr_struct<XrHapticVibration>(XR_TYPE_HAPTIC_VIBRATION);
    vibration.duration = XR_MIN_HAPTIC_DURATION;
    auto haptic = xr_struct<XrHapticActionInfo>(XR_TYPE_HAPTIC_ACTION_INFO);
    haptic.action = buzz;
    haptic.subactionPath = path("/user/hand/right");
    const auto* feedback = reinterpret_cast<const XrHapticBaseHeader*>(&vibration);
    EXPECT_EQ(xrApplyHapticFeedback(session_, &haptic, feedback), XR_ERROR_PATH_UNSUPPORTED);
    EXPECT_EQ(xrStopHapticFeedback(session_, &haptic), XR_ERROR_PATH_UNSUPPORTED);
    haptic.subactionPath = left;
    EXPECT_EQ(xrApplyHapticFeedback(session_, &haptic, feedback), XR_SUCCESS);
    vibration.type = XR_TYPE_ACTION_STATE_FLOAT;
    EXPECT_EQ(xrApplyHapticFeedback(session_, &haptic, feedback), XR_ERROR_VALIDATION_FAILURE);
}

}  // namespace
}  // namespace monoplane::simxr::testing
