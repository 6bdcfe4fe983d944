// The eye depth writer (app/headset/eye_depth_writer.h) on a GPU, validation on: window depths
// written into a D32_SFLOAT image like a depth swapchain's, decoded as the layer's
// XrCompositionLayerDepthInfoKHR says (minDepth 0, maxDepth 1, nearZ = +inf, farZ = near:
// distance = near / d), against distances worked out by hand for known linear depths, for a
// parallel and a canted eye; and behind a real renderer in each configuration whose passes leave
// its linear depth in another layout, against the same renderer's depth read back.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include <glm/gtc/quaternion.hpp>

#include "app/headset/eye_depth_writer.h"
#include "hmd/profile.h"
#include "renderer/passes/shared/view_constants.h"
#include "renderer/vk/buffer.h"
#include "scenes/generate.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane::headset {
namespace {

using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;
constexpr vk::ImageLayout kAttachment = vk::ImageLayout::eDepthStencilAttachmentOptimal;
constexpr double kNear = 0.1;

class EyeDepthWriterTest : public testing::GpuTest {
  protected:
    // A depth target like a depth swapchain image: in DEPTH_STENCIL_ATTACHMENT_OPTIMAL.
    vk_core::Image make_target(vk::Extent2D extent) {
        vk_core::Image target(ctx(), {extent, vk::Format::eD32Sfloat,
                                      vk::ImageUsageFlagBits::eDepthStencilAttachment |
                                          vk::ImageUsageFlagBits::eTransferSrc});
        ctx().submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
            vk_core::transition(cmd, target, vk::ImageLayout::eUndefined, kAttachment, Stage::eNone,
                                Access::eNone, Stage::eEarlyFragmentTests,
                                Access::eDepthStencilAttachmentWrite);
        });
        return target;
    }

    // Linear depths (row by row, top first) in an R32_SFLOAT image left in `layout`.
    vk_core::Image make_source(vk::Extent2D extent, const std::vector<float>& depths,
                               vk::ImageLayout layout) {
        vk_core::Image source(
            ctx(),
            {extent, passes::ForwardPass::kLinearDepthFormat,
             vk::ImageUsageFlagBits::eTransferDst | vk::ImageUsageFlagBits::eTransferSrc |
                 vk::ImageUsageFlagBits::eSampled | vk::ImageUsageFlagBits::eColorAttachment});
        const vk_core::Buffer staging(ctx(), depths.size() * sizeof(float),
                                      vk::BufferUsageFlagBits::eTransferSrc,
                                      vk_core::MemoryUse::kHostVisible);
        staging.write(depths.data(), depths.size() * sizeof(float));
        ctx().submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
            vk_core::transition(cmd, source, vk::ImageLayout::eUndefined,
                                vk::ImageLayout::eTransferDstOptimal, Stage::eNone, Access::eNone,
                                Stage::eTransfer, Access::eTransferWrite);
            cmd.copyBufferToImage(
                staging.handle(), source.handle(), vk::ImageLayout::eTransferDstOptimal,
                vk::BufferImageCopy(
                    0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                    {0, 0, 0}, vk::Extent3D(extent, 1)));
            vk_core::transition(cmd, source, vk::ImageLayout::eTransferDstOptimal, layout,
                                Stage::eTransfer, Access::eTransferWrite, Stage::eAllCommands,
                                Access::eMemoryRead);
        });
        return source;
    }

    // An image's texels as floats, copied out of `layout` and left in it.
    std::vector<float> read(const vk_core::Image& image, vk::ImageLayout layout) {
        const vk::Extent2D extent = image.desc().extent;
        const vk_core::Buffer buffer(ctx(), vk::DeviceSize{extent.width} * extent.height * 4,
                                     vk::BufferUsageFlagBits::eTransferDst,
                                     vk_core::MemoryUse::kHostVisible);
        ctx().submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
            vk_core::transition(cmd, image, layout, vk::ImageLayout::eTransferSrcOptimal,
                                Stage::eAllCommands, Access::eMemoryWrite, Stage::eTransfer,
                                Access::eTransferRead);
            cmd.copyImageToBuffer(
                image.handle(), vk::ImageLayout::eTransferSrcOptimal, buffer.handle(),
                vk::BufferImageCopy(0, 0, 0, vk::ImageSubresourceLayers(image.aspect(), 0, 0, 1),
                                    {0, 0, 0}, vk::Extent3D(extent, 1)));
            vk_core::transition(cmd, image, vk::ImageLayout::eTransferSrcOptimal, layout,
                                Stage::eTransfer, Access::eNone, Stage::eAllCommands,
                                Access::eNone);
        });
        const auto* values = reinterpret_cast<const float*>(buffer.mapped());
        return {values, values + std::size_t{extent.width} * extent.height};
    }
};

