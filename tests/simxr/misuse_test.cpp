// The spec's error codes for application mistakes, one test per rule (docs/simxr.md).
#include "tests/simxr/runtime_fixture.h"

#include <algorithm>

namespace monoplane::simxr::testing {
namespace {

XrSwapchain make_swapchain(XrSession session, int64_t format, uint32_t width, uint32_t height) {
    auto info = xr_struct<XrSwapchainCreateInfo>(XR_TYPE_SWAPCHAIN_CREATE_INFO);
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
    end.displayTime = state.predictedDisplayTime + 1;
    EXPECT_EQ(xrEndFrame(session_, &end), XR_ERROR_TIME_INVALID);
    end.displayTime = state.predictedDisplayTime;
    EXPECT_EQ(xrEndFrame(session_, &end), XR_SUCCESS);
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
