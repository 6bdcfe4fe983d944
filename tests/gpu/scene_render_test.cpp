// Each study scene renders in stereo without validation messages, shows structure (not a blank
// or uniform image), and the two eyes differ by parallax but not in overall content.
#include <gtest/gtest.h>

#include <cmath>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "scenes/generate.h"
#include "tests/gpu/gpu_test.h"

namespace monoplane {
namespace {

double luminance_stddev(const modes::RgbaImage& image) {
    double sum = 0.0;
    double sum_sq = 0.0;
    const std::size_t n = std::size_t{image.width} * image.height;
    for (std::size_t i = 0; i < n; ++i) {
        const double l = 0.2126 * image.pixels[4 * i] + 0.7152 * image.pixels[4 * i + 1] +
                         0.0722 * image.pixels[4 * i + 2];
        sum += l;
        sum_sq += l * l;
    }
    const double mean = sum / static_cast<double>(n);
    return std::sqrt(std::max(0.0, sum_sq / static_cast<double>(n) - mean * mean));
}

double mean_abs_difference(const modes::RgbaImage& a, const modes::RgbaImage& b) {
    double total = 0.0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        total += std::abs(static_cast<int>(a.pixels[i]) - static_cast<int>(b.pixels[i]));
    }
    return total / static_cast<double>(a.pixels.size());
}

class SceneRender : public testing::GpuTest,
                    public ::testing::WithParamInterface<scenes::SceneId> {};

TEST_P(SceneRender, StereoPairHasStructureAndParallax) {
    const scenes::Scene scene = scenes::generate_scene(GetParam(), scenes::Detail::Test, 7);
    const hmd::HmdProfile vive = hmd::load_hmd_profile("vive").value_or_throw();
    modes::RendererOptions options;
    options.shadow.resolution = 1024;
    modes::ModeRenderer stereo(ctx(), scene, plan::Mode::kStereo, {168, 189}, options);
    modes::StereoViewInputs inputs;
    inputs.head = scene.viewpoints.front().head;
    inputs.ipd = vive.ipd;
    inputs.left = vive.left;
    inputs.right = vive.right;
    const profile::FrameStats stats = stereo.render_frame({inputs});

    const auto& left = stereo.eye_image(modes::Eye::kLeft);
    const auto& right = stereo.eye_image(modes::Eye::kRight);
    EXPECT_GT(luminance_stddev(left), 10.0);
    EXPECT_GT(luminance_stddev(right), 10.0);
    const double difference = mean_abs_difference(left, right);
    EXPECT_GT(difference, 0.5);   // parallax and the asymmetric frusta
    EXPECT_LT(difference, 60.0);  // but the same scene

    ASSERT_EQ(stats.views.size(), 2u);
    for (const auto& v : stats.views) {
        if (!ctx().capabilities().pipeline_statistics) break;
        EXPECT_GT(v.input_primitives, 1000u) << v.view;
        EXPECT_LE(v.input_primitives, scene.triangle_count() + 1) << v.view;
        EXPECT_GE(v.fragment_invocations, 168u * 189u) << v.view;
    }
}

INSTANTIATE_TEST_SUITE_P(AllScenes, SceneRender,
                         ::testing::Values(scenes::SceneId::Beams, scenes::SceneId::Landscape,
                                           scenes::SceneId::Spheres),
                         [](const auto& info) {
                             return std::string(scenes::scene_name(info.param));
                         });

}  // namespace
}  // namespace monoplane
