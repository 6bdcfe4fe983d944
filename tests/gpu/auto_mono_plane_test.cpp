// `--mono-plane auto` on the GPU (issue 20 item 3): the chosen m lies in an empty depth band; the
// error of every visible pixel beyond m stays within the budget at every frame of a pose path;
// m moves by at most the bound per frame; all content near gives exactly stereo. Visible depths
// come from the eyes' depth read back after each frame, the errors from the rig's angular error
// (checked against the geometry in rig_angular_error_test), not from the chooser's own estimates.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <vector>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "rig/angular_error.h"
#include "rig/pose_path.h"
#include "scenes/generate.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/hybrid_test_scenes.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

using modes::Eye;
using plan::Mode;

const glm::dvec3 kViewer{0.0, 1.6, 0.0};

// Two strips of ground, from 2 to 6 m and from 40 to 200 m in front of the viewer, and nothing
// between: an empty band from 6 to 40 m, with content continuously on either side of it.
scenes::Scene band_scene() {
    scenes::Scene scene;
    scene.name = "band";
    const std::uint32_t near = scenes::pack_rgba8(0.7f, 0.4f, 0.3f);
    const std::uint32_t far = scenes::pack_rgba8(0.3f, 0.5f, 0.7f);
    // Counter-clockwise seen from above: edge_u x edge_v points up.
    testing::add_quad(scene, {-2.0f, 0.0f, -2.0f}, {4.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -4.0f}, near,
                      8);
    testing::add_quad(scene, {-80.0f, 0.0f, -40.0f}, {160.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -160.0f},
                      far, 8);
    testing::finish_bounds(scene);
    scene.viewpoints = {scenes::make_viewpoint("default", kViewer)};
    return scene;
}

// Every quad nearer than the chooser's nearest plane (1.6 m).
scenes::Scene near_scene() {
    scenes::Scene scene;
    scene.name = "near";
    const std::uint32_t colour = scenes::pack_rgba8(0.6f, 0.6f, 0.3f);
    for (const double depth : {0.6, 0.9, 1.2}) {
        const float w = static_cast<float>(0.3 * depth);
        const float x = static_cast<float>((depth - 0.9) * 1.5);
        testing::add_quad(scene, {x - w, 1.3f, -static_cast<float>(depth)}, {2 * w, 0, 0},
                          {0, 2 * w, 0}, colour, 2);
    }
    testing::finish_bounds(scene);
    scene.viewpoints = {scenes::make_viewpoint("default", kViewer)};
    return scene;
}

class AutoMonoPlane : public testing::GpuTest {
  protected:
    modes::RendererOptions options(const plan::AutoMonoPlaneParams& params) const {
        modes::RendererOptions o;
        o.shadow.resolution = 256;
        o.read_back_depth = true;
        o.auto_mono_plane = params;
        // Decisions from the frames' content only: a test must not depend on the machine's speed.
        o.auto_mono_plane->stereo_when_slower = false;
        return o;
    }
    // The farthest depth any eye pixel shows (the sky left out).
    static double farthest_visible(const modes::ModeRenderer& renderer) {
        double farthest = 0.0;
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            for (const float d : renderer.eye_linear_depth(eye)) {
                if (d < 1e20f) farthest = std::max(farthest, static_cast<double>(d));
            }
        }
        return farthest;
    }
    double eye_error(double m, double depth) const {
        if (m >= 1000.0 || depth <= m) return 0.0;
        rig::RigInputs in = hmd::rig_inputs(vive_, m);
        in.eye_width = static_cast<int>(extent_.width);
        in.eye_height = static_cast<int>(extent_.height);
        return rig::angular_error_at_depth(rig::build_rig(in).value_or_throw(), depth).eye_arcmin;
    }

    hmd::HmdProfile vive_ = hmd::load_hmd_profile("vive").value_or_throw();
    const vk::Extent2D extent_{168, 189};
};

