// Session life cycle (spec 9.3) and the virtual clock, through the real loader.
#include "tests/simxr/runtime_fixture.h"

namespace monoplane::simxr::testing {
namespace {

using States = std::vector<XrSessionState>;

TEST_F(SimxrTest, SessionWalksThroughTheSpecLifeCycle) {
    start("display_rate_hz = 100\n");
    EXPECT_EQ(poll_states(), (States{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_READY}));
    const XrSessionBeginInfo info = begin_info();
    ASSERT_EQ(xrBeginSession(session_, &info), XR_SUCCESS);
    EXPECT_EQ(poll_states(), States{});  // no frame submitted yet: still READY

    const XrFrameState frame0 = empty_frame();
    EXPECT_FALSE(frame0.shouldRender);  // READY: frames are not shown yet
    EXPECT_EQ(frame0.predictedDisplayPeriod, 10'000'000);
    EXPECT_EQ(poll_states(), (States{XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_VISIBLE,
                                     XR_SESSION_STATE_FOCUSED}));
    const XrFrameState frame1 = empty_frame();
    EXPECT_TRUE(frame1.shouldRender);
    // Frame n is displayed at frame 0's time + n periods; waiting never sleeps.
    EXPECT_EQ(frame1.predictedDisplayTime - frame0.predictedDisplayTime, 10'000'000);
    const XrFrameState frame2 = empty_frame();
    EXPECT_EQ(frame2.predictedDisplayTime - frame0.predictedDisplayTime, 20'000'000);

    ASSERT_EQ(xrRequestExitSession(session_), XR_SUCCESS);
    EXPECT_EQ(poll_states(), (States{XR_SESSION_STATE_VISIBLE, XR_SESSION_STATE_SYNCHRONIZED,
                                     XR_SESSION_STATE_STOPPING}));
    ASSERT_EQ(xrEndSession(session_), XR_SUCCESS);
    EXPECT_EQ(poll_states(), (States{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_EXITING}));
}

// spec 9.3: READY becomes SYNCHRONIZED once the application's frame loop is synchronized with
// the runtime, i.e. after it submitted a frame (OpenXR-CTS "Session State" polls right after
// xrBeginSession and fails on any change).
TEST_F(SimxrTest, SynchronizedWaitsForTheFirstSubmittedFrame) {
    start("");
    EXPECT_EQ(poll_states(), (States{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_READY}));
    const XrSessionBeginInfo info = begin_info();
    ASSERT_EQ(xrBeginSession(session_, &info), XR_SUCCESS);
    EXPECT_EQ(poll_states(), States{});
    auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    ASSERT_EQ(xrWaitFrame(session_, nullptr, &state), XR_SUCCESS);
    EXPECT_FALSE(state.shouldRender);
    ASSERT_EQ(xrBeginFrame(session_, nullptr), XR_SUCCESS);
    EXPECT_EQ(poll_states(), States{});  // waited and begun, not yet submitted
    auto end = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
    end.displayTime = state.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    ASSERT_EQ(xrEndFrame(session_, &end), XR_SUCCESS);
    EXPECT_EQ(poll_states(), (States{XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_VISIBLE,
                                     XR_SESSION_STATE_FOCUSED}));
    EXPECT_TRUE(empty_frame().shouldRender);
    EXPECT_EQ(poll_states(), States{});  // only the first frame moves the state
}

// An exit requested before any frame still walks the spec's graph: READY, SYNCHRONIZED,
// STOPPING (there is no edge from READY to STOPPING).
TEST_F(SimxrTest, ExitBeforeTheFirstFramePassesThroughSynchronized) {
    start("");
    poll_states();
    const XrSessionBeginInfo info = begin_info();
    ASSERT_EQ(xrBeginSession(session_, &info), XR_SUCCESS);
    ASSERT_EQ(xrRequestExitSession(session_), XR_SUCCESS);
    EXPECT_EQ(poll_states(), (States{XR_SESSION_STATE_SYNCHRONIZED, XR_SESSION_STATE_STOPPING}));
    ASSERT_EQ(xrEndSession(session_), XR_SUCCESS);
    EXPECT_EQ(poll_states(), (States{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_EXITING}));
}

TEST_F(SimxrTest, ExitAfterStopsTheSessionAtThatTime) {
    start("display_rate_hz = 100\nexit_after_s = 0.1\n");
    begin_and_focus();  // frame 0 ends, FOCUSED arrives
    int stopping_frame = -1;
    for (int frame = 1; frame < 20 && stopping_frame < 0; ++frame) {
        empty_frame();
        for (XrSessionState state : poll_states()) {
            if (state == XR_SESSION_STATE_STOPPING) stopping_frame = frame;
        }
    }
    // Frame 10 is the first whose predicted time (0.1 s after frame 0) reaches exit_after_s.
    EXPECT_EQ(stopping_frame, 10);
    EXPECT_EQ(xrEndSession(session_), XR_SUCCESS);
    EXPECT_EQ(poll_states(), (States{XR_SESSION_STATE_IDLE, XR_SESSION_STATE_EXITING}));
}

TEST_F(SimxrTest, LoseSessionAtMakesTheSessionLost) {
    start("display_rate_hz = 100\nlose_session_at_s = 0.05\n");
    begin_and_focus();
    bool lost = false;
    for (int frame = 1; frame <= 5; ++frame) {
        empty_frame();
        for (XrSessionState state : poll_states())
            lost = lost || state == XR_SESSION_STATE_LOSS_PENDING;
    }
    EXPECT_TRUE(lost);
    auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    EXPECT_EQ(xrWaitFrame(session_, nullptr, &state), XR_ERROR_SESSION_LOST);
}

// lose_instance_at_s: the instance is lost as a runtime's is when its service dies. The wait
// that reaches the time still succeeds; from then every call fails with XR_ERROR_INSTANCE_LOST,
// xrPollEvent first delivers the loss-pending event, and what the application holds can still
// be destroyed (TearDown destroys the session and the instance and expects success).
TEST_F(SimxrTest, LoseInstanceAtMakesEveryCallFailButTheDestroyFunctions) {
    start("display_rate_hz = 100\nlose_instance_at_s = 0.05\n");
    begin_and_focus();  // frame 0
    XrTime lost_frame_time = 0;
    int lost_frame = -1;
    for (int frame = 1; frame < 20 && lost_frame < 0; ++frame) {
        auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
        ASSERT_EQ(xrWaitFrame(session_, nullptr, &state), XR_SUCCESS) << "frame " << frame;
        const XrResult begun = xrBeginFrame(session_, nullptr);
        if (begun == XR_ERROR_INSTANCE_LOST) {
            lost_frame = frame;
            lost_frame_time = state.predictedDisplayTime;
            break;
        }
        ASSERT_EQ(begun, XR_SUCCESS);
        auto end = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
        end.displayTime = state.predictedDisplayTime;
        end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
        ASSERT_EQ(xrEndFrame(session_, &end), XR_SUCCESS);
    }
    // Frame 5 is the first whose predicted time (0.05 s after frame 0) reaches the loss.
    EXPECT_EQ(lost_frame, 5);

    auto event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
    ASSERT_EQ(xrPollEvent(instance_, &event), XR_SUCCESS);
    ASSERT_EQ(event.type, XR_TYPE_EVENT_DATA_INSTANCE_LOSS_PENDING);
    EXPECT_EQ(reinterpret_cast<const XrEventDataInstanceLossPending&>(event).lossTime,
              lost_frame_time);
    event = xr_struct<XrEventDataBuffer>(XR_TYPE_EVENT_DATA_BUFFER);
    EXPECT_EQ(xrPollEvent(instance_, &event), XR_ERROR_INSTANCE_LOST);

    auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    EXPECT_EQ(xrWaitFrame(session_, nullptr, &state), XR_ERROR_INSTANCE_LOST);
    EXPECT_EQ(xrRequestExitSession(session_), XR_ERROR_INSTANCE_LOST);
    EXPECT_EQ(xrEndSession(session_), XR_ERROR_INSTANCE_LOST);
    XrSystemId system = XR_NULL_SYSTEM_ID;
    auto system_info = xr_struct<XrSystemGetInfo>(XR_TYPE_SYSTEM_GET_INFO);
    system_info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    EXPECT_EQ(xrGetSystem(instance_, &system_info, &system), XR_ERROR_INSTANCE_LOST);
    // A loss is worded like any result.
    char text[XR_MAX_RESULT_STRING_SIZE] = {};
    ASSERT_EQ(xrResultToString(instance_, XR_ERROR_INSTANCE_LOST, text), XR_SUCCESS);
    EXPECT_STREQ(text, "XR_ERROR_INSTANCE_LOST");
}

TEST_F(SimxrTest, ReportsItsSystemAndViews) {
    start("hmd = \"vive\"\n");
    auto properties = xr_struct<XrSystemProperties>(XR_TYPE_SYSTEM_PROPERTIES);
    ASSERT_EQ(xrGetSystemProperties(instance_, system_, &properties), XR_SUCCESS);
    EXPECT_TRUE(properties.trackingProperties.positionTracking);
    uint32_t count = 0;
    ASSERT_EQ(
        xrEnumerateViewConfigurationViews(
            instance_, system_, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 0, &count, nullptr),
        XR_SUCCESS);
    ASSERT_EQ(count, 2u);
    std::vector<XrViewConfigurationView> views(
        2, xr_struct<XrViewConfigurationView>(XR_TYPE_VIEW_CONFIGURATION_VIEW));
    ASSERT_EQ(
        xrEnumerateViewConfigurationViews(
            instance_, system_, XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO, 2, &count, views.data()),
        XR_SUCCESS);
    EXPECT_EQ(views[0].recommendedImageRectWidth, 1344u);
    EXPECT_EQ(views[1].recommendedImageRectHeight, 1512u);
    EXPECT_EQ(views[0].recommendedSwapchainSampleCount, 1u);
    char name[XR_MAX_RESULT_STRING_SIZE];
    ASSERT_EQ(xrResultToString(instance_, XR_ERROR_SESSION_NOT_READY, name), XR_SUCCESS);
    EXPECT_STREQ(name, "XR_ERROR_SESSION_NOT_READY");
}

}  // namespace
}  // namespace monoplane::simxr::testing
