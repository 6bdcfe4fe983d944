// Hybrid rendering on canted displays (issue 18 item 4; docs/hybrid.md), measured on
// rendered images for the Vive's frusta turned by +-5 and +-15 degrees (outwards and inwards).
// Expected positions come from a pinhole model of the turned eyes written here, not from the
// rig: a point's tangents in an eye turned by yaw a are those of R_y(-a) (p - eye).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "scenes/generate.h"
#include "tests/gpu/cut_pixels.h"
#include "tests/gpu/gpu_test.h"
#include "tests/gpu/hybrid_test_scenes.h"
#include "tests/gpu/marker_centroid.h"
#include "tests/gpu/profile_inputs.h"

namespace monoplane {
namespace {

using modes::Eye;
using plan::Mode;

constexpr double kPi = 3.14159265358979323846;

modes::RendererOptions small_options(bool depth = false) {
    modes::RendererOptions options;
    options.shadow.resolution = 512;
    options.read_back_depth = depth;
    return options;
}

// The Vive's calibration with the left display turned `degrees` to the left and the right one
// as far to the right (negative: both inwards).
hmd::HmdProfile canted_vive(double degrees) {
    hmd::HmdProfile profile = hmd::load_hmd_profile("vive").value_or_throw();
    profile.cant_deg = {degrees, -degrees};
    return profile;
}

// Pixel of a head-frame point in eye `e` of `profile` (x right, y down), at this image size.
glm::dvec2 canted_pixel(const hmd::HmdProfile& profile, int e, const glm::dvec3& p,
                        vk::Extent2D extent) {
    const double a = profile.cant_deg[e] * kPi / 180.0;
    const glm::dvec3 d = p - glm::dvec3((e == 0 ? -0.5 : 0.5) * profile.ipd, 0.0, 0.0);
    const double x = std::cos(a) * d.x - std::sin(a) * d.z;
    const double z = std::sin(a) * d.x + std::cos(a) * d.z;
    const rig::Tangents& t = e == 0 ? profile.left : profile.right;
    const double tx = x / -z;
    const double ty = d.y / -z;
    return {(tx - t.left) / (t.right - t.left) * extent.width,
            (t.up - ty) / (t.up - t.down) * extent.height};
}

class CantedHybrid : public testing::GpuTest, public ::testing::WithParamInterface<double> {
  protected:
    hmd::HmdProfile profile_ = canted_vive(GetParam());
};

INSTANTIATE_TEST_SUITE_P(Cants, CantedHybrid, ::testing::Values(5.0, -5.0, 15.0, -15.0),
                         [](const ::testing::TestParamInfo<double>& info) {
                             return std::string(info.param > 0 ? "outwards_" : "inwards_") +
                                    std::to_string(static_cast<int>(std::abs(info.param))) +
                                    "_degrees";
                         });

// m at or beyond the far plane: hybrid is stereo, and stereo itself follows the cant (its image
// differs from the parallel headset's).
TEST_P(CantedHybrid, EqualsStereoWhenTheMonoPlaneIsAtFar) {
    const scenes::Scene scene =
        scenes::generate_scene(scenes::SceneId::Beams, scenes::Detail::Test, 3);
    const vk::Extent2D extent{96, 108};
    modes::ModeRenderer stereo(ctx(), scene, Mode::kStereo, extent, small_options());
    modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, extent, small_options());
    modes::ModeRenderer parallel(ctx(), scene, Mode::kStereo, extent, small_options());
    const rig::Pose head = scene.viewpoints.front().head;
    const auto inputs = testing::profile_inputs(profile_, head, 1000.0);
    stereo.render_frame(inputs);
    hybrid.render_frame(inputs);
    parallel.render_frame(testing::profile_inputs(canted_vive(0.0), head, 1000.0));
    EXPECT_EQ(hybrid.mono_image(), nullptr);
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        const auto& a = stereo.eye_image(eye).pixels;
        const auto& b = hybrid.eye_image(eye).pixels;
        const auto& c = parallel.eye_image(eye).pixels;
        int worst = 0;
        long long differs_from_parallel = 0;
        for (std::size_t i = 0; i < a.size(); ++i) {
            worst = std::max(worst, std::abs(a[i] - b[i]));
            differs_from_parallel += std::abs(a[i] - c[i]) > 8 ? 1 : 0;
        }
        EXPECT_LE(worst, 1) << modes::eye_name(eye);
        EXPECT_GT(differs_from_parallel, static_cast<long long>(a.size() / 20));
    }
}

