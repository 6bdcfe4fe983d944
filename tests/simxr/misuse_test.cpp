// The spec's error codes for application mistakes, one test per rule (docs/simxr.md).
#include "tests/simxr/runtime_fixture.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace monoplane::simxr::testing {
namespace {

XrSwapchain make_swapchain(XrSession session, int64_t format, uint32_t width, uint32_t height,
                           XrSwapchainCreateFlags flags = 0) {
    auto info = xr_struct<XrSwapchainCreateInfo>(XR_TYPE_SWAPCHAIN_CREATE_INFO);
    info.createFlags = flags;
    info.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT;
    info.format = format;
    info.sampleCount = 1;
    info.width = width;
    info.height = height;
    info.faceCount = 1;
    info.arraySize = 1;
    info.mipCount = 1;
    XrSwapchain swapchain = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateSwapchain(session, &info, &swapchain), XR_SUCCESS);
    return swapchain;
}

TEST_F(SimxrTest, CreateSessionBeforeRequirementsIsRefused) {
    start("", {.query_requirements = false, .create_session = false});
    const XrGraphicsBindingVulkan2KHR vulkan = binding();
    const XrSessionCreateInfo info = session_info(&vulkan);
    EXPECT_EQ(xrCreateSession(instance_, &info, &session_),
              XR_ERROR_GRAPHICS_REQUIREMENTS_CALL_MISSING);
}

TEST_F(SimxrTest, CreateSessionNeedsTheNamedPhysicalDevice) {
    // A session without a binding is invalid usage the OpenXR layer stops; simxr's answer is
    // what is tested here.
    start("", {.create_session = false, .xr_validation = false});
    XrGraphicsBindingVulkan2KHR vulkan = binding();
    vulkan.physicalDevice = reinterpret_cast<VkPhysicalDevice>(uintptr_t{0x1234});
    XrSessionCreateInfo info = session_info(&vulkan);
    EXPECT_EQ(xrCreateSession(instance_, &info, &session_), XR_ERROR_GRAPHICS_DEVICE_INVALID);
    info.next = nullptr;  // no binding at all
    EXPECT_EQ(xrCreateSession(instance_, &info, &session_), XR_ERROR_GRAPHICS_DEVICE_INVALID);
    session_ = XR_NULL_HANDLE;
}

TEST_F(SimxrTest, BeginSessionNeedsReadyAndOnlyOnce) {
    start("");
    const XrSessionBeginInfo info = begin_info();
    // READY is queued but not yet delivered: the application has not been told.
    EXPECT_EQ(xrBeginSession(session_, &info), XR_ERROR_SESSION_NOT_READY);
    poll_states();
    EXPECT_EQ(xrBeginSession(session_, &info), XR_SUCCESS);
    EXPECT_EQ(xrBeginSession(session_, &info), XR_ERROR_SESSION_RUNNING);
}

TEST_F(SimxrTest, EndSessionNeedsStopping) {
    start("");
    EXPECT_EQ(xrEndSession(session_), XR_ERROR_SESSION_NOT_RUNNING);
    begin_and_focus();
    EXPECT_EQ(xrEndSession(session_), XR_ERROR_SESSION_NOT_STOPPING);
}

TEST_F(SimxrTest, FrameCallsNeedARunningSession) {
    start("");
    auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    EXPECT_EQ(xrWaitFrame(session_, nullptr, &state), XR_ERROR_SESSION_NOT_RUNNING);
    EXPECT_EQ(xrBeginFrame(session_, nullptr), XR_ERROR_SESSION_NOT_RUNNING);
    auto end = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
    end.displayTime = 1;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    EXPECT_EQ(xrEndFrame(session_, &end), XR_ERROR_SESSION_NOT_RUNNING);
}

TEST_F(SimxrTest, FrameCallsMustComeInOrder) {
    start("");
    poll_states();
    const XrSessionBeginInfo info = begin_info();
    ASSERT_EQ(xrBeginSession(session_, &info), XR_SUCCESS);
    EXPECT_EQ(xrBeginFrame(session_, nullptr), XR_ERROR_CALL_ORDER_INVALID);
    auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    ASSERT_EQ(xrWaitFrame(session_, nullptr, &state), XR_SUCCESS);
    auto end = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
    end.displayTime = state.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    EXPECT_EQ(xrEndFrame(session_, &end), XR_ERROR_CALL_ORDER_INVALID);
    ASSERT_EQ(xrBeginFrame(session_, nullptr), XR_SUCCESS);
    end.displayTime = state.predictedDisplayTime;
    EXPECT_EQ(xrEndFrame(session_, &end), XR_SUCCESS);
}

