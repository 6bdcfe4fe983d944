// The eye projection checked against the tangent definition of a frustum (rig/tangents.h),
// computed here by hand rather than through the matrix code.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/ext/matrix_double4x4.hpp>

#include "rig/pose.h"
#include "rig/projection.h"

namespace monoplane::rig {
namespace {

// The Vive's left eye as quoted by Fink et al. 2019 (XrFovf convention).
constexpr Tangents kViveLeft{-1.391937, 1.247409, -1.468819, 1.464287};

glm::dvec3 project(const glm::dmat4& m, const glm::dvec3& p) {
    const glm::dvec4 clip = m * glm::dvec4(p, 1.0);
    return glm::dvec3(clip) / clip.w;
}

TEST(RigProjection, FrustumEdgesMapToNdcEdges) {
    const glm::dmat4 p = projection_reversed_z(kViveLeft, 0.1, 1000.0);
    const double z = -7.0;
    // A point on the left plane has x / -z = tan_left: NDC x = -1. Vulkan's y points down, so
    // the top plane (tan_up) maps to NDC y = -1.
    EXPECT_NEAR(project(p, {kViveLeft.left * 7.0, 0.0, z}).x, -1.0, 1e-12);
    EXPECT_NEAR(project(p, {kViveLeft.right * 7.0, 0.0, z}).x, 1.0, 1e-12);
    EXPECT_NEAR(project(p, {0.0, kViveLeft.up * 7.0, z}).y, -1.0, 1e-12);
    EXPECT_NEAR(project(p, {0.0, kViveLeft.down * 7.0, z}).y, 1.0, 1e-12);
}

TEST(RigProjection, ReversedZDepth) {
    const double n = 0.1;
    const double f = 1000.0;
    const glm::dmat4 p = projection_reversed_z(kViveLeft, n, f);
    EXPECT_NEAR(project(p, {0, 0, -n}).z, 1.0, 1e-12);
    EXPECT_NEAR(project(p, {0, 0, -f}).z, 0.0, 1e-12);
    // In between: depth = n (f - d) / (d (f - n)) for distance d, derived from the two limits.
    for (double d : {0.5, 3.0, 39.5, 500.0}) {
        EXPECT_NEAR(project(p, {0, 0, -d}).z, n * (f - d) / (d * (f - n)), 1e-12) << d;
    }
}

TEST(RigProjection, PixelOfAPointMatchesTangentArithmetic) {
    const glm::dmat4 p = projection_reversed_z(kViveLeft, 0.1, 1000.0);
    const double width = 1344.0;
    const double height = 1512.0;
    const glm::dvec3 point(0.37, -0.21, -5.3);
    const glm::dvec3 ndc = project(p, point);
    const double tx = point.x / -point.z;
    const double ty = point.y / -point.z;
    const double px = (tx - kViveLeft.left) / (kViveLeft.right - kViveLeft.left) * width;
    const double py = (kViveLeft.up - ty) / (kViveLeft.up - kViveLeft.down) * height;
    EXPECT_NEAR((ndc.x * 0.5 + 0.5) * width, px, 1e-9);
    EXPECT_NEAR((ndc.y * 0.5 + 0.5) * height, py, 1e-9);
}

TEST(RigPose, EyeViewMatrixMovesTheEyeToTheOrigin) {
    Pose head;
    head.position = {1.0, 1.7, 2.0};
    head.orientation = orientation_from_yaw_pitch(0.5, -0.2);
    const glm::dvec3 offset(-0.032, 0.0, 0.0);
    const glm::dmat4 view = view_matrix(head, offset);
    const glm::dvec3 eye_world = glm::dvec3(to_matrix(head) * glm::dvec4(offset, 1.0));
    const glm::dvec4 at_origin = view * glm::dvec4(eye_world, 1.0);
    EXPECT_NEAR(glm::length(glm::dvec3(at_origin)), 0.0, 1e-12);
    // Yaw turns left: +0.5 rad about +y rotates -z towards -x.
    const glm::dvec3 forward = glm::dvec3(to_matrix(head) * glm::dvec4(0, 0, -1, 0));
    EXPECT_NEAR(forward.x, -std::sin(0.5) * std::cos(-0.2), 1e-12);
    EXPECT_NEAR(forward.y, std::sin(-0.2), 1e-12);
}

}  // namespace
}  // namespace monoplane::rig
