// A small marker at a known world position must appear, in each eye, at the pixel that the
// tangent definition of that eye's frustum predicts (computed here by hand, not with the rig).
#include <gtest/gtest.h>

#include <cmath>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "tests/gpu/gpu_test.h"

namespace monoplane {
namespace {

struct Centroid {
    double x = 0.0;
    double y = 0.0;
    int pixels = 0;
};

// Pixels that are clearly the red marker (the sky and the ground are never twice as red as green).
Centroid red_centroid(const modes::RgbaImage& image) {
    Centroid c;
    for (std::uint32_t y = 0; y < image.height; ++y) {
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.pixels[(y * image.width + x) * 4];
            if (p[0] > 60 && p[0] > 2 * p[1] && p[0] > 2 * p[2]) {
                c.x += x + 0.5;  // pixel centres
                c.y += y + 0.5;
                ++c.pixels;
            }
        }
    }
    if (c.pixels > 0) {
        c.x /= c.pixels;
        c.y /= c.pixels;
    }
    return c;
}

// A square facing the viewer (normal +z): its projection is an axis-aligned rectangle whose
// centroid is the projection of its centre, exactly, because it is parallel to the image plane.
scenes::Scene marker_scene(const glm::vec3& centre, float half_size) {
    scenes::Scene scene;
    scene.name = "marker";
    const std::uint32_t red = scenes::pack_rgba8(1.0f, 0.0f, 0.0f);
    const std::uint32_t material = scenes::pack_material({0.9f, 0.02f, 0});
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    for (const auto& [dx, dy] : {std::pair{-1, -1}, {1, -1}, {1, 1}, {-1, 1}}) {
        scene.vertices.push_back(
            {centre + glm::vec3(dx * half_size, dy * half_size, 0.0f), n, red, material});
    }
    scene.indices = {0, 1, 2, 0, 2, 3};  // counter-clockwise seen from +z
    scenes::Chunk chunk;
    chunk.index_count = 6;
    chunk.bounds = {centre - glm::vec3(half_size, half_size, 0.0f),
                    centre + glm::vec3(half_size, half_size, 0.0f)};
    scene.chunks = {chunk};
    scene.bounds = chunk.bounds;
    scene.lighting.sun_direction = glm::normalize(glm::vec3(0.2f, 0.5f, 1.0f));
    return scene;
}

class StereoMarker : public testing::GpuTest {};

TEST_F(StereoMarker, MarkerLandsOnTheAnalyticPixelInEachEye) {
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    const glm::dvec3 head(0.0, 1.7, 0.0);
    const glm::dvec3 marker(0.31, 1.83, -4.0);
    const scenes::Scene scene = marker_scene(glm::vec3(marker), 0.06f);
    const std::uint32_t width = 336;  // a quarter of the Vive's 1344 x 1512
    const std::uint32_t height = 378;

    modes::RendererOptions options;
    options.shadow.resolution = 512;
    modes::ModeRenderer stereo(ctx(), scene, modes::Mode::kStereo, {width, height}, options);
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

        const Centroid c = red_centroid(stereo.eye_image(eye));
        SCOPED_TRACE(modes::eye_name(eye));
        ASSERT_GT(c.pixels, 4);
        EXPECT_NEAR(c.x, expected_x, 1.0);
        EXPECT_NEAR(c.y, expected_y, 1.0);
    }
    // Sanity of the set-up itself: the two eyes disagree by the disparity of a point at 4 m.
    const Centroid left = red_centroid(stereo.eye_image(modes::Eye::kLeft));
    const Centroid right = red_centroid(stereo.eye_image(modes::Eye::kRight));
    EXPECT_GT(std::abs(left.x - right.x), 1.0);
}

TEST_F(StereoMarker, PipelineStatisticsCountTheDrawnTriangles) {
    if (!ctx().capabilities().pipeline_statistics) GTEST_SKIP() << "no pipelineStatisticsQuery";
    const scenes::Scene scene = marker_scene({0.0f, 1.7f, -3.0f}, 0.5f);
    modes::RendererOptions options;
    options.shadow.resolution = 256;
    modes::ModeRenderer stereo(ctx(), scene, modes::Mode::kStereo, {64, 64}, options);
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
    ASSERT_FALSE(stats.passes.empty());
    EXPECT_EQ(stats.passes.front().name, "shadow");
    for (const auto& pass : stats.passes) EXPECT_GE(pass.gpu_ms, 0.0) << pass.name;
}

}  // namespace
}  // namespace monoplane