// spec (xrEndFrame): displayTime should come from xrWaitFrame, but only a time <= 0 is
// XR_ERROR_TIME_INVALID. OpenXR-CTS "xrBeginFrame/xrEndFrame" ends a frame with an earlier
// frame's time; a pipelined application may end one with the latest wait's time.
TEST_F(SimxrTest, EndFrameTakesAnyPositiveDisplayTime) {
    start("");
    begin_and_focus();
    auto first = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    ASSERT_EQ(xrWaitFrame(session_, nullptr, &first), XR_SUCCESS);
    ASSERT_EQ(xrBeginFrame(session_, nullptr), XR_SUCCESS);
    auto second = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    ASSERT_EQ(xrWaitFrame(session_, nullptr, &second), XR_SUCCESS);
    ASSERT_GT(second.predictedDisplayTime, first.predictedDisplayTime);
    auto end = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    end.displayTime = second.predictedDisplayTime;  // the next frame's time
    EXPECT_EQ(xrEndFrame(session_, &end), XR_SUCCESS);
    ASSERT_EQ(xrBeginFrame(session_, nullptr), XR_SUCCESS);
    end.displayTime = 0;
    EXPECT_EQ(xrEndFrame(session_, &end), XR_ERROR_TIME_INVALID);
    end.displayTime = -1;
    EXPECT_EQ(xrEndFrame(session_, &end), XR_ERROR_TIME_INVALID);
    end.displayTime = 1;  // long past, still a time
    EXPECT_EQ(xrEndFrame(session_, &end), XR_SUCCESS);
    EXPECT_EQ(xrEndFrame(session_, &end), XR_ERROR_CALL_ORDER_INVALID);  // nothing begun now
}

