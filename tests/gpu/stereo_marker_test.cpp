// A small marker at a known world position must appear, in each eye, at the pixel that the
// tangent definition of that eye's frustum predicts (computed here by hand, not with the rig).
#include <gtest/gtest.h>

#include <cmath>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/hybrid_test_scenes.h"
#include "tests/gpu/marker_centroid.h"

namespace monoplane {
namespace {

class StereoMarker : public testing::GpuTest {};

TEST_F(StereoMarker, MarkerLandsOnTheAnalyticPixelInEachEye) {
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    const glm::dvec3 head(0.0, 1.7, 0.0);
    const glm::dvec3 marker(0.31, 1.83, -4.0);
    const scenes::Scene scene = testing::marker_scene(glm::vec3(marker), 0.1f);
    const std::uint32_t width = 336;  // a quarter of the Vive's 1344 x 1512
    const std::uint32_t height = 378;

    modes::RendererOptions options;
    options.shadow.resolution = 512;
    modes::ModeRenderer stereo(ctx(), scene, plan::Mode::kStereo, {width, height}, options);
    modes::StereoViewInputs inputs;
    inputs.head.position = head;
    inputs.ipd = vive.ipd;
    inputs.left = vive.left;
    inputs.right = vive.right;
    stereo.render_frame({inputs});

    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        const rig::Tangents& t = eye == modes::Eye::kLeft ? vive.left : vive.right;
        const double eye_x = (eye == modes::Eye::kLeft ? -0.5 : 0.5) * vive.ipd;
        const glm::dvec3 rel = marker - (head + glm::dvec3(eye_x, 0.0, 0.0));
        const double tan_x = rel.x / -rel.z;
        const double tan_y = rel.y / -rel.z;
        const double expected_x = (tan_x - t.left) / (t.right - t.left) * width;
        const double expected_y = (t.up - tan_y) / (t.up - t.down) * height;

        const testing::Centroid c = testing::red_centroid(stereo.eye_image(eye));
        SCOPED_TRACE(modes::eye_name(eye));
        ASSERT_GT(c.weight, 0.0);
        EXPECT_NEAR(c.x, expected_x, 1.0);
        EXPECT_NEAR(c.y, expected_y, 1.0);
    }
    // Sanity of the set-up itself: the two eyes disagree by the disparity of a point at 4 m.
    const testing::Centroid left = testing::red_centroid(stereo.eye_image(modes::Eye::kLeft));
    const testing::Centroid right = testing::red_centroid(stereo.eye_image(modes::Eye::kRight));
    EXPECT_GT(std::abs(left.x - right.x), 1.0);
}

TEST_F(StereoMarker, PipelineStatisticsCountTheDrawnTriangles) {
    if (!ctx().capabilities().pipeline_statistics) GTEST_SKIP() << "no pipelineStatisticsQuery";
    // One untessellated square facing the viewer: exactly two triangles.
    scenes::Scene scene;
    testing::add_quad(scene, {-0.5f, 1.2f, -3.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f},
                      scenes::pack_rgba8(1.0f, 0.0f, 0.0f));
    testing::finish_bounds(scene);
    modes::RendererOptions options;
    options.shadow.resolution = 256;
    modes::ModeRenderer stereo(ctx(), scene, plan::Mode::kStereo, {64, 64}, options);
    modes::StereoViewInputs inputs;
    inputs.head.position = {0.0, 1.7, 0.0};
    inputs.left = inputs.right = rig::Tangents{-1.0, 1.0, -1.0, 1.0};
    const profile::FrameStats stats = stereo.render_frame({inputs});
    ASSERT_EQ(stats.views.size(), 2u);
    for (const profile::ViewStatistics& v : stats.views) {
        SCOPED_TRACE(v.view);
        // Two triangles of geometry, plus the sky's one full-screen triangle.
        EXPECT_EQ(v.input_primitives, 3u);
        EXPECT_EQ(v.clipping_invocations, 3u);
        EXPECT_LE(v.vertex_invocations, 4u + 3u);
        // Every one of the 64 x 64 pixels is shaded once, by the quad (1/6 of the width and of
        // the height: about 114 px) or by the sky behind it (depth-equal test). Implementations
        // may also count helper invocations in 2x2 quads along edges (llvmpipe does), so allow
        // up to a quarter more, far below the 2 x 4096 that shading each pixel twice would give.
        EXPECT_GE(v.fragment_invocations, 4096u);
        EXPECT_LE(v.fragment_invocations, 4096u * 5 / 4);
    }
    ASSERT_GE(stats.passes.size(), 2u);
    // The GPU culling runs first, then the (first frame's) shadow map.
    EXPECT_EQ(stats.passes[0].name, "culling");
    EXPECT_EQ(stats.passes[1].name, "shadow");
    for (const auto& v : stats.views) EXPECT_EQ(v.draws, 1u) << v.view;  // the quad's one chunk
    for (const auto& pass : stats.passes) EXPECT_GE(pass.gpu_ms, 0.0) << pass.name;
}

}  // namespace
}  // namespace monoplane
