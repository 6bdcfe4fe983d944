// One full-screen pass per eye in hybrid (issue 33): where nothing but the tone mapping reads an
// eye's HDR image, the composite tone maps C's colour and the eye's own into the display image
// itself (renderer/plan/frame_plan.h, PlannedPass::writes_display). Its images must be those of
// the composite followed by the separate tone mapping (RendererOptions::separate_tonemap, the
// same renderer otherwise): within 1/255 per channel, and the linear depth bit for bit. Over the
// study scenes and their viewpoints, both hybrid modes and two mono planes, the debug views,
// single-pass near content, and frames whose C has nothing to draw, where the GPU skips the
// composite and the tone mapping alone writes the display image.
#include <gtest/gtest.h>

#include <array>
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "scenes/generate.h"
#include "tests/gpu/frame_checks.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/hybrid_test_scenes.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

using modes::Eye;
using plan::DebugView;
using plan::Mode;
using testing::max_channel_difference;

constexpr vk::Extent2D kExtent{96, 108};

modes::RendererOptions options_with(bool separate_tonemap) {
    modes::RendererOptions options;
    options.shadow.resolution = 256;
    options.read_back_depth = true;
    options.separate_tonemap = separate_tonemap;
    return options;
}

// The pixels (of all channels) that differ between two images.
std::size_t differing_channels(const modes::RgbaImage& a, const modes::RgbaImage& b) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < a.pixels.size() && i < b.pixels.size(); ++i) {
        count += a.pixels[i] != b.pixels[i] ? 1 : 0;
    }
    return count;
}

// Two renderers of one scene and mode, the one fusing the tone mapping into the composite and
// the one keeping it a pass of its own, fed the same frames.
class Pair {
  public:
    Pair(const vk_core::Context& ctx, const scenes::Scene& scene, Mode mode,
         modes::RendererOptions options = options_with(false))
        : fused_(ctx, scene, mode, kExtent, options), separate_(ctx, scene, mode, kExtent, [&] {
              options.separate_tonemap = true;
              return options;
          }()) {
        // llvmpipe stores half floats rounded toward zero, as the composite rounds C's colour
        // before tone mapping it (composite_body.glsl): there the images are the same bit for bit.
        exact_ = ctx.device_info().name.find("llvmpipe") != std::string::npos;
    }

    // Renders one frame with both; returns whether the fused renderer's plan fused both eyes.
    bool render(const modes::FrameInputs& inputs) {
        stats_ = fused_.render_frame(inputs);
        separate_.render_frame(inputs);
        bool fused = true;
        for (plan::ViewId eye : plan::kEyeViews) {
            const plan::PlannedPass* composite =
                fused_.last_plan().find(plan::PassKind::kComposite, eye);
            fused =
                fused && composite != nullptr && !composite->skipped && composite->writes_display;
            const plan::PlannedPass* reference =
                separate_.last_plan().find(plan::PassKind::kComposite, eye);
            EXPECT_TRUE(reference != nullptr && !reference->writes_display) << plan::view_name(eye);
        }
        return fused;
    }

    // The last frame's images within 1/255 per channel (equal on llvmpipe), the linear depth
    // identical.
    void expect_same_images(const std::string& context) const {
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            const std::string where = context + " " + modes::eye_name(eye);
            const modes::RgbaImage& a = fused_.eye_image(eye);
            const modes::RgbaImage& b = separate_.eye_image(eye);
            EXPECT_LE(max_channel_difference(a, b), 1) << where;
            if (exact_) {
                EXPECT_EQ(differing_channels(a, b), 0u) << where << " of " << a.pixels.size();
            }
            const std::vector<float>& da = fused_.eye_linear_depth(eye);
            const std::vector<float>& db = separate_.eye_linear_depth(eye);
            ASSERT_EQ(da.size(), db.size()) << where;
            EXPECT_EQ(std::memcmp(da.data(), db.data(), da.size() * sizeof(float)), 0) << where;
        }
    }

    modes::ModeRenderer& fused() { return fused_; }
    // The fused renderer's last frame.
    const profile::FrameStats& stats() const { return stats_; }

  private:
    modes::ModeRenderer fused_;
    modes::ModeRenderer separate_;
    profile::FrameStats stats_;
    bool exact_ = false;
};

class FusedComposite : public testing::GpuTest {
  protected:
    bool predicated() { return ctx().capabilities().conditional_rendering; }

    modes::FrameInputs inputs_at(const rig::Pose& head, double m) const {
        return testing::profile_inputs(vive_, head, m);
    }

    hmd::HmdProfile vive_ = hmd::load_hmd_profile("vive").value_or_throw();
};

TEST_F(FusedComposite, StudyScenesMatchTheSeparatePassesInBothHybridModes) {
    for (scenes::SceneId id :
         {scenes::SceneId::Beams, scenes::SceneId::Landscape, scenes::SceneId::Spheres}) {
        const scenes::Scene scene = scenes::generate_scene(id, scenes::Detail::Test);
        for (Mode mode : {Mode::kHybrid, Mode::kHybridFarfield}) {
            Pair pair(ctx(), scene, mode);
            for (const scenes::Viewpoint& viewpoint : scene.viewpoints) {
                for (double m : {3.0, 8.0}) {
                    const std::string context = scene.name + " " + plan::mode_name(mode) + " " +
                                                viewpoint.name + " m " + std::to_string(m);
                    EXPECT_TRUE(pair.render(inputs_at(viewpoint.head, m))) << context;
                    pair.expect_same_images(context);
                }
            }
        }
    }
}