// A marker on the mono plane lands where stereo puts it in both turned eyes (the plane-induced
// homography is exact there), and stereo puts it where the independent pinhole says.
TEST_P(CantedHybrid, AMarkerOnTheMonoPlaneIsExactInBothEyes) {
    const double m = 4.0;
    const vk::Extent2D extent{336, 378};
    const glm::dvec3 head(0.0, 1.7, 0.0);
    for (const glm::dvec3 in_head : {glm::dvec3(-1.2, 0.5, -m), glm::dvec3(1.4, -0.6, -m)}) {
        const scenes::Scene scene = testing::marker_scene(glm::vec3(head + in_head), 0.2f);
        rig::Pose pose;
        pose.position = head;
        const auto inputs = testing::profile_inputs(profile_, pose, m);
        auto hybrid_inputs = inputs;
        hybrid_inputs.mono_plane = m - 0.001;  // the marker just beyond the plane: C draws it
        modes::ModeRenderer stereo(ctx(), scene, Mode::kStereo, extent, small_options());
        modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, extent, small_options());
        stereo.render_frame(inputs);
        hybrid.render_frame(hybrid_inputs);
        ASSERT_NE(hybrid.mono_image(), nullptr);
        for (Eye eye : {Eye::kLeft, Eye::kRight}) {
            SCOPED_TRACE(std::string(modes::eye_name(eye)) + " x " + std::to_string(in_head.x));
            const testing::Centroid reference = testing::red_centroid(stereo.eye_image(eye));
            const testing::Centroid exact = testing::red_centroid(hybrid.eye_image(eye));
            const glm::dvec2 predicted =
                canted_pixel(profile_, static_cast<int>(eye), in_head, extent);
            EXPECT_NEAR(reference.x, predicted.x, 0.6);  // the oblique marker's centroid bias
            EXPECT_NEAR(reference.y, predicted.y, 0.6);
            EXPECT_NEAR(exact.x, reference.x, 0.2);
            EXPECT_NEAR(exact.y, reference.y, 0.2);
        }
    }
}

// Beyond the plane, hybrid shows a marker at its central projection from C onto the plane, seen
// by the turned eye: the drift matches that, computed here from C's position (where the outer
// edges, turned by the cant, cross behind the eyes).
TEST_P(CantedHybrid, DriftOfAFarMarkerMatchesTheAnalyticError) {
    const double m = 2.0;
    const double a = profile_.cant_deg[0] * kPi / 180.0;
    const double half_ipd = 0.5 * profile_.ipd;
    const double s = std::max(half_ipd / std::tan(std::atan(-profile_.left.left) + a),
                              half_ipd / std::tan(std::atan(profile_.right.right) + a));
    const vk::Extent2D extent{336, 378};
    const glm::dvec3 head(0.0, 1.7, 0.0);
    for (double depth : {10.0, 40.0}) {
        for (double tangent : {-0.5, 0.6}) {
            const glm::dvec3 in_head(tangent * depth, 0.1 * depth, -depth);
            const scenes::Scene scene =
                testing::marker_scene(glm::vec3(head + in_head), static_cast<float>(0.06 * depth));
            modes::ModeRenderer stereo(ctx(), scene, Mode::kStereo, extent, small_options());
            modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, extent, small_options());
            rig::Pose pose;
            pose.position = head;
            const auto inputs = testing::profile_inputs(profile_, pose, m);
            stereo.render_frame(inputs);
            hybrid.render_frame(inputs);
            const glm::dvec3 c(0.0, 0.0, s);
            const glm::dvec3 on_plane = c + (in_head - c) * ((m + s) / (depth + s));
            for (Eye eye : {Eye::kLeft, Eye::kRight}) {
                const int e = static_cast<int>(eye);
                const glm::dvec2 expected = canted_pixel(profile_, e, on_plane, extent) -
                                            canted_pixel(profile_, e, in_head, extent);
                const testing::Centroid st = testing::red_centroid(stereo.eye_image(eye));
                const testing::Centroid hy = testing::red_centroid(hybrid.eye_image(eye));
                SCOPED_TRACE(std::string(modes::eye_name(eye)) + " depth " + std::to_string(depth) +
                             " tangent " + std::to_string(tangent));
                EXPECT_GT(std::abs(expected.x), 0.5);  // a drift worth measuring
                EXPECT_NEAR(hy.x - st.x, expected.x, 0.35);
                EXPECT_NEAR(hy.y - st.y, expected.y, 0.35);
            }
        }
    }
}