TEST_F(AutoMonoPlane, ChoosesAPlaneInAnEmptyDepthBand) {
    const scenes::Scene scene = band_scene();
    plan::AutoMonoPlaneParams params;
    params.error_budget_arcmin = 25.0;  // a floor near 5 m, inside the near content
    params.max_step_arcmin = 2.0;
    modes::ModeRenderer renderer(ctx(), scene, Mode::kHybrid, extent_, options(params));
    const modes::FrameInputs inputs = testing::profile_inputs(vive_, scene.viewpoints[0].head, 8.0);
    double floor = 0.0;
    for (int frame = 0; frame < 20; ++frame) {
        renderer.render_frame(inputs);
        floor = renderer.last_mono_plane_decision()->floor;
    }
    const plan::MonoPlaneDecision& d = *renderer.last_mono_plane_decision();
    EXPECT_LT(floor, 6.0);
    EXPECT_GT(d.mono_plane, 6.0) << d.reason;
    EXPECT_LT(d.mono_plane, 40.0) << d.reason;
    EXPECT_EQ(d.reason, "gap");
    ASSERT_TRUE(renderer.last_rig());
    EXPECT_EQ(renderer.last_rig()->inputs.mono_plane, d.mono_plane);
}

// The GPU histogram (each invocation counting a block of pixels, runs of one bin added at once)
// counts every pixel of both eyes once: the sky exactly, the geometry pixels by bin as the
// read-back depth gives them binned here (a pixel within float rounding of a bin edge may land
// in the neighbour), and the farthest depth exactly. At an eye size that is not a multiple of the
// blocks, so partial blocks and workgroups are covered.
TEST_F(AutoMonoPlane, TheHistogramCountsEveryEyePixelOnce) {
    const scenes::Scene scene = band_scene();
    plan::AutoMonoPlaneParams params;
    params.error_budget_arcmin = 25.0;
    modes::ModeRenderer renderer(ctx(), scene, Mode::kHybrid, extent_, options(params));
    rig::Pose head = scene.viewpoints[0].head;
    for (int frame = 0; frame < 4; ++frame) {
        // Turning and looking down a little more each frame: the sky's share changes.
        head.orientation = rig::orientation_from_yaw_pitch(0.05 * frame, -0.08 * frame);
        renderer.render_frame(testing::profile_inputs(vive_, head, 8.0));
        const plan::DepthHistogram* gpu = renderer.last_depth_histogram();
        ASSERT_NE(gpu, nullptr) << "frame " << frame;

        std::array<std::int64_t, plan::DepthHistogram::kBins> expected{};
        std::int64_t sky = 0;
        double farthest = 0.0;
        std::int64_t near_an_edge = 0;
        const double log_ratio = std::log(gpu->far / gpu->near);
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            for (const float d : renderer.eye_linear_depth(eye)) {
                if (d >= 0.5e30f) {
                    ++sky;
                    continue;
                }
                const double position = std::log(std::max(double(d), 1e-30) / gpu->near) /
                                        log_ratio * plan::DepthHistogram::kBins;
                const int bin = std::clamp(static_cast<int>(std::floor(position)), 0,
                                           plan::DepthHistogram::kBins - 1);
                ++expected[static_cast<std::size_t>(bin)];
                if (std::abs(position - std::round(position)) < 1e-3) ++near_an_edge;
                farthest = std::max(farthest, double(d));
            }
        }
        EXPECT_EQ(sky + std::accumulate(expected.begin(), expected.end(), std::int64_t{0}),
                  2 * std::int64_t{extent_.width} * extent_.height);
        EXPECT_EQ(gpu->sky, sky) << "frame " << frame;
        EXPECT_GT(sky, 0) << "the view shows sky";
        EXPECT_EQ(static_cast<std::int64_t>(gpu->geometry_pixels()),
                  2 * std::int64_t{extent_.width} * extent_.height - sky);
        std::int64_t misplaced = 0;
        for (int b = 0; b < plan::DepthHistogram::kBins; ++b) {
            misplaced += std::abs(std::int64_t{gpu->counts[static_cast<std::size_t>(b)]} -
                                  expected[static_cast<std::size_t>(b)]);
        }
        EXPECT_LE(misplaced, 2 * near_an_edge) << "frame " << frame;
        EXPECT_FLOAT_EQ(static_cast<float>(gpu->farthest), static_cast<float>(farthest));
    }
}

