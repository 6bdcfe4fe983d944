// The gaze point in the mirrored eye's image (app/window/gaze_marker.h), against values worked
// out by hand: u = (tan_x - left) / (right - left), v = (up - tan_y) / (up - down), with tan_x and
// tan_y the direction's tangents in the eye's own (canted) frame.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>

#include "app/window/gaze_marker.h"

namespace monoplane::window {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr rig::Tangents kSquare{-1.0, 1.0, -1.0, 1.0};  // 90 degrees each way

double radians(double degrees) {
    return degrees * kPi / 180.0;
}

void expect_uv(const std::optional<ImageUv>& uv, double u, double v) {
    ASSERT_TRUE(uv.has_value());
    EXPECT_NEAR((*uv)[0], u, 1e-12);
    EXPECT_NEAR((*uv)[1], v, 1e-12);
}

TEST(GazeInEyeImage, StraightAheadIsTheCentreOfASymmetricFrustum) {
    expect_uv(gaze_in_eye_image({0.0, 0.0, -1.0}, 0.0, kSquare), 0.5, 0.5);
}

TEST(GazeInEyeImage, TangentsMapLinearlyAcrossTheImage) {
    // tan 0.5 to the right: three quarters across; tan 0.5 up: a quarter down.
    expect_uv(gaze_in_eye_image(glm::normalize(glm::dvec3(0.5, 0.0, -1.0)), 0.0, kSquare), 0.75,
              0.5);
    expect_uv(gaze_in_eye_image(glm::normalize(glm::dvec3(0.0, 0.5, -1.0)), 0.0, kSquare), 0.5,
              0.25);
    // The corner (tan -1, tan -1): bottom left.
    expect_uv(gaze_in_eye_image(glm::normalize(glm::dvec3(-1.0, -1.0, -1.0)), 0.0, kSquare), 0.0,
              1.0);
}

TEST(GazeInEyeImage, AnAsymmetricFrustumPutsAheadOffCentre) {
    const rig::Tangents asymmetric{-1.2, 0.8, -1.0, 0.5};
    // Ahead: 1.2 of the 2.0 across, 0.5 of the 1.5 down.
    expect_uv(gaze_in_eye_image({0.0, 0.0, -1.0}, 0.0, asymmetric), 0.6, 1.0 / 3.0);
    // tan 0.25 up: (0.5 - 0.25) / 1.5 down.
    expect_uv(gaze_in_eye_image(glm::normalize(glm::dvec3(0.0, 0.25, -1.0)), 0.0, asymmetric), 0.6,
              1.0 / 6.0);
}

TEST(GazeInEyeImage, ACantedEyeSeesAheadToTheSide) {
    // The left eye turned 15 degrees outwards (left): the head's ahead lies tan 15 degrees to
    // the right of its axis, (0.267949 + 1) / 2 across.
    const double cant = radians(15.0);
    expect_uv(gaze_in_eye_image({0.0, 0.0, -1.0}, cant, kSquare), (std::tan(cant) + 1.0) / 2.0,
              0.5);
    EXPECT_NEAR((*gaze_in_eye_image({0.0, 0.0, -1.0}, cant, kSquare))[0], 0.6339746, 1e-7);
    // A gaze 15 degrees left and 20 up lies on the eye's vertical: x in the eye's frame is
    // -sin15 cos20 cos15 + cos20 cos15 sin15 = 0, ahead cos20, so tan_y = tan 20 = 0.3639702.
    const glm::dvec3 left_and_up(-std::sin(cant) * std::cos(radians(20.0)), std::sin(radians(20.0)),
                                 -std::cos(cant) * std::cos(radians(20.0)));
    const std::optional<ImageUv> uv = gaze_in_eye_image(left_and_up, cant, kSquare);
    expect_uv(uv, 0.5, (1.0 - std::tan(radians(20.0))) / 2.0);
    EXPECT_NEAR((*uv)[1], (1.0 - 0.3639702) / 2.0, 1e-7);
}

TEST(GazeInEyeImage, BeyondTheFieldIsOutsideTheUnitSquare) {
    // tan 2 to the right of a frustum reaching tan 1: u = 1.5.
    expect_uv(gaze_in_eye_image(glm::normalize(glm::dvec3(2.0, 0.0, -1.0)), 0.0, kSquare), 1.5,
              0.5);
}

TEST(GazeInEyeImage, BesideOrBehindTheEyeHasNoImagePoint) {
    EXPECT_FALSE(gaze_in_eye_image({0.0, 0.0, 1.0}, 0.0, kSquare).has_value());
    EXPECT_FALSE(gaze_in_eye_image({1.0, 0.0, 0.0}, 0.0, kSquare).has_value());
    // Ahead of the head but beside an eye canted 90 degrees left: its axis is the head's -x.
    EXPECT_FALSE(gaze_in_eye_image({0.0, 0.0, -1.0}, radians(90.0), kSquare).has_value());
}

}  // namespace
}  // namespace monoplane::window