// Surfaces crossing the plane show no cutting line with the overlap, and do without it (k = 0),
// at random heads and planes (the steep slabs of hybrid_accuracy_test).
TEST_P(CantedHybrid, NoCuttingLineAlongTheMonoPlane) {
    const scenes::Scene scene = testing::steep_slabs_scene();
    const vk::Extent2D extent{96, 108};
    modes::ModeRenderer stereo(ctx(), scene, Mode::kStereo, extent, small_options(true));
    modes::ModeRenderer hybrid(ctx(), scene, Mode::kHybrid, extent, small_options(true));
    std::mt19937_64 random(20261202);
    auto uniform = [&](double lo, double hi) {
        return lo + (hi - lo) * static_cast<double>(random() >> 11) * 0x1.0p-53;
    };
    int with_overlap = 0, without_overlap = 0, at_plane = 0;
    for (int trial = 0; trial < 16; ++trial) {
        rig::Pose head;
        head.position = {uniform(-0.8, 0.8), uniform(0.8, 2.2), uniform(-1.0, 1.0)};
        head.orientation =
            rig::orientation_from_yaw_pitch(uniform(-0.25, 0.25), uniform(-0.2, 0.2));
        auto inputs = testing::profile_inputs(profile_, head,
                                              std::exp(uniform(std::log(1.2), std::log(60.0))));
        stereo.render_frame(inputs);
        const double m = inputs.mono_plane;
        for (double k : {2.0, 0.0}) {
            inputs.overlap_k = k;
            hybrid.render_frame(inputs);
            for (Eye eye : {Eye::kLeft, Eye::kRight}) {
                const std::vector<float>& st = stereo.eye_linear_depth(eye);
                (k > 0 ? with_overlap : without_overlap) += testing::cut_pixels(
                    st, hybrid.eye_linear_depth(eye), static_cast<int>(extent.width),
                    static_cast<int>(extent.height), m);
                if (k > 0) {
                    at_plane += static_cast<int>(std::count_if(st.begin(), st.end(), [&](float d) {
                        return std::abs(d - m) <= 0.05 * m;
                    }));
                }
            }
        }
    }
    EXPECT_GT(at_plane, 300);
    EXPECT_EQ(with_overlap, 0);
    EXPECT_GT(without_overlap, 0);
}

// TAA's history follows C's content through the general form of eq. 9 (the homography's
// Jacobian per pixel): with the head turning steadily, a far marker in hybrid with TAA stays
// where hybrid without TAA draws it. A constant 1/2 S (right only for parallel eyes) would
// reproject the history to the wrong place and drag the marker behind.
TEST_P(CantedHybrid, TaaHistoryFollowsCsContentWhileTheHeadTurns) {
    const double m = 2.0;
    const vk::Extent2D extent{192, 216};
    const glm::dvec3 head(0.0, 1.7, 0.0);
    const glm::dvec3 marker(-6.0, 1.7 + 1.0, -20.0);
    const scenes::Scene scene = testing::marker_scene(glm::vec3(marker), 1.2f);
    modes::RendererOptions taa_options = small_options();
    taa_options.anti_aliasing = plan::AntiAliasing::kTaa;
    modes::ModeRenderer taa(ctx(), scene, Mode::kHybrid, extent, taa_options);
    modes::ModeRenderer plain(ctx(), scene, Mode::kHybrid, extent, small_options());
    for (int frame = 0; frame < 24; ++frame) {
        rig::Pose pose;
        pose.position = head;
        pose.orientation = rig::orientation_from_yaw_pitch(0.25 - 0.012 * frame, 0.0);
        auto inputs = testing::profile_inputs(profile_, pose, m);
        inputs.frame_index = static_cast<std::uint64_t>(frame);
        taa.render_frame(inputs);
        if (frame == 23) plain.render_frame(inputs);
    }
    for (Eye eye : {Eye::kLeft, Eye::kRight}) {
        SCOPED_TRACE(modes::eye_name(eye));
        const testing::Centroid with_taa = testing::red_centroid(taa.eye_image(eye));
        const testing::Centroid without = testing::red_centroid(plain.eye_image(eye));
        EXPECT_NEAR(with_taa.x, without.x, 0.5);
        EXPECT_NEAR(with_taa.y, without.y, 0.5);
    }
}

}  // namespace
}  // namespace monoplane