TEST_F(AutoMonoPlane, EveryVisiblePixelStaysWithinTheBudgetAlongAPosePath) {
    const scenes::Scene scene =
        scenes::generate_scene(scenes::SceneId::Spheres, scenes::Detail::Test);
    plan::AutoMonoPlaneParams params;
    params.error_budget_arcmin = 8.0;
    params.max_step_arcmin = 0.5;
    modes::RendererOptions o = options(params);
    o.anti_aliasing = plan::AntiAliasing::kTaa;
    modes::ModeRenderer renderer(ctx(), scene, Mode::kHybrid, extent_, o);
    const rig::PosePath path = *rig::builtin_pose_path("turn");
    modes::FrameInputs inputs = testing::profile_inputs(vive_, scene.viewpoints[0].head, 8.0);
    std::optional<double> previous;
    int moved = 0;
    for (int frame = 0; frame < 24; ++frame) {
        inputs.views.head = rig::pose_along(path, scene.viewpoints[0].head, frame / 20.0);
        inputs.frame_index = static_cast<std::uint64_t>(frame);
        const profile::FrameStats stats = renderer.render_frame(inputs);
        ASSERT_TRUE(stats.mono_plane);
        const double m = *stats.mono_plane;
        const double visible = farthest_visible(renderer);
        const plan::MonoPlaneDecision& d = *renderer.last_mono_plane_decision();
        SCOPED_TRACE("frame " + std::to_string(frame) + " m " + std::to_string(m) + " (" +
                     d.reason + "), farthest visible " + std::to_string(visible));
        // The chunks' bound holds what the pixels show, and the budget holds there.
        EXPECT_GE(d.content_depth, visible * (1.0 - 1e-5));
        EXPECT_LE(eye_error(m, visible), params.error_budget_arcmin + 1e-6);
        if (previous) {
            // At the depth the chooser held the budget for: the far content's shift this frame.
            EXPECT_TRUE(d.jumped || std::abs(eye_error(m, d.content_depth) -
                                             eye_error(*previous, d.content_depth)) <=
                                        params.max_step_arcmin + 1e-6);
            if (*previous != m) ++moved;
            // TAA's history survives the moves.
            if (!d.jumped) {
                EXPECT_FALSE(renderer.history_restarted());
            }
        }
        previous = m;
    }
    EXPECT_GT(moved, 0);  // the path really moved m
}

TEST_F(AutoMonoPlane, AllContentNearIsExactlyStereo) {
    const scenes::Scene scene = near_scene();
    modes::RendererOptions o = options({});
    o.read_back_depth = false;
    modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, extent_, o);
    modes::RendererOptions stereo_options;
    stereo_options.shadow.resolution = 256;
    modes::ModeRenderer stereo(ctx(), scene, Mode::kStereo, extent_, stereo_options);
    const modes::FrameInputs inputs = testing::profile_inputs(vive_, scene.viewpoints[0].head, 8.0);
    const profile::FrameStats stats = hybrid.render_frame(inputs);
    stereo.render_frame(inputs);
    EXPECT_EQ(stats.mono_plane, 1000.0);
    EXPECT_EQ(stats.mono_plane_reason, "stereo: no content beyond the floor");
    EXPECT_EQ(hybrid.mono_image(), nullptr);
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        const auto& a = hybrid.eye_image(eye).pixels;
        const auto& b = stereo.eye_image(eye).pixels;
        ASSERT_EQ(a.size(), b.size());
        int worst = 0;
        for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] - b[i]));
        EXPECT_EQ(worst, 0) << modes::eye_name(eye);
    }
}

}  // namespace
}  // namespace monoplane
