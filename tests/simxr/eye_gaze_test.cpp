// XR_EXT_eye_gaze_interaction on simxr: the system says whether it tracks the eyes, an
// application's gaze pose action is bound on /user/eyes_ext, and its action space, located in
// the VIEW space, points where the script's fixation on a known point puts the eyes; during a
// blink the space is not located and no sample time is given.
#include <cmath>
#include <cstring>

#include "tests/simxr/runtime_fixture.h"

namespace monoplane::simxr::testing {
namespace {

// The gaze direction (-z of the pose) of a located pose.
void gaze_direction(const XrPosef& pose, double out[3]) {
    const double x = pose.orientation.x, y = pose.orientation.y, z = pose.orientation.z,
                 w = pose.orientation.w;
    // The rotation's third column, negated: R * (0, 0, -1).
    out[0] = -(2.0 * (x * z + w * y));
    out[1] = -(2.0 * (y * z - w * x));
    out[2] = -(1.0 - 2.0 * (x * x + y * y));
}

class EyeGazeTest : public SimxrTest {
  protected:
    bool supports_gaze() {
        auto gaze = xr_struct<XrSystemEyeGazeInteractionPropertiesEXT>(
            XR_TYPE_SYSTEM_EYE_GAZE_INTERACTION_PROPERTIES_EXT);
        auto properties = xr_struct<XrSystemProperties>(XR_TYPE_SYSTEM_PROPERTIES);
        properties.next = &gaze;
        EXPECT_EQ(xrGetSystemProperties(instance_, system_, &properties), XR_SUCCESS);
        return gaze.supportsEyeGazeInteraction == XR_TRUE;
    }

    // A set with a pose action, and the suggestion of the gaze pose for it: the suggestion's
    // result.
    XrResult suggest_gaze_binding() {
        auto set_info = xr_struct<XrActionSetCreateInfo>(XR_TYPE_ACTION_SET_CREATE_INFO);
        std::strcpy(set_info.actionSetName, "gaze");
        std::strcpy(set_info.localizedActionSetName, "Gaze");
        EXPECT_EQ(xrCreateActionSet(instance_, &set_info, &set_), XR_SUCCESS);
        auto action_info = xr_struct<XrActionCreateInfo>(XR_TYPE_ACTION_CREATE_INFO);
        action_info.actionType = XR_ACTION_TYPE_POSE_INPUT;
        std::strcpy(action_info.actionName, "gaze");
        std::strcpy(action_info.localizedActionName, "Gaze");
        EXPECT_EQ(xrCreateAction(set_, &action_info, &action_), XR_SUCCESS);
        const XrActionSuggestedBinding binding{action_, path("/user/eyes_ext/input/gaze_ext/pose")};
        auto suggested = xr_struct<XrInteractionProfileSuggestedBinding>(
            XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING);
        suggested.interactionProfile = path("/interaction_profiles/ext/eye_gaze_interaction");
        suggested.countSuggestedBindings = 1;
        suggested.suggestedBindings = &binding;
        return xrSuggestInteractionProfileBindings(instance_, &suggested);
    }

    // A pose action bound to the gaze, its set attached, the session focused and synced once;
    // returns the action space and the VIEW space.
    void bind_gaze(XrSpace* gaze_space, XrSpace* view_space) {
        ASSERT_EQ(suggest_gaze_binding(), XR_SUCCESS);
        auto attach =
            xr_struct<XrSessionActionSetsAttachInfo>(XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO);
        attach.countActionSets = 1;
        attach.actionSets = &set_;
        ASSERT_EQ(xrAttachSessionActionSets(session_, &attach), XR_SUCCESS);
        auto space_info = xr_struct<XrActionSpaceCreateInfo>(XR_TYPE_ACTION_SPACE_CREATE_INFO);
        space_info.action = action_;
        space_info.poseInActionSpace.orientation.w = 1.0f;
        ASSERT_EQ(xrCreateActionSpace(session_, &space_info, gaze_space), XR_SUCCESS);
        auto view_info = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
        view_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_VIEW;
        view_info.poseInReferenceSpace.orientation.w = 1.0f;
        ASSERT_EQ(xrCreateReferenceSpace(session_, &view_info, view_space), XR_SUCCESS);
        begin_and_focus();
        sync();
    }