// The layer's decoding: t = (d - minDepth) / (maxDepth - minDepth) = d, and
// 1 / distance = (1 - t) / nearZ + t / farZ = d / near.
double decoded(float window_depth) {
    return window_depth > 0.0f ? kNear / window_depth : std::numeric_limits<double>::infinity();
}

rig::Tangents tangents(double left, double right, double up, double down) {
    rig::Tangents t;
    t.left = left;
    t.right = right;
    t.up = up;
    t.down = down;
    return t;
}

TEST_F(EyeDepthWriterTest, ParallelEyeGetsNearOverDistanceInEveryLayoutItLeavesAlone) {
    const vk::Extent2D extent(24, 16);
    // Depths by pixel: a ramp from 0.3 m, the sky in the top row, one pixel nearer than near.
    std::vector<float> depths(std::size_t{extent.width} * extent.height);
    for (std::uint32_t y = 0; y < extent.height; ++y) {
        for (std::uint32_t x = 0; x < extent.width; ++x) {
            depths[y * extent.width + x] = y == 0 ? static_cast<float>(MONOPLANE_SKY_LINEAR_DEPTH)
                                                  : 0.3f + 0.7f * x + 3.1f * y;
        }
    }
    depths[5 * extent.width + 7] = 0.04f;
    EyeDepthWriter writer(ctx(), vk::Format::eD32Sfloat);
    for (vk::ImageLayout layout :
         {vk::ImageLayout::eColorAttachmentOptimal, vk::ImageLayout::eShaderReadOnlyOptimal,
          vk::ImageLayout::eTransferSrcOptimal}) {
        SCOPED_TRACE(vk::to_string(layout));
        const vk_core::Image source = make_source(extent, depths, layout);
        const vk_core::Image target = make_target(extent);
        EyeDepthSource eye;
        eye.linear_depth = {&source, layout};
        eye.tangents = tangents(-1.2, 1.0, 0.9, -1.1);
        // An overlay in the lower right: infinity there.
        const std::vector<PixelRect> overlays = {{20, 12, 23, 15}};
        ctx().submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
            writer.record(cmd, target.handle(), extent, &eye, kNear, overlays);
        });
        const std::vector<float> written = read(target, kAttachment);
        // Read from the layout it was in: the writer put it back (validation would object).
        EXPECT_EQ(read(source, layout), depths);
        for (std::uint32_t y = 0; y < extent.height; ++y) {
            for (std::uint32_t x = 0; x < extent.width; ++x) {
                const std::size_t i = y * extent.width + x;
                const double distance = decoded(written[i]);
                if (y == 0 || (x >= 20 && x < 23 && y >= 12 && y < 15)) {
                    EXPECT_TRUE(std::isinf(distance)) << x << ", " << y;
                } else if (x == 7 && y == 5) {
                    EXPECT_EQ(written[i], 1.0f) << "nearer than near: clamped to the near plane";
                } else {
                    // Parallel eye: its axis is the head's, the distance is the plane depth.
                    EXPECT_NEAR(distance, depths[i], 1e-6 * depths[i]) << x << ", " << y;
                }
            }
        }
    }
}

