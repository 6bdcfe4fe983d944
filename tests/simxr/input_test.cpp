// Scripted presses reach the application's actions at exactly the frames whose predicted display
// time lies in [t, t + duration).
#include <cstring>

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
    auto profile = xr_struct<XrInteractionProfileState>(XR_TYPE_INTERACTION_PROFILE_STATE);
    ASSERT_EQ(xrGetCurrentInteractionProfile(session_, hands[1], &profile), XR_SUCCESS);
    EXPECT_EQ(profile.interactionProfile, suggested.interactionProfile);

    begin_and_focus();            // frame 0
    EXPECT_EQ(other_events_, 1);  // XrEventDataInteractionProfileChanged

    XrActiveActionSet active{set, XR_NULL_PATH};
    auto sync = xr_struct<XrActionsSyncInfo>(XR_TYPE_ACTIONS_SYNC_INFO);
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
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

}  // namespace
}  // namespace monoplane::simxr::testing
