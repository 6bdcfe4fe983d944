// TAA's camera math (rig/temporal_jitter.h, eq. 9 in rig.h) and scripted head motion
// (rig/pose_path.h), against values derived here from the geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <glm/ext/matrix_double4x4.hpp>

#include "rig/pose_path.h"
#include "rig/projection.h"
#include "rig/rig.h"
#include "rig/temporal_jitter.h"

namespace monoplane::rig {
namespace {

constexpr Tangents kViveLeft{-1.391937, 1.247409, -1.468819, 1.464287};
constexpr Tangents kViveRight{-1.246557, 1.398447, -1.465505, 1.472458};

TEST(HaltonJitter, FirstOffsetsAreTheRadicalInversesAroundThePixelCentre) {
    // Halton index 1, 2, 3 in bases 2 and 3: (1/2, 1/3), (1/4, 2/3), (3/4, 1/9).
    EXPECT_NEAR(halton_jitter(0).x, 0.0, 1e-12);
    EXPECT_NEAR(halton_jitter(0).y, 1.0 / 3.0 - 0.5, 1e-12);
    EXPECT_NEAR(halton_jitter(1).x, -0.25, 1e-12);
    EXPECT_NEAR(halton_jitter(1).y, 2.0 / 3.0 - 0.5, 1e-12);
    EXPECT_NEAR(halton_jitter(2).x, 0.25, 1e-12);
    EXPECT_NEAR(halton_jitter(2).y, 1.0 / 9.0 - 0.5, 1e-12);
    EXPECT_EQ(halton_jitter(kJitterPeriod + 5), halton_jitter(5));
}

TEST(HaltonJitter, APeriodCoversThePixelEvenly) {
    glm::dvec2 sum(0.0);
    std::set<std::pair<int, int>> quadrants;
    for (std::uint64_t i = 0; i < kJitterPeriod; ++i) {
        const glm::dvec2 j = halton_jitter(i);
        ASSERT_GT(j.x, -0.5);
        ASSERT_LT(j.x, 0.5);
        ASSERT_GT(j.y, -0.5);
        ASSERT_LT(j.y, 0.5);
        sum += j;
        quadrants.insert({j.x < 0.0, j.y < 0.0});
    }
    // Halton points 1..16 in base 2: 1/16 .. 15/16 once each (sum 7.5), then 1/32.
    EXPECT_NEAR(sum.x / kJitterPeriod, (7.5 + 1.0 / 32.0) / 16.0 - 0.5, 1e-12);
    EXPECT_LT(std::abs(sum.y / kJitterPeriod), 1.0 / 16.0);
    EXPECT_EQ(quadrants.size(), 4u);
}

TEST(JitterMatrix, MovesTheImageByTheOffsetInPixels) {
    const glm::dmat4 projection = projection_reversed_z(kViveLeft, 0.1, 100.0);
    const glm::dvec2 viewport(200.0, 240.0);
    const glm::dvec2 jitter(0.3, -0.4);
    const glm::dvec4 point(0.7, -0.2, -5.0, 1.0);
    auto pixel = [&](const glm::dmat4& m) {
        const glm::dvec4 clip = m * point;
        return (glm::dvec2(clip) / clip.w + 1.0) * 0.5 * viewport;
    };
    const glm::dvec2 moved = pixel(jitter_matrix(jitter, viewport) * projection);
    const glm::dvec2 before = pixel(projection);
    EXPECT_NEAR(moved.x - before.x, 0.3, 1e-9);
    EXPECT_NEAR(moved.y - before.y, -0.4, 1e-9);
    // Depth is untouched.
    const glm::dvec4 a = jitter_matrix(jitter, viewport) * projection * point;
    const glm::dvec4 b = projection * point;
    EXPECT_NEAR(a.z / a.w, b.z / b.w, 1e-15);
}

TEST(JitterMatrix, ConjugatedPixelMappingMapsJitteredPixels) {
    // An affine pixel mapping: scale 0.9, shift (12, -3).
    glm::dmat3 h(1.0);
    h[0][0] = 0.9;
    h[1][1] = 0.9;
    h[2][0] = 12.0;
    h[2][1] = -3.0;
    const glm::dvec2 j(0.25, -0.1);
    const glm::dmat3 hj = jittered_pixel_mapping(h, j);
    // A point at pixel p in the unjittered source is at p + j in the jittered source, and at
    // h(p) + j in the jittered target.
    const glm::dvec2 p(40.0, 17.0);
    const glm::dvec3 target = hj * glm::dvec3(p + j, 1.0);
    EXPECT_NEAR(target.x / target.z, 0.9 * 40.0 + 12.0 + 0.25, 1e-12);
    EXPECT_NEAR(target.y / target.z, 0.9 * 17.0 - 3.0 - 0.1, 1e-12);
}

// Eq. 9 from the frusta alone: C's NDC spans its frustum's width at the mono plane, (tan_right -
// tan_left)(m + s) metres; the eye's NDC spans (tan_right - tan_left) m. A C-NDC velocity v is
// v (tan_r - tan_l)_C (m + s) / 2 metres at the plane, which is that times 2 / ((tan_r -
// tan_l)_E m) in the eye's NDC.
TEST(MonoVelocity, Eq9ScaleFollowsFromTheFrustaAtTheMonoPlane) {
    for (double m : {1.6, 8.0, 39.5}) {
        RigInputs in;
        in.eyes = {kViveLeft, kViveRight};
        in.eye_width = 1344;
        in.eye_height = 1512;
        in.mono_plane = m;
        const Rig rig = build_rig(in).value_or_throw();
        const double s = rig.mono.offset_behind_eyes;
        const Tangents& c = rig.mono.tangents;
        for (int e : {kLeft, kRight}) {
            const Tangents& eye = in.eyes[e];
            const glm::dvec2 scale = mono_velocity_to_eye(rig, e);
            EXPECT_NEAR(scale.x, (c.right - c.left) * (m + s) / ((eye.right - eye.left) * m), 1e-9)
                << "m " << m << " eye " << e;
            EXPECT_NEAR(scale.y, (c.up - c.down) * (m + s) / ((eye.up - eye.down) * m), 1e-9);
            // C's frustum contains the eye's cross-section, so C's NDC units are longer.
            EXPECT_GT(scale.x, 1.0);
        }
    }
    RigInputs skipped;
    skipped.eyes = {kViveLeft, kViveRight};
    skipped.eye_width = skipped.eye_height = 100;
    skipped.mono_plane = 2000.0;
    EXPECT_EQ(mono_velocity_to_eye(build_rig(skipped).value_or_throw(), kLeft), glm::dvec2(1.0));
}

TEST(PosePath, BuiltInPathsMoveRelativeToTheStartPose) {
    Pose start;
    start.position = {1.0, 1.6, -2.0};
    start.orientation = orientation_from_yaw_pitch(glm::radians(90.0), 0.0);  // looks down -x
    const PosePath sway = *builtin_pose_path("sway");
    // At 0.5 s the head is 2 cm to its own right: start's right is -z after the yaw.
    const Pose half = pose_along(sway, start, 0.5);
    EXPECT_NEAR(half.position.x, 1.0, 1e-12);
    EXPECT_NEAR(half.position.z, -2.0 - 0.02, 1e-12);
    // The path repeats every 2 s, and at its keyframes it is exact.
    const Pose again = pose_along(sway, start, 2.5);
    EXPECT_NEAR(glm::length(again.position - half.position), 0.0, 1e-12);
    EXPECT_NEAR(pose_along(sway, start, 0.0).position.z, -2.0, 1e-12);
    // Turn: 15 degrees of yaw at 0.5 s, on top of the start's 90.
    const Pose turned = pose_along(*builtin_pose_path("turn"), start, 0.5);
    const glm::dvec3 forward = turned.orientation * glm::dvec3(0.0, 0.0, -1.0);
    EXPECT_NEAR(std::atan2(-forward.x, -forward.z), glm::radians(105.0), 1e-9);
    // Static stays put.
    const Pose still = pose_along(*builtin_pose_path("static"), start, 7.3);
    EXPECT_EQ(still.position, start.position);
    EXPECT_FALSE(builtin_pose_path("dance").has_value());
}

}  // namespace
}  // namespace monoplane::rig
