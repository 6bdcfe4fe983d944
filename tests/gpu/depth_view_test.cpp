// The depth debug view (`--debug-view depth`, renderer/passes/depth_view), the first pass kind
// written as one unit: each eye's display image shows its linear depth d as a brightness
// g = 1 - 0.75 * clamp(log10(d) / 3, 0, 1), warm (1, 0.85, 0.6) * g nearer than the mono plane m
// and cool (0.6, 0.8, 1) * g at or beyond it (everything warm in stereo), black for the sky,
// stored sRGB-encoded. The scene is two walls facing the viewer at known distances (2 m and
// 20 m) and sky between them, so the colours expected are derived here from the distances alone;
// and every pixel is checked against the same mapping of its read-back depth.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <string>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/hybrid_test_scenes.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

using modes::Eye;
using plan::Mode;

constexpr vk::Extent2D kExtent{72, 80};
constexpr double kNear = 2.0;   // the left wall's distance, metres
constexpr double kFar = 20.0;   // the right wall's
constexpr double kPlane = 8.0;  // m: between them
constexpr double kSky = 1.0e29;

double srgb_encode(double linear) {
    return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055;
}

// The view's colour for depth d with mono plane m, 8-bit sRGB.
std::array<int, 3> expected_colour(double d, double m) {
    if (d >= kSky) return {0, 0, 0};
    const double t = std::clamp(std::log10(d) / 3.0, 0.0, 1.0);
    const double g = 1.0 - 0.75 * t;
    const std::array<double, 3> hue =
        d < m ? std::array{1.0, 0.85, 0.6} : std::array{0.6, 0.8, 1.0};
    std::array<int, 3> rgb{};
    for (int c = 0; c < 3; ++c) {
        rgb[c] = static_cast<int>(std::lround(255.0 * srgb_encode(g * hue[c])));
    }
    return rgb;
}

scenes::Scene two_walls() {
    scenes::Scene scene;
    // Facing +z (towards the viewer at the origin, who looks down -z), left of centre at 2 m and
    // right of centre at 20 m.
    testing::add_quad(scene, {-3.0f, -1.0f, static_cast<float>(-kNear)}, {2.7f, 0.0f, 0.0f},
                      {0.0f, 5.0f, 0.0f}, scenes::pack_rgba8(0.7f, 0.3f, 0.2f), 2);
    testing::add_quad(scene, {3.0f, -30.0f, static_cast<float>(-kFar)}, {40.0f, 0.0f, 0.0f},
                      {0.0f, 60.0f, 0.0f}, scenes::pack_rgba8(0.2f, 0.4f, 0.7f), 2);
    testing::finish_bounds(scene);
    return scene;
}

class DepthView : public testing::GpuTest {
  protected:
    // Renders one frame of the view; checks every pixel against its read-back depth and returns
    // how many pixels lay on the near wall, the far wall and the sky, with the walls' colours.
    struct Seen {
        int near = 0, far = 0, sky = 0;
        std::array<int, 3> near_colour{}, far_colour{};
    };

    Seen render(Mode mode, const std::string& context) {
        modes::RendererOptions options;
        options.shadow.resolution = 256;
        options.read_back_depth = true;
        modes::ModeRenderer renderer(ctx(), scene_, mode, kExtent, options);
        const rig::Pose head{glm::dvec3(0.0), glm::dquat(1.0, 0.0, 0.0, 0.0)};
        modes::FrameInputs inputs = testing::profile_inputs(vive_, head, kPlane);
        inputs.unit_debug_view = "depth";
        renderer.render_frame(inputs);
        for (plan::ViewId eye : plan::kEyeViews) {
            const plan::PlannedPass* pass = renderer.last_plan().find_unit("depth_view", eye);
            EXPECT_TRUE(pass != nullptr && !pass->skipped) << context;
        }
        const double m = mode == Mode::kStereo ? 1.0e30 : kPlane;
        Seen seen;
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            const modes::RgbaImage& image = renderer.eye_image(eye);
            const std::vector<float>& depth = renderer.eye_linear_depth(eye);
            int mismatches = 0;
            for (std::size_t p = 0; p < depth.size(); ++p) {
                const std::array<int, 3> want = expected_colour(depth[p], m);
                std::array<int, 3> got{};
                for (int c = 0; c < 3; ++c) got[c] = image.pixels[4 * p + c];
                for (int c = 0; c < 3; ++c) mismatches += std::abs(got[c] - want[c]) > 1 ? 1 : 0;
                if (std::abs(depth[p] - kNear) < 0.02) {
                    ++seen.near;
                    seen.near_colour = got;
                } else if (std::abs(depth[p] - kFar) < 0.2) {
                    ++seen.far;
                    seen.far_colour = got;
                } else if (depth[p] >= kSky) {
                    ++seen.sky;
                }
            }
            EXPECT_EQ(mismatches, 0) << context << " " << modes::eye_name(eye);
        }
        return seen;
    }

    static void expect_colour(const std::array<int, 3>& got, const std::array<int, 3>& want,
                              const std::string& context) {
        for (int c = 0; c < 3; ++c) EXPECT_LE(std::abs(got[c] - want[c]), 1) << context << " " << c;
    }

    scenes::Scene scene_ = two_walls();
    hmd::HmdProfile vive_ = hmd::load_hmd_profile("vive").value_or_throw();
};

// Hybrid at m = 8: the 2 m wall is warm, the 20 m wall (drawn by C) cool, the sky black.
TEST_F(DepthView, HybridShowsNearContentWarmAndWhatCDrewCool) {
    for (Mode mode : {Mode::kHybrid, Mode::kHybridFarfield}) {
        const std::string context = plan::mode_name(mode);
        const Seen seen = render(mode, context);
        EXPECT_GT(seen.near, 200) << context;
        EXPECT_GT(seen.far, 200) << context;
        EXPECT_GT(seen.sky, 100) << context;
        // From the distances alone: 2 m warm at g = 1 - 0.25 log10 2, 20 m cool.
        expect_colour(seen.near_colour, expected_colour(kNear, kPlane), context + " near");
        expect_colour(seen.far_colour, expected_colour(kFar, kPlane), context + " far");
        EXPECT_GT(seen.near_colour[0], seen.near_colour[2]) << context;
        EXPECT_LT(seen.far_colour[0], seen.far_colour[2]) << context;
    }
}

// Stereo has no mono plane: both walls warm, the nearer brighter.
TEST_F(DepthView, StereoShowsEverythingWarm) {
    const Seen seen = render(Mode::kStereo, "stereo");
    EXPECT_GT(seen.near, 200);
    EXPECT_GT(seen.far, 200);
    expect_colour(seen.near_colour, expected_colour(kNear, 1.0e30), "near");
    expect_colour(seen.far_colour, expected_colour(kFar, 1.0e30), "far");
    EXPECT_GT(seen.far_colour[0], seen.far_colour[2]);
    EXPECT_GT(seen.near_colour[1], seen.far_colour[1]);
}

}  // namespace
}  // namespace monoplane