// A wall parallel to the eyes' plane, D = 2 m in front of it, seen by an eye yawed by theta =
// 20 degrees to the left and 3 cm in front of the plane. In the head's
// frame the eye looks along f = (-sin theta, 0, -cos theta) with right axis
// r = (cos theta, 0, -sin theta); the pixel with tangents (tx, ty) looks along tx r + ty y + f,
// which gains tx sin theta + cos theta of the head's forward per metre along the eye's axis. So
// the wall lies s = (D - 0.03) / (cos theta + tx sin theta) along the eye's axis at that pixel.
TEST_F(EyeDepthWriterTest, CantedEyeMeasuresAlongItsOwnAxis) {
    const vk::Extent2D extent(40, 10);
    const double wall = 2.0, in_front = 0.03, theta = 20.0 * 3.14159265358979323846 / 180.0;
    const vk_core::Image source = make_source(
        extent, std::vector<float>(std::size_t{extent.width} * extent.height, float(wall)),
        vk::ImageLayout::eShaderReadOnlyOptimal);
    const vk_core::Image target = make_target(extent);
    EyeDepthWriter writer(ctx(), vk::Format::eD32Sfloat);
    EyeDepthSource eye;
    eye.linear_depth = {&source, vk::ImageLayout::eShaderReadOnlyOptimal};
    eye.tangents = tangents(-1.5, 1.0, 0.5, -0.5);
    // Head -> eye undoes the eye's yaw.
    eye.head_to_eye = glm::mat3_cast(glm::angleAxis(-theta, glm::dvec3(0.0, 1.0, 0.0)));
    eye.eye_in_front = in_front;
    ctx().submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        writer.record(cmd, target.handle(), extent, &eye, kNear, {});
    });
    const std::vector<float> written = read(target, kAttachment);
    for (std::uint32_t x = 0; x < extent.width; ++x) {
        const double tx = -1.5 + (x + 0.5) / extent.width * 2.5;
        const double expected = (wall - in_front) / (std::cos(theta) + tx * std::sin(theta));
        for (std::uint32_t y = 0; y < extent.height; ++y) {
            EXPECT_NEAR(decoded(written[y * extent.width + x]), expected, 2e-6 * expected)
                << x << ", " << y;
        }
    }
    // The parallel eye's value (the plane depth) would be off by several per cent at the edges.
    const double edge = (wall - in_front) / (std::cos(theta) - 1.46875 * std::sin(theta));
    EXPECT_GT(decoded(written[0]), 1.2 * wall);
    EXPECT_NEAR(decoded(written[0]), edge, 2e-6 * edge);
}

TEST_F(EyeDepthWriterTest, NoSourceIsInfinityEverywhere) {
    const vk::Extent2D extent(8, 8);
    const vk_core::Image target = make_target(extent);
    EyeDepthWriter writer(ctx(), vk::Format::eD32Sfloat);
    ctx().submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        writer.record(cmd, target.handle(), extent, nullptr, kNear, {{0, 0, 4, 4}});
    });
    for (float d : read(target, kAttachment)) EXPECT_EQ(d, 0.0f);
}

// Behind a renderer, in record_after as the headset records it: each configuration leaves the
// eye's linear depth in another layout (colour attachment; shader-readable after SSAO or TAA;
// TRANSFER_SRC after its own read-back) or in another image (MSAA's resolve, a layer of
// single-pass stereo's two-layer image). The written depth decodes to what a twin renderer reads
// back for the same frame. Multiview is skipped on llvmpipe: Debian 12's lavapipe drops view 1's
// sky and misroutes some of its fragments (tests/gpu/single_pass_stereo_test.cpp), so the right
// eye's linear depth, read back or written, holds zeros there.
struct RendererCase {
    const char* name;
    plan::Mode mode;
    plan::AntiAliasing aa;
    plan::StereoPass stereo_pass;
    bool ssao;
    bool read_back_depth;
};

class EyeDepthBehindRenderer : public EyeDepthWriterTest,
                               public ::testing::WithParamInterface<RendererCase> {};