TEST_F(SimxrTest, SwapchainImagesMustBeAcquiredWaitedReleasedInOrder) {
    start("");
    const XrSwapchain swapchain = make_swapchain(session_, VK_FORMAT_R8G8B8A8_SRGB, 64, 64);
    auto wait = xr_struct<XrSwapchainImageWaitInfo>(XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
    wait.timeout = XR_INFINITE_DURATION;
    EXPECT_EQ(xrWaitSwapchainImage(swapchain, &wait), XR_ERROR_CALL_ORDER_INVALID);
    EXPECT_EQ(xrReleaseSwapchainImage(swapchain, nullptr), XR_ERROR_CALL_ORDER_INVALID);
    uint32_t index = 99;
    ASSERT_EQ(xrAcquireSwapchainImage(swapchain, nullptr, &index), XR_SUCCESS);
    EXPECT_EQ(index, 0u);
    EXPECT_EQ(xrReleaseSwapchainImage(swapchain, nullptr), XR_ERROR_CALL_ORDER_INVALID);
    ASSERT_EQ(xrAcquireSwapchainImage(swapchain, nullptr, &index), XR_SUCCESS);
    ASSERT_EQ(xrAcquireSwapchainImage(swapchain, nullptr, &index), XR_SUCCESS);
    EXPECT_EQ(index, 2u);
    // All three are acquired: none is left.
    EXPECT_EQ(xrAcquireSwapchainImage(swapchain, nullptr, &index), XR_ERROR_CALL_ORDER_INVALID);
    ASSERT_EQ(xrWaitSwapchainImage(swapchain, &wait), XR_SUCCESS);
    // Only one image may be waited at a time.
    EXPECT_EQ(xrWaitSwapchainImage(swapchain, &wait), XR_ERROR_CALL_ORDER_INVALID);
    EXPECT_EQ(xrReleaseSwapchainImage(swapchain, nullptr), XR_SUCCESS);
    EXPECT_EQ(xrDestroySwapchain(swapchain), XR_SUCCESS);
    EXPECT_EQ(xrDestroySwapchain(swapchain), XR_ERROR_HANDLE_INVALID);
}

// spec (XrSwapchainCreateFlagBits, xrAcquireSwapchainImage): a static swapchain is acquired
// and released once over its whole life; a second acquire is XR_ERROR_CALL_ORDER_INVALID.
TEST_F(SimxrTest, StaticSwapchainHasOneImageAcquiredOnce) {
    start("");
    const XrSwapchain swapchain = make_swapchain(session_, VK_FORMAT_R8G8B8A8_SRGB, 64, 64,
                                                 XR_SWAPCHAIN_CREATE_STATIC_IMAGE_BIT);
    uint32_t count = 0;
    ASSERT_EQ(xrEnumerateSwapchainImages(swapchain, 0, &count, nullptr), XR_SUCCESS);
    EXPECT_EQ(count, 1u);
    uint32_t index = 99;
    ASSERT_EQ(xrAcquireSwapchainImage(swapchain, nullptr, &index), XR_SUCCESS);
    EXPECT_EQ(index, 0u);
    auto wait = xr_struct<XrSwapchainImageWaitInfo>(XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
    wait.timeout = XR_INFINITE_DURATION;
    ASSERT_EQ(xrWaitSwapchainImage(swapchain, &wait), XR_SUCCESS);
    ASSERT_EQ(xrReleaseSwapchainImage(swapchain, nullptr), XR_SUCCESS);
    EXPECT_EQ(xrAcquireSwapchainImage(swapchain, nullptr, &index), XR_ERROR_CALL_ORDER_INVALID);
    // The other swapchains keep their three images, acquired round-robin.
    const XrSwapchain dynamic = make_swapchain(session_, VK_FORMAT_R8G8B8A8_SRGB, 64, 64);
    ASSERT_EQ(xrEnumerateSwapchainImages(dynamic, 0, &count, nullptr), XR_SUCCESS);
    EXPECT_EQ(count, 3u);
}

TEST_F(SimxrTest, UnsupportedSwapchainFormatIsRefused) {
    start("");
    uint32_t count = 0;
    ASSERT_EQ(xrEnumerateSwapchainFormats(session_, 0, &count, nullptr), XR_SUCCESS);
    std::vector<int64_t> formats(count);
    ASSERT_EQ(xrEnumerateSwapchainFormats(session_, count, &count, formats.data()), XR_SUCCESS);
    EXPECT_EQ(formats, (std::vector<int64_t>{VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_B8G8R8A8_SRGB,
                                             VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_D32_SFLOAT}));
    auto info = xr_struct<XrSwapchainCreateInfo>(XR_TYPE_SWAPCHAIN_CREATE_INFO);
    info.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT;
    info.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    info.sampleCount = 1;
    info.width = info.height = 64;
    info.faceCount = info.arraySize = info.mipCount = 1;
    XrSwapchain swapchain = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateSwapchain(session_, &info, &swapchain),
              XR_ERROR_SWAPCHAIN_FORMAT_UNSUPPORTED);
}

TEST_F(SimxrTest, LayerWithAnUnreleasedSwapchainIsInvalid) {
    start("");
    begin_and_focus();
    const XrSwapchain swapchain = make_swapchain(session_, VK_FORMAT_R8G8B8A8_SRGB, 64, 64);
    auto space_info = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    space_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    space_info.poseInReferenceSpace.orientation.w = 1.0f;
    XrSpace local = XR_NULL_HANDLE;
    ASSERT_EQ(xrCreateReferenceSpace(session_, &space_info, &local), XR_SUCCESS);
    auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    ASSERT_EQ(xrWaitFrame(session_, nullptr, &state), XR_SUCCESS);
    ASSERT_EQ(xrBeginFrame(session_, nullptr), XR_SUCCESS);
    uint32_t index = 0;
    ASSERT_EQ(xrAcquireSwapchainImage(swapchain, nullptr, &index), XR_SUCCESS);
    XrCompositionLayerProjectionView views[2];
    for (auto& view : views) {
        view =
            xr_struct<XrCompositionLayerProjectionView>(XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW);
        view.pose.orientation.w = 1.0f;
        view.subImage.swapchain = swapchain;
        view.subImage.imageRect = {{0, 0}, {64, 64}};
    }
    auto layer = xr_struct<XrCompositionLayerProjection>(XR_TYPE_COMPOSITION_LAYER_PROJECTION);
    layer.space = local;
    layer.viewCount = 2;
    layer.views = views;
    const auto* layers = reinterpret_cast<const XrCompositionLayerBaseHeader*>(&layer);
    auto end = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
    end.displayTime = state.predictedDisplayTime;
    end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
    end.layerCount = 1;
    end.layers = &layers;
    EXPECT_EQ(xrEndFrame(session_, &end), XR_ERROR_LAYER_INVALID);
    auto wait = xr_struct<XrSwapchainImageWaitInfo>(XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
    ASSERT_EQ(xrWaitSwapchainImage(swapchain, &wait), XR_SUCCESS);
    ASSERT_EQ(xrReleaseSwapchainImage(swapchain, nullptr), XR_SUCCESS);
    views[1].subImage.imageRect = {{32, 0}, {64, 64}};  // sticks out of the image
    EXPECT_EQ(xrEndFrame(session_, &end), XR_ERROR_SWAPCHAIN_RECT_INVALID);
    views[1].subImage.imageRect = {{0, 0}, {64, 64}};
    EXPECT_EQ(xrEndFrame(session_, &end), XR_SUCCESS);
}

// spec (XrPosef): a runtime must return XR_ERROR_POSE_INVALID if the orientation norm deviates
// by more than 1% from unit length; OpenXR-CTS submits a projection view of norm 0.2 and a quad
// of norm 0.98.
TEST_F(SimxrTest, LayerPosesMustBeUnitQuaternions) {
    start("");
    begin_and_focus();
    const XrSwapchain swapchain = make_swapchain(session_, VK_FORMAT_R8G8B8A8_SRGB, 64, 64);
    uint32_t index = 0;
    ASSERT_EQ(xrAcquireSwapchainImage(swapchain, nullptr, &index), XR_SUCCESS);
    auto wait = xr_struct<XrSwapchainImageWaitInfo>(XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
    wait.timeout = XR_INFINITE_DURATION;
    ASSERT_EQ(xrWaitSwapchainImage(swapchain, &wait), XR_SUCCESS);
    ASSERT_EQ(xrReleaseSwapchainImage(swapchain, nullptr), XR_SUCCESS);
    auto space_info = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    space_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    space_info.poseInReferenceSpace.orientation.w = 1.0f;
    XrSpace local = XR_NULL_HANDLE;
    ASSERT_EQ(xrCreateReferenceSpace(session_, &space_info, &local), XR_SUCCESS);

    XrCompositionLayerProjectionView views[2];
    for (auto& view : views) {
        view =
            xr_struct<XrCompositionLayerProjectionView>(XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW);
        view.pose.orientation.w = 1.0f;
        view.fov = {-0.5f, 0.5f, 0.5f, -0.5f};
        view.subImage.swapchain = swapchain;
        view.subImage.imageRect = {{0, 0}, {64, 64}};
    }
    auto projection = xr_struct<XrCompositionLayerProjection>(XR_TYPE_COMPOSITION_LAYER_PROJECTION);
    projection.space = local;
    projection.viewCount = 2;
    projection.views = views;
    auto quad = xr_struct<XrCompositionLayerQuad>(XR_TYPE_COMPOSITION_LAYER_QUAD);
    quad.space = local;
    quad.eyeVisibility = XR_EYE_VISIBILITY_BOTH;
    quad.subImage = views[0].subImage;
    quad.pose = {{0.0f, 0.0f, 0.0f, 1.0f}, {0.0f, 0.0f, -1.0f}};
    quad.size = {1.0f, 1.0f};
    auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
    const auto submit = [&](const void* layer) {
        const auto* header = static_cast<const XrCompositionLayerBaseHeader*>(layer);
        auto end = xr_struct<XrFrameEndInfo>(XR_TYPE_FRAME_END_INFO);
        end.displayTime = state.predictedDisplayTime;
        end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
        end.layerCount = 1;
        end.layers = &header;
        return xrEndFrame(session_, &end);
    };
    ASSERT_EQ(xrWaitFrame(session_, nullptr, &state), XR_SUCCESS);
    ASSERT_EQ(xrBeginFrame(session_, nullptr), XR_SUCCESS);
    views[1].pose.orientation = {0.1f, 0.1f, 0.1f, 0.1f};  // norm 0.2
    EXPECT_EQ(submit(&projection), XR_ERROR_POSE_INVALID);
    views[1].pose.orientation = {0.0f, 0.0f, 0.0f, 0.0f};
    EXPECT_EQ(submit(&projection), XR_ERROR_POSE_INVALID);
    views[1].pose.orientation = {0.0f, 0.0f, 0.0f, std::nanf("")};
    EXPECT_EQ(submit(&projection), XR_ERROR_POSE_INVALID);
    quad.pose.orientation = {0.0f, 0.0f, 0.0f, 0.98f};  // 2 % short
    EXPECT_EQ(submit(&quad), XR_ERROR_POSE_INVALID);
    quad.pose.orientation = {0.0f, 0.0f, 0.0f, 1.005f};  // within 1 %: accepted
    EXPECT_EQ(submit(&quad), XR_SUCCESS);
    ASSERT_EQ(xrWaitFrame(session_, nullptr, &state), XR_SUCCESS);
    ASSERT_EQ(xrBeginFrame(session_, nullptr), XR_SUCCESS);
    views[1].pose.orientation = {0.0f, 0.70710678f, 0.0f, 0.70710678f};  // turned 90 degrees
    EXPECT_EQ(submit(&projection), XR_SUCCESS);
}

XrResult create_set(XrInstance instance, const char* name, const char* localized,
                    XrActionSet* set) {
    auto info = xr_struct<XrActionSetCreateInfo>(XR_TYPE_ACTION_SET_CREATE_INFO);
    std::snprintf(info.actionSetName, sizeof(info.actionSetName), "%s", name);
    std::snprintf(info.localizedActionSetName, sizeof(info.localizedActionSetName), "%s",
                  localized);
    return xrCreateActionSet(instance, &info, set);
}

XrResult create_action(XrActionSet set, const char* name, const char* localized,
                       const std::vector<XrPath>& subaction_paths, XrAction* action) {
    auto info = xr_struct<XrActionCreateInfo>(XR_TYPE_ACTION_CREATE_INFO);
    info.actionType = XR_ACTION_TYPE_BOOLEAN_INPUT;
    std::snprintf(info.actionName, sizeof(info.actionName), "%s", name);
    std::snprintf(info.localizedActionName, sizeof(info.localizedActionName), "%s", localized);
    info.countSubactionPaths = static_cast<uint32_t>(subaction_paths.size());
    info.subactionPaths = subaction_paths.empty() ? nullptr : subaction_paths.data();
    return xrCreateAction(set, &info, action);
}

// spec 11.2 and 11.3: localized names are unique among the instance's action sets and among
// one set's actions; destroying the holder frees the name.
TEST_F(SimxrTest, LocalizedNamesMustBeUnique) {
    start("", {.create_session = false});
    XrActionSet study = XR_NULL_HANDLE;
    XrActionSet other = XR_NULL_HANDLE;
    ASSERT_EQ(create_set(instance_, "study", "Study", &study), XR_SUCCESS);
    EXPECT_EQ(create_set(instance_, "study2", "Study", &other), XR_ERROR_LOCALIZED_NAME_DUPLICATED);
    EXPECT_EQ(create_set(instance_, "study", "Study 2", &other), XR_ERROR_NAME_DUPLICATED);
    ASSERT_EQ(create_set(instance_, "menu", "Menu", &other), XR_SUCCESS);

    XrAction select = XR_NULL_HANDLE;
    XrAction action = XR_NULL_HANDLE;
    ASSERT_EQ(create_action(study, "select", "Select", {}, &select), XR_SUCCESS);
    EXPECT_EQ(create_action(study, "choose", "Select", {}, &action),
              XR_ERROR_LOCALIZED_NAME_DUPLICATED);
    // Another set's actions are another name space.
    EXPECT_EQ(create_action(other, "choose", "Select", {}, &action), XR_SUCCESS);
    ASSERT_EQ(xrDestroyAction(select), XR_SUCCESS);
    EXPECT_EQ(create_action(study, "choose", "Select", {}, &action), XR_SUCCESS);

    ASSERT_EQ(xrDestroyActionSet(study), XR_SUCCESS);
    EXPECT_EQ(create_set(instance_, "study2", "Study", &study), XR_SUCCESS);
    EXPECT_EQ(create_set(instance_, "study3", "Menu", &study), XR_ERROR_LOCALIZED_NAME_DUPLICATED);
}

// Each call's code for a subaction path: xrCreateAction refuses a path that is not a top level
// user path, or listed twice, with XR_ERROR_PATH_UNSUPPORTED (spec 11.3); a value that is no
// path atom at all is XR_ERROR_PATH_INVALID everywhere (OpenXR-CTS passes 0x1234); a path the
// action (xrGetActionState*, haptics) or no action of the set (xrSyncActions) was created with
// is XR_ERROR_PATH_UNSUPPORTED.
TEST_F(SimxrTest, SubactionPathsGetEachCallsCode) {
    start("", {.xr_validation = false});  // simxr's own answers, behind the layer's checks
    const XrPath left = path("/user/hand/left");
    const XrPath gamepad = path("/user/gamepad");
    const XrPath not_an_atom = 0x1234;
    XrActionSet set = XR_NULL_HANDLE;
    ASSERT_EQ(create_set(instance_, "study", "Study", &set), XR_SUCCESS);
    XrAction action = XR_NULL_HANDLE;
    EXPECT_EQ(create_action(set, "a", "A", {path("/user/hand/left/input")}, &action),
              XR_ERROR_PATH_UNSUPPORTED);
    EXPECT_EQ(create_action(set, "a", "A", {path("/user/invalid")}, &action),
              XR_ERROR_PATH_UNSUPPORTED);
    EXPECT_EQ(create_action(set, "a", "A", {left, left}, &action), XR_ERROR_PATH_UNSUPPORTED);
    EXPECT_EQ(create_action(set, "a", "A", {not_an_atom}, &action), XR_ERROR_PATH_INVALID);
    ASSERT_EQ(create_action(set, "press", "Press", {left}, &action), XR_SUCCESS);
    auto vibrate = xr_struct<XrActionCreateInfo>(XR_TYPE_ACTION_CREATE_INFO);
    vibrate.actionType = XR_ACTION_TYPE_VIBRATION_OUTPUT;
    std::snprintf(vibrate.actionName, sizeof(vibrate.actionName), "buzz");
    std::snprintf(vibrate.localizedActionName, sizeof(vibrate.localizedActionName), "Buzz");
    vibrate.countSubactionPaths = 1;
    vibrate.subactionPaths = &left;
    XrAction buzz = XR_NULL_HANDLE;
    ASSERT_EQ(xrCreateAction(set, &vibrate, &buzz), XR_SUCCESS);
    auto attach = xr_struct<XrSessionActionSetsAttachInfo>(XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO);
    attach.countActionSets = 1;
    attach.actionSets = &set;
    ASSERT_EQ(xrAttachSessionActionSets(session_, &attach), XR_SUCCESS);

    auto get = xr_struct<XrActionStateGetInfo>(XR_TYPE_ACTION_STATE_GET_INFO);
    get.action = action;
    auto state = xr_struct<XrActionStateBoolean>(XR_TYPE_ACTION_STATE_BOOLEAN);
    get.subactionPath = not_an_atom;
    EXPECT_EQ(xrGetActionStateBoolean(session_, &get, &state), XR_ERROR_PATH_INVALID);
    get.subactionPath = gamepad;
    EXPECT_EQ(xrGetActionStateBoolean(session_, &get, &state), XR_ERROR_PATH_UNSUPPORTED);
    get.subactionPath = left;
    EXPECT_EQ(xrGetActionStateBoolean(session_, &get, &state), XR_SUCCESS);

    auto haptic = xr_struct<XrHapticActionInfo>(XR_TYPE_HAPTIC_ACTION_INFO);
    haptic.action = buzz;
    haptic.subactionPath = not_an_atom;
    auto vibration = xr_struct<XrHapticVibration>(XR_TYPE_HAPTIC_VIBRATION);
    vibration.duration = XR_MIN_HAPTIC_DURATION;
    const auto* feedback = reinterpret_cast<const XrHapticBaseHeader*>(&vibration);
    EXPECT_EQ(xrApplyHapticFeedback(session_, &haptic, feedback), XR_ERROR_PATH_INVALID);
    EXPECT_EQ(xrStopHapticFeedback(session_, &haptic), XR_ERROR_PATH_INVALID);

    XrActiveActionSet active{set, not_an_atom};
    auto sync = xr_struct<XrActionsSyncInfo>(XR_TYPE_ACTIONS_SYNC_INFO);
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    EXPECT_EQ(xrSyncActions(session_, &sync), XR_ERROR_PATH_INVALID);
    active.subactionPath = gamepad;  // a top level user path, but none of the set's actions has it
    EXPECT_EQ(xrSyncActions(session_, &sync), XR_ERROR_PATH_UNSUPPORTED);
    active.subactionPath = left;
    EXPECT_EQ(xrSyncActions(session_, &sync), XR_SESSION_NOT_FOCUSED);
}

// spec (xrGetSystem): a form factor the runtime does not have is
// XR_ERROR_FORM_FACTOR_UNSUPPORTED, whatever the value (OpenXR-CTS passes
// XR_FORM_FACTOR_MAX_ENUM).
TEST_F(SimxrTest, EveryFormFactorButTheHmdIsUnsupported) {
    start("", {.create_session = false, .xr_validation = false});  // the layer refuses MAX_ENUM
    auto info = xr_struct<XrSystemGetInfo>(XR_TYPE_SYSTEM_GET_INFO);
    for (XrFormFactor form : {XR_FORM_FACTOR_HANDHELD_DISPLAY, XR_FORM_FACTOR_MAX_ENUM,
                              static_cast<XrFormFactor>(12345)}) {
        info.formFactor = form;
        XrSystemId system = 42;
        EXPECT_EQ(xrGetSystem(instance_, &info, &system), XR_ERROR_FORM_FACTOR_UNSUPPORTED) << form;
        EXPECT_EQ(system, 42u) << form;  // untouched
    }
    info.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
    XrSystemId system = XR_NULL_SYSTEM_ID;
    EXPECT_EQ(xrGetSystem(instance_, &info, &system), XR_SUCCESS);
    EXPECT_EQ(system, system_);
}

TEST_F(SimxrTest, BindingsMustNameKnownProfilesAndComponents) {
    start("");
    auto set_info = xr_struct<XrActionSetCreateInfo>(XR_TYPE_ACTION_SET_CREATE_INFO);
    std::snprintf(set_info.actionSetName, sizeof(set_info.actionSetName), "study");
    std::snprintf(set_info.localizedActionSetName, sizeof(set_info.localizedActionSetName),
                  "Study");
    XrActionSet set = XR_NULL_HANDLE;
    ASSERT_EQ(xrCreateActionSet(instance_, &set_info, &set), XR_SUCCESS);
    auto action_info = xr_struct<XrActionCreateInfo>(XR_TYPE_ACTION_CREATE_INFO);
    action_info.actionType = XR_ACTION_TYPE_BOOLEAN_INPUT;
    std::snprintf(action_info.actionName, sizeof(action_info.actionName), "switch");
    std::snprintf(action_info.localizedActionName, sizeof(action_info.localizedActionName),
                  "Switch");
    XrAction action = XR_NULL_HANDLE;
    ASSERT_EQ(xrCreateAction(set, &action_info, &action), XR_SUCCESS);

    XrActionSuggestedBinding binding{action, path("/user/hand/right/input/select/click")};
    auto suggested = xr_struct<XrInteractionProfileSuggestedBinding>(
        XR_TYPE_INTERACTION_PROFILE_SUGGESTED_BINDING);
    suggested.interactionProfile = path("/interaction_profiles/acme/stick");
    suggested.countSuggestedBindings = 1;
    suggested.suggestedBindings = &binding;
    EXPECT_EQ(xrSuggestInteractionProfileBindings(instance_, &suggested),
              XR_ERROR_PATH_UNSUPPORTED);
    suggested.interactionProfile = path("/interaction_profiles/khr/simple_controller");
    binding.binding = path("/user/hand/right/input/trigger/click");
    EXPECT_EQ(xrSuggestInteractionProfileBindings(instance_, &suggested),
              XR_ERROR_PATH_UNSUPPORTED);
    binding.binding = path("/user/hand/right/input/select/click");
    EXPECT_EQ(xrSuggestInteractionProfileBindings(instance_, &suggested), XR_SUCCESS);

    auto attach = xr_struct<XrSessionActionSetsAttachInfo>(XR_TYPE_SESSION_ACTION_SETS_ATTACH_INFO);
    attach.countActionSets = 1;
    attach.actionSets = &set;
    ASSERT_EQ(xrAttachSessionActionSets(session_, &attach), XR_SUCCESS);
    EXPECT_EQ(xrSuggestInteractionProfileBindings(instance_, &suggested),
              XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);
    EXPECT_EQ(xrAttachSessionActionSets(session_, &attach), XR_ERROR_ACTIONSETS_ALREADY_ATTACHED);

    // Not focused yet (READY): syncing succeeds but says so.
    XrActiveActionSet active{set, XR_NULL_PATH};
    auto sync = xr_struct<XrActionsSyncInfo>(XR_TYPE_ACTIONS_SYNC_INFO);
    sync.countActiveActionSets = 1;
    sync.activeActionSets = &active;
    EXPECT_EQ(xrSyncActions(session_, &sync), XR_SESSION_NOT_FOCUSED);
    auto get = xr_struct<XrActionStateGetInfo>(XR_TYPE_ACTION_STATE_GET_INFO);
    get.action = action;
    auto value = xr_struct<XrActionStateBoolean>(XR_TYPE_ACTION_STATE_BOOLEAN);
    ASSERT_EQ(xrGetActionStateBoolean(session_, &get, &value), XR_SUCCESS);
    EXPECT_FALSE(value.isActive);
    auto float_value = xr_struct<XrActionStateFloat>(XR_TYPE_ACTION_STATE_FLOAT);
    EXPECT_EQ(xrGetActionStateFloat(session_, &get, &float_value), XR_ERROR_ACTION_TYPE_MISMATCH);
}

TEST_F(SimxrTest, HandlesAndStructureTypesAreChecked) {
    start("", {.xr_validation = false});  // simxr's own checks, behind the layer's

    const XrSessionBeginInfo info = begin_info();
    EXPECT_EQ(xrBeginSession(reinterpret_cast<XrSession>(uintptr_t{0xdead}), &info),
              XR_ERROR_HANDLE_INVALID);
    auto wrong = xr_struct<XrSessionBeginInfo>(XR_TYPE_FRAME_BEGIN_INFO);
    wrong.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
    poll_states();
    EXPECT_EQ(xrBeginSession(session_, &wrong), XR_ERROR_VALIDATION_FAILURE);
    auto system_info = xr_struct<XrSystemGetInfo>(XR_TYPE_SYSTEM_GET_INFO);
    system_info.formFactor = XR_FORM_FACTOR_HANDHELD_DISPLAY;
    XrSystemId system = XR_NULL_SYSTEM_ID;
    EXPECT_EQ(xrGetSystem(instance_, &system_info, &system), XR_ERROR_FORM_FACTOR_UNSUPPORTED);
    PFN_xrVoidFunction function = nullptr;
    EXPECT_EQ(xrGetInstanceProcAddr(instance_, "xrNoSuchFunction", &function),
              XR_ERROR_FUNCTION_UNSUPPORTED);
    EXPECT_EQ(function, nullptr);
}

// Without the fixture: instance creation itself.
TEST(SimxrInstance, RefusesUnknownExtensionsAndBadScripts) {
    const auto dir = std::filesystem::temp_directory_path() / "simxr_instance_test";
    XrInstance instance = XR_NULL_HANDLE;
    EXPECT_EQ(create_instance_with_script(dir, "", {"XR_KHR_no_such_extension"}, &instance),
              XR_ERROR_EXTENSION_NOT_PRESENT);
    // A script error fails xrCreateInstance (and names file, line and key on stderr).
    ::testing::internal::CaptureStderr();
    EXPECT_EQ(create_instance_with_script(dir, "display_rate_hz = -5\n", {}, &instance),
              XR_ERROR_RUNTIME_FAILURE);
    const std::string printed = ::testing::internal::GetCapturedStderr();
    EXPECT_NE(printed.find("script.toml:1:"), std::string::npos) << printed;
    EXPECT_NE(printed.find("display_rate_hz"), std::string::npos) << printed;
    ASSERT_EQ(create_instance_with_script(dir, "", {}, &instance), XR_SUCCESS);
    auto properties = xr_struct<XrInstanceProperties>(XR_TYPE_INSTANCE_PROPERTIES);
    ASSERT_EQ(xrGetInstanceProperties(instance, &properties), XR_SUCCESS);
    EXPECT_STREQ(properties.runtimeName, "monoplane simxr");
    EXPECT_EQ(xrDestroyInstance(instance), XR_SUCCESS);
    std::filesystem::remove_all(dir);
}

// The OpenXR core validation layer is really in the chain of every other test here: a misuse
// it must catch (a structure of the wrong type, and an enum value outside XrReferenceSpaceType)
// reaches the messenger with the spec's VUIDs, and the runtime is not called.
TEST_F(SimxrTest, TheOpenXrValidationLayerReportsMisuse) {
    start("");
    ASSERT_TRUE(xr_validation_messages().empty());
    auto wrong = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_SESSION_BEGIN_INFO);
    wrong.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    wrong.poseInReferenceSpace.orientation.w = 1.0f;
    XrSpace space = XR_NULL_HANDLE;
    EXPECT_EQ(xrCreateReferenceSpace(session_, &wrong, &space), XR_ERROR_VALIDATION_FAILURE);
    auto unknown_type = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    unknown_type.referenceSpaceType = static_cast<XrReferenceSpaceType>(12345);
    unknown_type.poseInReferenceSpace.orientation.w = 1.0f;
    EXPECT_EQ(xrCreateReferenceSpace(session_, &unknown_type, &space), XR_ERROR_VALIDATION_FAILURE);
    EXPECT_EQ(space, XR_NULL_HANDLE);
    const std::vector<std::string> seen = xr_validation_messages();
    const auto mentions = [&](const std::string& vuid) {
        return std::any_of(seen.begin(), seen.end(),
                           [&](const std::string& message) { return message.starts_with(vuid); });
    };
    EXPECT_TRUE(mentions("VUID-XrReferenceSpaceCreateInfo-type-type"));
    EXPECT_TRUE(mentions("VUID-XrReferenceSpaceCreateInfo-referenceSpaceType-parameter"));
    // Expected here, so they must not fail the test in TearDown.
    xr_validation_messages().clear();
}

}  // namespace
}  // namespace monoplane::simxr::testing
