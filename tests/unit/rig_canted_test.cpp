// The rig with canted displays (docs/hybrid.md, "Canted displays"): eyes turned by a yaw about the
// head's +y. Every expected value is derived here from a pinhole model of each camera written
// independently of rig/rig.cpp: a point's tangents in a camera turned by yaw a are
// those of R_y(-a) (p - position), and pixels follow from the tangents (rig/tangents.h).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/ext/matrix_double4x4.hpp>

#include "rig/rig.h"

namespace monoplane::rig {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr Tangents kViveLeft{-1.391937, 1.247409, -1.468819, 1.464287};
constexpr Tangents kViveRight{-1.246557, 1.398447, -1.465505, 1.472458};

double radians(double degrees) {
    return degrees * kPi / 180.0;
}

// Canted outwards by `degrees` (left eye turned left, right eye turned right); negative: inwards.
RigInputs canted_vive(double mono_plane, double degrees) {
    RigInputs in;
    in.eyes = {kViveLeft, kViveRight};
    in.eye_width = 1344;
    in.eye_height = 1512;
    in.ipd = 0.064;
    in.mono_plane = mono_plane;
    in.cant = {radians(degrees), radians(-degrees)};
    return in;
}

Rig built(const RigInputs& in) {
    Result<Rig> rig = build_rig(in);
    EXPECT_TRUE(rig.ok()) << (rig.ok() ? "" : rig.error().message);
    return rig.ok() ? rig.value() : Rig{};
}

// The independent pinhole: a camera at `position`, turned by yaw `a` (positive: left).
struct Pinhole {
    glm::dvec3 position;
    double yaw = 0.0;
    Tangents t;
    int width = 0;
    int height = 0;