TEST_P(EyeDepthBehindRenderer, WritesTheRenderersDepth) {
    const RendererCase& c = GetParam();
    if (c.stereo_pass == plan::StereoPass::kMultiview &&
        (!ctx().capabilities().multiview ||
         ctx().device_info().name.find("llvmpipe") != std::string::npos)) {
        GTEST_SKIP() << "multiview is missing or defective on " << ctx().device_info().name;
    }
    if (c.stereo_pass == plan::StereoPass::kGeometryShader &&
        !ctx().capabilities().geometry_shader) {
        GTEST_SKIP() << "the device has no geometry shader";
    }
    if (c.stereo_pass == plan::StereoPass::kInstanced &&
        !(ctx().capabilities().vertex_shader_layer &&
          ctx().capabilities().shader_draw_parameters)) {
        GTEST_SKIP() << "the device cannot write gl_Layer from a vertex shader";
    }
    const scenes::Scene scene =
        scenes::generate_scene(scenes::SceneId::Beams, scenes::Detail::Test, 5);
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    const vk::Extent2D extent(72, 80);
    modes::RendererOptions options;
    options.shadow.resolution = 512;
    options.anti_aliasing = c.aa;
    options.stereo_pass = c.stereo_pass;
    if (c.ssao) options.ssao = passes::SsaoVariant::kPerView;
    options.read_back = false;
    options.read_back_depth = c.read_back_depth;
    modes::ModeRenderer renderer(ctx(), scene, c.mode, extent, options);
    modes::RendererOptions twin_options = options;
    twin_options.read_back_depth = true;
    modes::ModeRenderer twin(ctx(), scene, c.mode, extent, twin_options);

    const modes::FrameInputs inputs =
        testing::profile_inputs(vive, scene.find_viewpoint("default")->head, 3.0);
    EyeDepthWriter writer(ctx(), vk::Format::eD32Sfloat);
    const std::array targets = {make_target(extent), make_target(extent)};
    // Two frames: the second follows a frame that already went through the writer.
    for (int frame = 0; frame < 2; ++frame) {
        renderer.render_frame(inputs, [&](const vk::raii::CommandBuffer& cmd) {
            for (int e = 0; e < 2; ++e) {
                EyeDepthSource eye;
                eye.linear_depth = renderer.eye_linear_depth_image(static_cast<modes::Eye>(e));
                eye.tangents = e == 0 ? vive.left : vive.right;
                writer.record(cmd, targets[e].handle(), extent, &eye, kNear, {});
            }
        });
        twin.render_frame(inputs);
    }
    for (int e = 0; e < 2; ++e) {
        const std::vector<float> written = read(targets[e], kAttachment);
        const std::vector<float>& linear = twin.eye_linear_depth(static_cast<modes::Eye>(e));
        ASSERT_EQ(written.size(), linear.size());
        std::size_t sky = 0;
        for (std::size_t i = 0; i < written.size(); ++i) {
            if (linear[i] >= static_cast<float>(MONOPLANE_SKY_LINEAR_DEPTH) * 0.1f) {
                ++sky;
                EXPECT_EQ(written[i], 0.0f) << "eye " << e << " pixel " << i;
            } else {
                EXPECT_NEAR(decoded(written[i]), linear[i], 1e-6 * linear[i])
                    << "eye " << e << " pixel " << i;
            }
        }
        // BEAMS from its viewpoint: sky above, structure and ground below.
        EXPECT_GT(sky, written.size() / 10);
        EXPECT_LT(sky, written.size() * 9 / 10);
    }
}

INSTANTIATE_TEST_SUITE_P(
    Configurations, EyeDepthBehindRenderer,
    ::testing::Values(
        RendererCase{"StereoPlain", plan::Mode::kStereo, plan::AntiAliasing::kNone,
                     plan::StereoPass::kTwoPasses, false, false},
        RendererCase{"HybridPlain", plan::Mode::kHybrid, plan::AntiAliasing::kNone,
                     plan::StereoPass::kTwoPasses, false, false},
        RendererCase{"HybridTaaSsao", plan::Mode::kHybrid, plan::AntiAliasing::kTaa,
                     plan::StereoPass::kTwoPasses, true, false},
        RendererCase{"HybridReadBack", plan::Mode::kHybrid, plan::AntiAliasing::kNone,
                     plan::StereoPass::kTwoPasses, false, true},
        RendererCase{"StereoMsaa4", plan::Mode::kStereo, plan::AntiAliasing::kMsaa4,
                     plan::StereoPass::kTwoPasses, false, false},
        RendererCase{"StereoMultiviewMsaa4", plan::Mode::kStereo, plan::AntiAliasing::kMsaa4,
                     plan::StereoPass::kMultiview, false, false},
        RendererCase{"StereoGsTaa", plan::Mode::kStereo, plan::AntiAliasing::kTaa,
                     plan::StereoPass::kGeometryShader, false, false},
        RendererCase{"StereoInstancedMsaa4", plan::Mode::kStereo, plan::AntiAliasing::kMsaa4,
                     plan::StereoPass::kInstanced, false, false}),
    [](const ::testing::TestParamInfo<RendererCase>& info) { return info.param.name; });

}  // namespace
}  // namespace monoplane::headset