    void sync() {
        XrActiveActionSet active{set_, XR_NULL_PATH};
        auto info = xr_struct<XrActionsSyncInfo>(XR_TYPE_ACTIONS_SYNC_INFO);
        info.countActiveActionSets = 1;
        info.activeActionSets = &active;
        ASSERT_EQ(xrSyncActions(session_, &info), XR_SUCCESS);
    }

    XrActionSet set_ = XR_NULL_HANDLE;
    XrAction action_ = XR_NULL_HANDLE;
};

TEST_F(EyeGazeTest, TheSystemTracksTheEyesUnlessTheScriptSaysItHasNoTracker) {
    start("", FixtureOptions{.eye_gaze = true});
    EXPECT_TRUE(supports_gaze());
}

TEST_F(EyeGazeTest, AHeadsetWithoutAnEyeTrackerSaysSo) {
    start("[gaze]\ntracker = false\n", FixtureOptions{.eye_gaze = true});
    EXPECT_FALSE(supports_gaze());
}

// The eyes fixate a point 4 m ahead and 1 m right of the head (at 1.6 m, looking down -z): in
// the VIEW space the gaze points along (1, 0, -4) / |(1, 0, -4)|, worked out by hand.
TEST_F(EyeGazeTest, TheGazePosePointsAtTheScriptsFixation) {
    start(R"(
[gaze]
blink_every_s = 0
[[fixation]]
t = 0
duration = 100
target = [1.0, 1.6, -4.0]
[[blink]]
t = 0.5
duration = 0.2
)",
          FixtureOptions{.eye_gaze = true});
    XrSpace gaze = XR_NULL_HANDLE;
    XrSpace view = XR_NULL_HANDLE;
    bind_gaze(&gaze, &view);
    auto profile = xr_struct<XrInteractionProfileState>(XR_TYPE_INTERACTION_PROFILE_STATE);
    ASSERT_EQ(xrGetCurrentInteractionProfile(session_, path("/user/eyes_ext"), &profile),
              XR_SUCCESS);
    EXPECT_EQ(profile.interactionProfile, path("/interaction_profiles/ext/eye_gaze_interaction"));

    const XrFrameState frame = empty_frame();
    sync();
    auto sample = xr_struct<XrEyeGazeSampleTimeEXT>(XR_TYPE_EYE_GAZE_SAMPLE_TIME_EXT);
    auto location = xr_struct<XrSpaceLocation>(XR_TYPE_SPACE_LOCATION);
    location.next = &sample;
    ASSERT_EQ(xrLocateSpace(gaze, view, frame.predictedDisplayTime, &location), XR_SUCCESS);
    EXPECT_TRUE(location.locationFlags & XR_SPACE_LOCATION_ORIENTATION_VALID_BIT);
    EXPECT_TRUE(location.locationFlags & XR_SPACE_LOCATION_ORIENTATION_TRACKED_BIT);
    EXPECT_EQ(sample.time, frame.predictedDisplayTime);
    double d[3];
    gaze_direction(location.pose, d);
    const double norm = std::sqrt(17.0);
    EXPECT_NEAR(d[0], 1.0 / norm, 1e-6);
    EXPECT_NEAR(d[1], 0.0, 1e-6);
    EXPECT_NEAR(d[2], -4.0 / norm, 1e-6);
    // The midpoint between the eyes: the VIEW space's origin.
    EXPECT_NEAR(location.pose.position.x, 0.0, 1e-6);

    // 0.6 s after frame 0: inside the blink, no sample.
    const XrTime blink = frame.predictedDisplayTime + 600'000'000;
    location = xr_struct<XrSpaceLocation>(XR_TYPE_SPACE_LOCATION);
    sample.time = 1;
    location.next = &sample;
    ASSERT_EQ(xrLocateSpace(gaze, view, blink, &location), XR_SUCCESS);
    EXPECT_EQ(location.locationFlags, 0u);
    EXPECT_EQ(sample.time, 0);
}

// Without the extension the gaze profile and its user path are not known.
TEST_F(EyeGazeTest, WithoutTheExtensionTheGazeProfileIsRefused) {
    start("");
    EXPECT_EQ(suggest_gaze_binding(), XR_ERROR_PATH_UNSUPPORTED);
    xr_validation_messages().clear();  // the layer reports the refused profile as well
}

}  // namespace
}  // namespace monoplane::simxr::testing