    // The point in the camera's frame: rotate by -yaw about +y.
    glm::dvec3 local(const glm::dvec3& p) const {
        const glm::dvec3 d = p - position;
        const double c = std::cos(yaw), s = std::sin(yaw);
        // R_y(a) maps (x, z) -> (c x + s z, -s x + c z); its inverse (c x - s z, s x + c z).
        return {c * d.x - s * d.z, d.y, s * d.x + c * d.z};
    }
    glm::dvec2 tangents_of(const glm::dvec3& p) const {
        const glm::dvec3 q = local(p);
        return {q.x / -q.z, q.y / -q.z};
    }
    glm::dvec2 pixel(const glm::dvec3& p) const {
        const glm::dvec2 tan = tangents_of(p);
        return {(tan.x - t.left) / (t.right - t.left) * width,
                (t.up - tan.y) / (t.up - t.down) * height};
    }
    // The head-frame direction of the tangents (tan_x, tan_y).
    glm::dvec3 ray(double tan_x, double tan_y) const {
        const double c = std::cos(yaw), s = std::sin(yaw);
        return {c * tan_x - s, tan_y, -s * tan_x - c};  // R_y(a) (tan_x, tan_y, -1)
    }
};

Pinhole eye_camera(const RigInputs& in, int eye) {
    const double x = eye == kLeft ? -0.5 * in.ipd : 0.5 * in.ipd;
    return {glm::dvec3(x, 0.0, 0.0), in.cant[eye], in.eyes[eye], in.eye_width, in.eye_height};
}

// A point of eye e's field on the head's plane z = -distance.
glm::dvec3 on_plane(const Pinhole& eye, double tan_x, double tan_y, double distance) {
    const glm::dvec3 r = eye.ray(tan_x, tan_y);
    return eye.position + r * (distance / -r.z);
}

glm::dvec3 ndc_of(const glm::dmat4& m, const glm::dvec4& p) {
    const glm::dvec4 clip = m * p;
    return glm::dvec3(clip) / clip.w;
}

class CantedRig : public ::testing::TestWithParam<double> {};

INSTANTIATE_TEST_SUITE_P(Cants, CantedRig, ::testing::Values(5.0, -5.0, 15.0, -15.0),
                         [](const ::testing::TestParamInfo<double>& info) {
                             const int d = static_cast<int>(std::abs(info.param));
                             return (info.param > 0 ? "outwards_" : "inwards_") +
                                    std::to_string(d) + "_degrees";
                         });

TEST_P(CantedRig, ThePinholeModelAgreesWithItself) {
    // The test's own ray() and tangents_of() invert each other (guards the model used below).
    const Pinhole eye = eye_camera(canted_vive(8.0, GetParam()), kLeft);
    const glm::dvec2 back = eye.tangents_of(eye.position + eye.ray(0.3, -0.2));
    EXPECT_NEAR(back.x, 0.3, 1e-12);
    EXPECT_NEAR(back.y, -0.2, 1e-12);
}

TEST_P(CantedRig, EyeViewAndProjectionAreTheCantedPinholes) {
    const RigInputs in = canted_vive(8.0, GetParam());
    const Rig rig = built(in);
    for (int e : {kLeft, kRight}) {
        const Pinhole eye = eye_camera(in, e);
        for (const glm::dvec3 p : {glm::dvec3(0.5, 0.2, -3.0), glm::dvec3(-2.0, -1.0, -6.0),
                                   glm::dvec3(0.1, 0.3, -0.5)}) {
            const glm::dvec3 ndc =
                ndc_of(rig.eye_projection[e] * rig.eye_from_head[e], glm::dvec4(p, 1.0));
            const glm::dvec2 px = eye.pixel(p);
            EXPECT_NEAR((ndc.x + 1.0) * 0.5 * in.eye_width, px.x, 1e-9);
            EXPECT_NEAR((ndc.y + 1.0) * 0.5 * in.eye_height, px.y, 1e-9);
            EXPECT_NEAR(rig::eye_pixel_stereo(rig, e, p).x, px.x, 1e-9);
        }
    }
}

TEST_P(CantedRig, TheEyesFarPlaneIsTheHeadsMonoPlane) {
    const double m = 8.0;
    const RigInputs in = canted_vive(m, GetParam());
    const Rig rig = built(in);
    for (int e : {kLeft, kRight}) {
        const Pinhole eye = eye_camera(in, e);
        const glm::dmat4 world_to_clip = rig.eye_projection[e] * rig.eye_from_head[e];
        for (double tx : {in.eyes[e].left, 0.0, in.eyes[e].right}) {
            for (double ty : {in.eyes[e].down, 0.0, in.eyes[e].up}) {
                // NDC depth 0 on the head's plane z = -m, positive in front of it, negative
                // behind: the near pass keeps exactly what lies nearer than the plane.
                EXPECT_NEAR(ndc_of(world_to_clip, glm::dvec4(on_plane(eye, tx, ty, m), 1.0)).z, 0.0,
                            1e-12);
                EXPECT_GT(ndc_of(world_to_clip, glm::dvec4(on_plane(eye, tx, ty, m - 0.01), 1)).z,
                          0.0);
                EXPECT_LT(ndc_of(world_to_clip, glm::dvec4(on_plane(eye, tx, ty, m + 0.01), 1)).z,
                          0.0);
            }
        }
        // Depth 1 at the near distance on the eye's own axis.
        const glm::dvec3 axis = eye.position + eye.ray(0.0, 0.0) * in.near;
        EXPECT_NEAR(ndc_of(world_to_clip, glm::dvec4(axis, 1.0)).z, 1.0, 1e-12);
    }
}

TEST_P(CantedRig, AMarkerOnTheMonoPlaneIsExactInBothEyes) {
    const double m = 8.0;
    const RigInputs in = canted_vive(m, GetParam());
    const Rig rig = built(in);
    for (int e : {kLeft, kRight}) {
        const Pinhole eye = eye_camera(in, e);
        for (double tx : {in.eyes[e].left * 0.9, 0.0, in.eyes[e].right * 0.9}) {
            for (double ty : {in.eyes[e].down * 0.9, 0.3, in.eyes[e].up * 0.9}) {
                const glm::dvec3 marker = on_plane(eye, tx, ty, m);
                const glm::dvec2 expected = eye.pixel(marker);
                EXPECT_NEAR(eye_pixel_hybrid(rig, e, marker).x, expected.x, 1e-9);
                EXPECT_NEAR(eye_pixel_hybrid(rig, e, marker).y, expected.y, 1e-9);
                // Through the GPU's path: C's pixel of the marker (its own pinhole, unturned),
                // then the homography of eq. 5 restricted to the plane.
                const Pinhole mono{rig.mono_position, 0.0, rig.mono.tangents,
                                   rig.mono.viewport_width, rig.mono.viewport_height};
                const glm::dvec2 c_pixel = mono.pixel(marker);
                const glm::dvec3 h =
                    mono_pixel_to_eye_pixel(rig, e) * glm::dvec3(c_pixel.x, c_pixel.y, 1.0);
                EXPECT_NEAR(h.x / h.z, expected.x, 1e-6);
                EXPECT_NEAR(h.y / h.z, expected.y, 1e-6);
            }
        }
    }
}

TEST_P(CantedRig, CsFrustumHoldsBothCrossSectionsAndTouchesThem) {
    const double m = 8.0;
    const RigInputs in = canted_vive(m, GetParam());
    const Rig rig = built(in);
    const Pinhole mono{rig.mono_position, 0.0, rig.mono.tangents, 1, 1};
    double lowest_x = 1e9, highest_x = -1e9, lowest_y = 1e9, highest_y = -1e9;
    for (int e : {kLeft, kRight}) {
        const Pinhole eye = eye_camera(in, e);
        const Tangents& t = in.eyes[e];
        for (int i = 0; i <= 32; ++i) {
            for (int j = 0; j <= 32; ++j) {
                const glm::dvec2 tan =
                    mono.tangents_of(on_plane(eye, t.left + (t.right - t.left) * i / 32.0,
                                              t.down + (t.up - t.down) * j / 32.0, m));
                EXPECT_GE(tan.x, rig.mono.tangents.left - 1e-12);
                EXPECT_LE(tan.x, rig.mono.tangents.right + 1e-12);
                EXPECT_GE(tan.y, rig.mono.tangents.down - 1e-12);
                EXPECT_LE(tan.y, rig.mono.tangents.up + 1e-12);
                lowest_x = std::min(lowest_x, tan.x);
                highest_x = std::max(highest_x, tan.x);
                lowest_y = std::min(lowest_y, tan.y);
                highest_y = std::max(highest_y, tan.y);
            }
        }
    }
    // The smallest such frustum: the extremes are corners, which the grid contains.
    EXPECT_NEAR(lowest_x, rig.mono.tangents.left, 1e-12);
    EXPECT_NEAR(highest_x, rig.mono.tangents.right, 1e-12);
    EXPECT_NEAR(lowest_y, rig.mono.tangents.down, 1e-12);
    EXPECT_NEAR(highest_y, rig.mono.tangents.up, 1e-12);
}

TEST_P(CantedRig, CSitsWhereTheOuterEdgesCrossBehindTheEyes) {
    const RigInputs in = canted_vive(8.0, GetParam());
    const Rig rig = built(in);
    // The left outer edge, turned by a, leaves the eye at atan(-tan_left) + a left of -z; from
    // x = -d/2 it meets x = 0 at z = (d/2) / tan(angle) behind the eyes. The right likewise.
    const double a = radians(GetParam());
    const double left_angle = std::atan(-kViveLeft.left) + a;
    const double right_angle = std::atan(kViveRight.right) + a;
    const double expected = std::max(0.032 / std::tan(left_angle), 0.032 / std::tan(right_angle));
    EXPECT_NEAR(rig.mono.offset_behind_eyes, expected, 1e-12);
    EXPECT_NEAR(rig.mono_position.z, expected, 1e-12);
}

TEST_P(CantedRig, ErrorAtInfinityOnTheEyeAxisHasTheClosedForm) {
    // A point infinitely far along the left eye's axis (yaw a left of -z): hybrid shows C's
    // projection of it onto the plane, P' = (-(m + s) tan a, 0, -m); the eye at x_e sees P' at
    // angle atan(((m + s) tan a + x_e) / m) left of -z, i.e. at eye tangent -tan(that - a).
    const double m = 8.0;
    const RigInputs in = canted_vive(m, GetParam());
    const Rig rig = built(in);
    const double a = in.cant[kLeft];
    const double s = rig.mono.offset_behind_eyes;
    const double x_e = -0.032;
    const double seen = std::atan(((m + s) * std::tan(a) + x_e) / m);
    const double tangent_offset = -std::tan(seen - a);
    const double expected_px = tangent_offset * in.eye_width / (kViveLeft.right - kViveLeft.left);
    const Pinhole eye = eye_camera(in, kLeft);
    const glm::dvec3 far_on_axis = eye.position + eye.ray(0.0, 0.0) * 1e9;
    const double measured =
        eye_pixel_hybrid(rig, kLeft, far_on_axis).x - eye_pixel_stereo(rig, kLeft, far_on_axis).x;
    EXPECT_NEAR(measured, expected_px, 1e-5);
}

TEST_P(CantedRig, TheReportedSupremumBoundsADenserSearch) {
    // An independent brute force over a 129 x 129 grid of both fields at infinity (the 65 x 65
    // grid of the rig is a subset): the rig's maximum may not exceed it and must come within
    // half a percent of it.
    const double m = 8.0;
    const RigInputs in = canted_vive(m, GetParam());
    const Rig rig = built(in);
    const Pinhole mono{rig.mono_position, 0.0, rig.mono.tangents, 1, 1};
    double brute = 0.0;
    for (int e : {kLeft, kRight}) {
        const Pinhole eye = eye_camera(in, e);
        const Tangents& t = in.eyes[e];
        for (int i = 0; i <= 128; ++i) {
            for (int j = 0; j <= 128; ++j) {
                const double tx = t.left + (t.right - t.left) * i / 128.0;
                const double ty = t.down + (t.up - t.down) * j / 128.0;
                const glm::dvec3 r = eye.ray(tx, ty);
                // Where C's ray parallel to r meets the plane: what hybrid shows at infinity.
                const glm::dvec3 shown = mono.position + r * ((m + mono.position.z) / -r.z);
                const glm::dvec2 truth((tx - t.left) / (t.right - t.left) * in.eye_width, 0.0);
                brute = std::max(brute, std::abs(eye.pixel(shown).x - truth.x));
            }
        }
    }
    EXPECT_LE(rig.max_error_px, brute + 1e-9);
    EXPECT_GE(rig.max_error_px, 0.995 * brute);
    // Finite depths grow towards it: zero at m, below the supremum beyond.
    EXPECT_EQ(error_at_depth(rig, m).horizontal_px, 0.0);
    const double at_20 = error_at_depth(rig, 20.0).horizontal_px;
    const double at_200 = error_at_depth(rig, 200.0).horizontal_px;
    EXPECT_GT(at_20, 0.0);
    EXPECT_LT(at_20, at_200);
    EXPECT_LE(at_200, rig.max_error_px + 1e-9);
}

// C's pixel size: one C pixel, stepped along the plane from the point on each eye's own axis,
// covers at least one eye pixel in both eyes and exactly one in the finer eye (per axis): the
// eyes and C match where each eye looks straight ahead (rig.cpp explains why not everywhere).
TEST_P(CantedRig, CsPixelsMatchTheFinerEyeOnItsAxis) {
    const double m = 8.0;
    const RigInputs in = canted_vive(m, GetParam());
    const Rig rig = built(in);
    const Pinhole mono{rig.mono_position, 0.0, rig.mono.tangents, 1, 1};
    const double dist = m + mono.position.z;
    const double step_x = (rig.mono.tangents.right - rig.mono.tangents.left) / rig.mono.width;
    const double step_y = (rig.mono.tangents.up - rig.mono.tangents.down) / rig.mono.height;
    glm::dvec2 finer(1e9);
    for (int e : {kLeft, kRight}) {
        const Pinhole eye = eye_camera(in, e);
        const glm::dvec3 p = on_plane(eye, 0.0, 0.0, m);
        const glm::dvec2 ct = mono.tangents_of(p);
        const glm::dvec3 right(mono.position.x + (ct.x + step_x) * dist, p.y, -m);
        const glm::dvec3 up(p.x, mono.position.y + (ct.y + step_y) * dist, -m);
        const glm::dvec2 covered(std::abs(eye.pixel(right).x - eye.pixel(p).x),
                                 std::abs(eye.pixel(up).y - eye.pixel(p).y));
        EXPECT_GE(covered.x, 1.0 - 1e-3);
        EXPECT_GE(covered.y, 1.0 - 1e-3);
        finer = glm::min(finer, covered);
    }
    // A step of one pixel is a finite difference of the homography: within 0.1 % of the
    // derivative the rig matches.
    EXPECT_NEAR(finer.x, 1.0, 1e-3);
    EXPECT_NEAR(finer.y, 1.0, 1e-3);
}

TEST_P(CantedRig, TheNearestPlaneDepthIsTheLargestOverTheCrossSection) {
    const double m = 8.0;
    const RigInputs in = canted_vive(m, GetParam());
    const Rig rig = built(in);
    const double distance = m - rig.overlap;
    const double reported = nearest_eye_depth_of_plane(rig, distance);
    double largest = -1.0;
    for (int e : {kLeft, kRight}) {
        const Pinhole eye = eye_camera(in, e);
        const Tangents& t = in.eyes[e];
        for (int i = 0; i <= 16; ++i) {
            for (int j = 0; j <= 16; ++j) {
                const glm::dvec3 p = on_plane(eye, t.left + (t.right - t.left) * i / 16.0,
                                              t.down + (t.up - t.down) * j / 16.0, distance);
                largest = std::max(
                    largest,
                    ndc_of(rig.eye_projection[e] * rig.eye_from_head[e], glm::dvec4(p, 1.0)).z);
            }
        }
    }
    EXPECT_NEAR(reported, largest, 1e-12);
    EXPECT_GT(reported, 0.0);
}

TEST_P(CantedRig, BeyondTheFarPlaneCIsSkippedAndTheEyesAreStereo) {
    RigInputs in = canted_vive(1000.0, GetParam());
    const Rig rig = built(in);
    EXPECT_TRUE(rig.mono_skipped);
    EXPECT_EQ(rig.max_error_px, 0.0);
    const Pinhole eye = eye_camera(in, kRight);
    const glm::dvec3 p(3.0, 1.0, -500.0);
    const glm::dvec3 ndc =
        ndc_of(rig.eye_projection[kRight] * rig.eye_from_head[kRight], glm::dvec4(p, 1.0));
    EXPECT_NEAR((ndc.x + 1.0) * 0.5 * in.eye_width, eye.pixel(p).x, 1e-8);
    EXPECT_GT(ndc.z, 0.0);  // far plane f = 1000: 500 m is inside the eye's range
    EXPECT_EQ(eye_pixel_hybrid(rig, kRight, p), eye_pixel_stereo(rig, kRight, p));
}

TEST(CantedRigRefusals, ImplausibleCantsAreRefusedWithTheReason) {
    RigInputs in = canted_vive(8.0, 46.0);
    Result<Rig> rig = build_rig(in);
    ASSERT_FALSE(rig);
    EXPECT_NE(rig.error().message.find("cant[left]"), std::string::npos) << rig.error().message;
    // 40 degrees outwards puts the Vive's outer edge (54 degrees) at 94 degrees from forward.
    rig = build_rig(canted_vive(8.0, 40.0));
    ASSERT_FALSE(rig);
    EXPECT_NE(rig.error().message.find("beyond 84 degrees"), std::string::npos)
        << rig.error().message;
    // Inwards past the outer edge: a narrow field turned in by more than its outer half-angle.
    in = canted_vive(8.0, -40.0);
    in.eyes = {Tangents{-0.7, 1.0, -1.0, 1.0}, Tangents{-1.0, 0.7, -1.0, 1.0}};  // 35 degrees out
    rig = build_rig(in);
    ASSERT_FALSE(rig);
    EXPECT_NE(rig.error().message.find("turned inwards"), std::string::npos) << rig.error().message;
    in = canted_vive(8.0, 5.0);
    in.cant[kRight] = std::nan("");
    rig = build_rig(in);
    ASSERT_FALSE(rig);
    EXPECT_NE(rig.error().message.find("cant[right] is not a finite number"), std::string::npos);
}

TEST(CantedRigParallel, ZeroCantIsTheParallelRigBitForBit) {
    // Covered in depth by rig_test; here only that the cant field at zero changes nothing.
    RigInputs parallel = canted_vive(8.0, 0.0);
    const Rig a = built(parallel);
    EXPECT_FALSE(is_canted(parallel));
    parallel.cant = {0.0, -0.0};
    const Rig b = built(parallel);
    EXPECT_EQ(a.max_error_px, b.max_error_px);
    EXPECT_EQ(a.mono.viewport_width, b.mono.viewport_width);
    EXPECT_NEAR(a.max_error_px, 3.9, 0.1);  // docs/hybrid.md: 3.862 px at m = 8
}

}  // namespace
}  // namespace monoplane::rig
