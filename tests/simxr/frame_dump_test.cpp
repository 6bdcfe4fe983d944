// Submitted frames are dumped to PNG with the colours the application rendered.
#include <stb_image.h>

#include "tests/simxr/runtime_fixture.h"

namespace monoplane::simxr::testing {
namespace {

struct EyeSwapchain {
    XrSwapchain swapchain = XR_NULL_HANDLE;
    std::vector<VkImage> images;
};

EyeSwapchain make_eye_swapchain(XrSession session, VkFormat format) {
    auto info = xr_struct<XrSwapchainCreateInfo>(XR_TYPE_SWAPCHAIN_CREATE_INFO);
    info.usageFlags = XR_SWAPCHAIN_USAGE_COLOR_ATTACHMENT_BIT | XR_SWAPCHAIN_USAGE_TRANSFER_DST_BIT;
    info.format = format;
    info.sampleCount = 1;
    info.width = 48;
    info.height = 32;
    info.faceCount = info.arraySize = info.mipCount = 1;
    EyeSwapchain eye;
    EXPECT_EQ(xrCreateSwapchain(session, &info, &eye.swapchain), XR_SUCCESS);
    uint32_t count = 0;
    EXPECT_EQ(xrEnumerateSwapchainImages(eye.swapchain, 0, &count, nullptr), XR_SUCCESS);
    std::vector<XrSwapchainImageVulkan2KHR> images(
        count, xr_struct<XrSwapchainImageVulkan2KHR>(XR_TYPE_SWAPCHAIN_IMAGE_VULKAN2_KHR));
    EXPECT_EQ(
        xrEnumerateSwapchainImages(eye.swapchain, count, &count,
                                   reinterpret_cast<XrSwapchainImageBaseHeader*>(images.data())),
        XR_SUCCESS);
    for (const auto& image : images) eye.images.push_back(image.image);
    return eye;
}

// The PNG's pixel at (x, y) as RGBA.
std::array<int, 4> pixel(const std::filesystem::path& file, int x, int y, int* width) {
    int height = 0;
    int channels = 0;
    unsigned char* data = stbi_load(file.c_str(), width, &height, &channels, 4);
    EXPECT_NE(data, nullptr) << file;
    if (data == nullptr) return {};
    const unsigned char* p = data + (static_cast<std::size_t>(y) * *width + x) * 4;
    std::array<int, 4> rgba{p[0], p[1], p[2], p[3]};
    stbi_image_free(data);
    return rgba;
}

TEST_F(SimxrTest, SubmittedEyesAreDumpedWithTheirColours) {
    start("dump_dir = \"dump\"\ndump_every = 2\n");
    begin_and_focus();  // frame 0
    auto space_info = xr_struct<XrReferenceSpaceCreateInfo>(XR_TYPE_REFERENCE_SPACE_CREATE_INFO);
    space_info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_LOCAL;
    space_info.poseInReferenceSpace.orientation.w = 1.0f;
    XrSpace local = XR_NULL_HANDLE;
    ASSERT_EQ(xrCreateReferenceSpace(session_, &space_info, &local), XR_SUCCESS);
    // Left: UNORM, stored as written. Right: BGRA sRGB, swizzled to RGBA in the file.
    EyeSwapchain eyes[2] = {make_eye_swapchain(session_, VK_FORMAT_R8G8B8A8_UNORM),
                            make_eye_swapchain(session_, VK_FORMAT_B8G8R8A8_SRGB)};
    const VkClearColorValue colours[2] = {{{0.2f, 0.4f, 0.6f, 1.0f}}, {{1.0f, 0.0f, 0.0f, 1.0f}}};

    for (int frame = 1; frame <= 2; ++frame) {
        auto state = xr_struct<XrFrameState>(XR_TYPE_FRAME_STATE);
        ASSERT_EQ(xrWaitFrame(session_, nullptr, &state), XR_SUCCESS);
        ASSERT_TRUE(state.shouldRender);
        ASSERT_EQ(xrBeginFrame(session_, nullptr), XR_SUCCESS);
        XrCompositionLayerProjectionView views[2];
        for (int eye = 0; eye < 2; ++eye) {
            uint32_t index = 0;
            ASSERT_EQ(xrAcquireSwapchainImage(eyes[eye].swapchain, nullptr, &index), XR_SUCCESS);
            auto wait = xr_struct<XrSwapchainImageWaitInfo>(XR_TYPE_SWAPCHAIN_IMAGE_WAIT_INFO);
            wait.timeout = XR_INFINITE_DURATION;
            ASSERT_EQ(xrWaitSwapchainImage(eyes[eye].swapchain, &wait), XR_SUCCESS);
            clear_image(eyes[eye].images[index], colours[eye]);
            ASSERT_EQ(xrReleaseSwapchainImage(eyes[eye].swapchain, nullptr), XR_SUCCESS);
            views[eye] = xr_struct<XrCompositionLayerProjectionView>(
                XR_TYPE_COMPOSITION_LAYER_PROJECTION_VIEW);
            views[eye].pose.orientation.w = 1.0f;
            views[eye].subImage.swapchain = eyes[eye].swapchain;
            views[eye].subImage.imageRect = {{8, 0}, {40, 32}};
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
        ASSERT_EQ(xrEndFrame(session_, &end), XR_SUCCESS);
    }
    // dump_every = 2: frame 2 is dumped, frame 1 is not.
    const std::filesystem::path dump = dir_ / "dump";
    EXPECT_FALSE(std::filesystem::exists(dump / "frame_000001_left.png"));
    ASSERT_TRUE(std::filesystem::exists(dump / "frame_000002_left.png"));
    ASSERT_TRUE(std::filesystem::exists(dump / "frame_000002_right.png"));
    int width = 0;
    const std::array<int, 4> left = pixel(dump / "frame_000002_left.png", 5, 7, &width);
    EXPECT_EQ(width, 40);  // the sub-image's rectangle
    EXPECT_NEAR(left[0], 51, 1);
    EXPECT_NEAR(left[1], 102, 1);
    EXPECT_NEAR(left[2], 153, 1);
    EXPECT_EQ(left[3], 255);
    const std::array<int, 4> right = pixel(dump / "frame_000002_right.png", 30, 20, &width);
    EXPECT_EQ(right, (std::array<int, 4>{255, 0, 0, 255}));
    for (const EyeSwapchain& eye : eyes) EXPECT_EQ(xrDestroySwapchain(eye.swapchain), XR_SUCCESS);
}

}  // namespace
}  // namespace monoplane::simxr::testing
