// xrLocateViews and xrLocateSpace against the HMD profile, computed independently here.
#include <cmath>

#include "tests/simxr/runtime_fixture.h"

namespace monoplane::simxr::testing {
namespace {

// The vive profile's numbers (hmd/profiles/vive.toml), written out so the test does not share code
// with the runtime.
constexpr double kViveLeft[4] = {-1.391937, 1.247409, 1.464287, -1.468819};  // l, r, u, d
constexpr double kViveRight[4] = {-1.246557, 1.398447, 1.472458, -1.465505};

XrSpace make_space(XrSession session, XrReferenceSpaceType type) {
    auto info = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    info.referenceSpaceType = type;
    info.poseInReferenceSpace.orientation.w = 1.0f;
    XrSpace space = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateReferenceSpace(session, &info, &space), XR_SUCCESS);
    return space;
}

TEST_F(SimxrTest, ViewsHaveTheProfilesFrustaAndEyePositions) {
    start(R"(hmd = "vive"
[[pose]]
t = 0
position = [0.5, 1.6, -1.0]
)");
    begin_and_focus();
    const XrSpace local = make_space(session_, XR_REFERENCE_SPACE_TYPE_LOCAL);
    auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    ASSERT_EQ(xrWaitFrame(session_, nullptr, &state), XR_SUCCESS);
    auto locate = xr_struct<XrViewLocateInfo>(XR_TYPE_VIEW_LOCATE_INFO);
    locate.viewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    locate.displayTime = state.predictedDisplayTime;
    locate.space = local;
    auto view_state = xr_struct<XrViewState>(XR_TYPE_VIEW_STATE);
    std::vector<XrView> views(2, xr_struct<XrView>(XR_TYPE_VIEW));
    uint32_t count = 0;
    ASSERT_EQ(xrLocateViews(session_, &locate, &view_state, 2, &count, views.data()), XR_SUCCESS);
    ASSERT_EQ(count, 2u);
    EXPECT_EQ(view_state.viewStateFlags,
              XR_VIEW_STATE_ORIENTATION_VALID_BIT | XR_VIEW_STATE_POSITION_VALID_BIT |
                  XR_VIEW_STATE_ORIENTATION_TRACKED_BIT | XR_VIEW_STATE_POSITION_TRACKED_BIT);
    for (int eye = 0; eye < 2; ++eye) {
        const double* tangents = eye == 0 ? kViveLeft : kViveRight;
        EXPECT_NEAR(views[eye].fov.angleLeft, std::atan(tangents[0]), 1e-6);
        EXPECT_NEAR(views[eye].fov.angleRight, std::atan(tangents[1]), 1e-6);
        EXPECT_NEAR(views[eye].fov.angleUp, std::atan(tangents[2]), 1e-6);
        EXPECT_NEAR(views[eye].fov.angleDown, std::atan(tangents[3]), 1e-6);
        EXPECT_NEAR(views[eye].pose.position.x, 0.5 + (eye == 0 ? -0.032 : 0.032), 1e-6);
        EXPECT_NEAR(views[eye].pose.position.y, 1.6, 1e-6);
        EXPECT_NEAR(views[eye].pose.position.z, -1.0, 1e-6);
        EXPECT_NEAR(views[eye].pose.orientation.w, 1.0, 1e-6);
    }
    EXPECT_LT(views[0].fov.angleLeft, 0.0f);
    EXPECT_EQ(xrDestroySpace(local), XR_SUCCESS);
}

TEST_F(SimxrTest, ViewSpaceFollowsTheScriptedHead) {
    start(R"(display_rate_hz = 100
[[pose]]
t = 0
position = [0.0, 1.6, 0.0]
[[pose]]
t = 1
position = [0.0, 1.6, -1.0]
yaw_pitch_roll_deg = [90, 0, 0]
)");
    const XrSpace local = make_space(session_, XR_REFERENCE_SPACE_TYPE_LOCAL);
    const XrSpace view = make_space(session_, XR_REFERENCE_SPACE_TYPE_VIEW);
    auto location = xr_struct<XrSpaceLocation>(XR_TYPE_SPACE_LOCATION);
    // Frame 0 is at script time 0; half a second later the head is halfway.
    auto info = begin_info();
    poll_states();
    ASSERT_EQ(xrBeginSession(session_, &info), XR_SUCCESS);
    const XrFrameState frame0 = empty_frame();
    ASSERT_EQ(xrLocateSpace(view, local, frame0.predictedDisplayTime + 500'000'000, &location),
              XR_SUCCESS);
    EXPECT_EQ(location.locationFlags & XR_SPACE_LOCATION_POSITION_TRACKED_BIT,
              XR_SPACE_LOCATION_POSITION_TRACKED_BIT);
    EXPECT_NEAR(location.pose.position.z, -0.5, 1e-6);
    // Yaw 45 degrees about +y: quaternion (0, sin 22.5, 0, cos 22.5).
    EXPECT_NEAR(location.pose.orientation.y, std::sin(M_PI / 8), 1e-6);
    EXPECT_NEAR(location.pose.orientation.w, std::cos(M_PI / 8), 1e-6);
    // And LOCAL seen from VIEW is the inverse.
    ASSERT_EQ(xrLocateSpace(local, view, frame0.predictedDisplayTime + 2'000'000'000, &location),
              XR_SUCCESS);
    // Head at (0, 1.6, -1) looking along -x (its right is -z): LOCAL's origin lies 1 m to the
    // head's left and 1.6 m below it.
    EXPECT_NEAR(location.pose.position.x, -1.0, 1e-6);
    EXPECT_NEAR(location.pose.position.y, -1.6, 1e-6);
    EXPECT_NEAR(location.pose.position.z, 0.0, 1e-6);
}

}  // namespace
}  // namespace monoplane::simxr::testing