TEST_F(FusedComposite, DebugViewsMatchTheSeparatePasses) {
    const scenes::Scene scene =
        scenes::generate_scene(scenes::SceneId::Beams, scenes::Detail::Test);
    const rig::Pose head = scene.viewpoints.front().head;
    for (Mode mode : {Mode::kHybrid, Mode::kHybridFarfield}) {
        Pair pair(ctx(), scene, mode);
        for (DebugView debug : {DebugView::kTintMono, DebugView::kStereoOnly, DebugView::kMonoOnly,
                                DebugView::kRouting}) {
            modes::FrameInputs inputs = inputs_at(head, 8.0);
            inputs.debug = debug;
            const std::string context =
                plan::mode_name(mode) + " debug " + std::to_string(static_cast<int>(debug));
            EXPECT_TRUE(pair.render(inputs)) << context;
            pair.expect_same_images(context);
        }
    }
}

// Near content drawn for both eyes in one pass: the eyes' HDR images are layers of one image.
TEST_F(FusedComposite, SinglePassNearContentMatchesTheSeparatePasses) {
    const scenes::Scene scene =
        scenes::generate_scene(scenes::SceneId::Landscape, scenes::Detail::Test);
    for (plan::StereoPass pass :
         {plan::StereoPass::kMultiview, plan::StereoPass::kGeometryShader}) {
        if (pass == plan::StereoPass::kMultiview && !ctx().capabilities().multiview) continue;
        if (pass == plan::StereoPass::kGeometryShader && !ctx().capabilities().geometry_shader) {
            continue;
        }
        modes::RendererOptions options = options_with(false);
        options.stereo_pass = pass;
        Pair pair(ctx(), scene, Mode::kHybrid, options);
        const std::string context = "stereo pass " + plan::stereo_pass_name(pass);
        EXPECT_TRUE(pair.render(inputs_at(scene.viewpoints.front().head, 8.0))) << context;
        pair.expect_same_images(context);
    }
}

// Everything within 3 m, so C's list is empty at m = 8: the GPU skips the composite, the eyes
// draw their own sky, and the tone mapping (planned if mono-none) writes the display image. At
// m = 2 C draws again: the tone mapping's draw is then skipped and its pass must keep what the
// composite wrote; and back.
TEST_F(FusedComposite, EmptyMonoListLeavesTheToneMappingAloneAndBack) {
    if (!predicated()) GTEST_SKIP() << "no VK_EXT_conditional_rendering: C always draws";
    scenes::Scene scene;
    testing::add_quad(scene, {-0.8f, 1.1f, -2.0f}, {0.6f, 0.0f, 0.0f}, {0.0f, 0.6f, 0.0f},
                      scenes::pack_rgba8(0.7f, 0.3f, 0.2f), 2);
    testing::add_quad(scene, {0.1f, 1.5f, -2.9f}, {0.8f, 0.0f, 0.0f}, {0.0f, 0.8f, 0.0f},
                      scenes::pack_rgba8(0.2f, 0.4f, 0.7f), 3);
    testing::add_quad(scene, {-1.0f, 0.8f, -1.0f}, {2.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -1.9f},
                      scenes::pack_rgba8(0.4f, 0.5f, 0.3f), 2);
    testing::finish_bounds(scene);
    ASSERT_LT(-scene.bounds.min.z, 3.0f);

    const rig::Pose head{glm::dvec3(0.0, 1.6, 0.0), glm::dquat(1.0, 0.0, 0.0, 0.0)};
    Pair pair(ctx(), scene, Mode::kHybrid);
    for (double m : {8.0, 2.0, 8.0}) {
        const std::string context = "m " + std::to_string(m);
        modes::FrameInputs inputs = inputs_at(head, m);
        // The paper's overlap eps, not its growth for grazing surfaces: C starts near m.
        inputs.grazing_angle = 0.0;
        EXPECT_TRUE(pair.render(inputs)) << context;
        pair.expect_same_images(context);
        const plan::PlannedPass* tonemap =
            pair.fused().last_plan().find(plan::PassKind::kTonemap, plan::ViewId::kLeft);
        ASSERT_NE(tonemap, nullptr);
        EXPECT_FALSE(tonemap->skipped.has_value()) << context;
        EXPECT_EQ(tonemap->when, plan::GpuPredicate::kMonoNone) << context;
        if (!ctx().capabilities().pipeline_statistics) continue;
        // Which of the two ran on the GPU: the composite's draws only when C drew something.
        const bool mono_empty = m == 8.0;
        for (const char* composite : {"left.composite", "right.composite"}) {
            EXPECT_EQ(testing::view_of(pair.stats(), composite).input_primitives,
                      mono_empty ? 0u : 2u)
                << context << " " << composite;
        }
    }
}

}  // namespace
}  // namespace monoplane
