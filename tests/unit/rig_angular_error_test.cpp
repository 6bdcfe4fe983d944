// The rig's error in visual angle and the error budget (rig/angular_error.h,
// error_budget.h; issue 20 item 1). The expectations are derived here from the geometry of
// Fig. 2 alone: C at s = max(d / (2 (-l_L)), d / (2 r_R)) behind the eyes (eq. 1), a point seen
// through C's central projection onto the plane z = -m, and brute-force maxima over dense
// samples of the fields; nothing is taken from the code under test.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "rig/angular_error.h"
#include "rig/error_budget.h"
#include "rig/rig.h"

namespace monoplane::rig {
namespace {

constexpr double kArcmin = 60.0 * 180.0 / 3.14159265358979323846;
constexpr double kInf = std::numeric_limits<double>::infinity();

// The paper's HTC Vive calibration (papers/000 Sect. 4.2).
RigInputs vive(double m, int width = 1344, int height = 1512) {
    RigInputs in;
    in.eyes[kLeft] = {-1.391937, 1.247409, -1.468819, 1.464287};
    in.eyes[kRight] = {-1.246557, 1.398447, -1.465505, 1.472458};
    in.eye_width = width;
    in.eye_height = height;
    in.ipd = 0.064;
    in.mono_plane = m;
    return in;
}

double offset_behind_eyes(const RigInputs& in) {
    return std::max(in.ipd / (2.0 * -in.eyes[kLeft].left), in.ipd / (2.0 * in.eyes[kRight].right));
}

// Eye e's horizontal angle error for its direction t at depth z (infinity allowed): the point
// (x_e + t z, ., -z), its central projection from C = (0, 0, s) onto z = -m, seen by the eye.
double eye_error(const RigInputs& in, int eye, double t, double z) {
    const double s = offset_behind_eyes(in), m = in.mono_plane;
    const double x_e = eye == kLeft ? -in.ipd / 2 : in.ipd / 2;
    const double on_plane = std::isinf(z) ? t * (m + s) : (x_e + t * z) * (m + s) / (z + s);
    return std::abs(std::atan((on_plane - x_e) / m) - std::atan(t));
}

double brute_eye_error(const RigInputs& in, double z) {
    double worst = 0.0;
    for (int eye : {kLeft, kRight}) {
        const Tangents& f = in.eyes[eye];
        constexpr int kSamples = 400001;
        for (int i = 0; i < kSamples; ++i) {
            worst = std::max(
                worst, eye_error(in, eye, f.left + (f.right - f.left) * i / (kSamples - 1), z));
        }
    }
    return worst * kArcmin;
}

// The change of disparity of the point in cyclopean direction u at depth z, or -1 where an eye
// does not see it.
double disparity_change(const RigInputs& in, double u, double z) {
    const double s = offset_behind_eyes(in), m = in.mono_plane, d = in.ipd;
    const double x = std::isinf(z) ? 0.0 : u * z;  // the point's x (at infinity: a direction)
    const double on_plane = std::isinf(z) ? u * (m + s) : x * (m + s) / (z + s);
    double change = 0.0;
    for (int eye : {kLeft, kRight}) {
        const double x_e = eye == kLeft ? -d / 2 : d / 2;
        const double t = std::isinf(z) ? u : (x - x_e) / z;
        if (t < in.eyes[eye].left || t > in.eyes[eye].right) return -1.0;
        const double shown = std::atan((on_plane - x_e) / m) - std::atan(t);
        change += eye == kLeft ? shown : -shown;
    }
    return std::abs(change);
}

double brute_disparity_error(const RigInputs& in, double z) {
    double worst = 0.0;
    constexpr int kSamples = 400001;
    for (int i = 0; i < kSamples; ++i) {
        worst = std::max(worst, disparity_change(in, -1.5 + 3.0 * i / (kSamples - 1), z));
    }
    return worst * kArcmin;
}

TEST(RigAngularError, ViveAtEightMetresMatchesTheGeometry) {
    const Rig rig = build_rig(vive(8.0)).value_or_throw();
    const AngularError error = max_angular_error(rig);
    EXPECT_NEAR(error.eye_arcmin, brute_eye_error(rig.inputs, kInf), 1e-6);
    EXPECT_NEAR(error.eye_arcmin, 15.3, 0.05);  // docs/hybrid.md: 15.32 at m = 8
    // At infinity both eyes see direction u at the plane point u (m + s): the change is
    // atan((u (m + s) + d/2) / m) - atan((u (m + s) - d/2) / m), largest at u = 0: 2 atan(d/2m).
    EXPECT_NEAR(error.disparity_arcmin, 2.0 * std::atan(0.064 / 16.0) * kArcmin, 1e-7);
    EXPECT_NEAR(error.disparity_arcmin, brute_disparity_error(rig.inputs, kInf), 1e-6);
    EXPECT_NEAR(error.disparity_arcmin, 27.5, 0.05);
}

TEST(RigAngularError, ArcminutesAreTheSameOnAViveProWherePixelsAreNot) {
    // The Vive Pro reuses the Vive's tangents at 2352 x 2612 (hmd/profiles/vive-pro.toml).
    const Rig vive_rig = build_rig(vive(8.0)).value_or_throw();
    const Rig pro_rig = build_rig(vive(8.0, 2352, 2612)).value_or_throw();
    EXPECT_NEAR(pro_rig.max_error_px / vive_rig.max_error_px, 2352.0 / 1344.0, 1e-9);
    const AngularError a = max_angular_error(vive_rig), b = max_angular_error(pro_rig);
    EXPECT_DOUBLE_EQ(a.eye_arcmin, b.eye_arcmin);
    EXPECT_DOUBLE_EQ(a.disparity_arcmin, b.disparity_arcmin);
}

TEST(RigAngularError, FiniteDepthsAgreeWithTheGeometryAndGrowTowardsTheSupremum) {
    for (const double m : {1.6, 8.0, 39.5}) {
        const Rig rig = build_rig(vive(m)).value_or_throw();
        double previous = 0.0;
        for (const double factor : {1.0, 1.01, 1.5, 3.0, 10.0, 100.0}) {
            const double z = m * factor;
            SCOPED_TRACE("m " + std::to_string(m) + " z " + std::to_string(z));
            const AngularError error = angular_error_at_depth(rig, z);
            if (factor == 1.0) {
                EXPECT_EQ(error.eye_arcmin, 0.0);  // at the plane hybrid is exact
                EXPECT_EQ(error.disparity_arcmin, 0.0);
                continue;
            }
            EXPECT_NEAR(error.eye_arcmin, brute_eye_error(rig.inputs, z), 1e-6);
            EXPECT_NEAR(error.disparity_arcmin, brute_disparity_error(rig.inputs, z), 1e-5);
            EXPECT_GT(error.eye_arcmin, previous);
            previous = error.eye_arcmin;
        }
        EXPECT_LT(previous, max_angular_error(rig).eye_arcmin);
    }
}

TEST(RigAngularError, ZeroWhereHybridIsStereo) {
    const Rig rig = build_rig(vive(8.0)).value_or_throw();
    EXPECT_EQ(angular_error_at_depth(rig, 5.0).eye_arcmin, 0.0);
    const Rig skipped = build_rig(vive(1000.0)).value_or_throw();
    EXPECT_EQ(max_angular_error(skipped).eye_arcmin, 0.0);
    EXPECT_EQ(max_angular_error(skipped).disparity_arcmin, 0.0);
}

// Canted eyes (+-15 degrees): each eye's horizontal angle in its own frame, brute force over a
// 301 x 301 grid of its field with the turned eye written out here.
TEST(RigAngularError, CantedEyesAgreeWithABruteForceOverTheField) {
    RigInputs in = vive(8.0);
    in.eyes[kLeft] = {-1.2, 0.9, -1.2, 1.2};
    in.eyes[kRight] = {-0.9, 1.2, -1.2, 1.2};
    const double cant = 15.0 * 3.14159265358979323846 / 180.0;
    in.cant = {cant, -cant};
    const Rig rig = build_rig(in).value_or_throw();
    const glm::dvec3 c = rig.mono_position;  // checked against eq. 1 by rig_canted_test
    double worst = 0.0;
    for (int eye : {kLeft, kRight}) {
        const double a = in.cant[eye];
        const double x_e = eye == kLeft ? -in.ipd / 2 : in.ipd / 2;
        const Tangents& f = in.eyes[eye];
        for (int i = 0; i <= 300; ++i) {
            for (int j = 0; j <= 300; ++j) {
                const double tx = f.left + (f.right - f.left) * i / 300.0;
                const double ty = f.down + (f.up - f.down) * j / 300.0;
                // Eye frame (tx, ty, -1) turned by the yaw a (positive: towards -x).
                const glm::dvec3 r(tx * std::cos(a) - std::sin(a), ty,
                                   -tx * std::sin(a) - std::cos(a));
                const glm::dvec3 q = c + r * ((8.0 + c.z) / -r.z);  // on the plane z = -8
                const glm::dvec3 v = q - glm::dvec3(x_e, 0, 0);
                // Back into the eye's frame: the inverse yaw.
                const double vx = v.x * std::cos(a) - v.z * std::sin(a);
                const double vz = v.x * std::sin(a) + v.z * std::cos(a);
                worst = std::max(worst, std::abs(std::atan(vx / -vz) - std::atan(tx)));
            }
        }
    }
    const AngularError error = max_angular_error(rig);
    EXPECT_GT(worst * kArcmin, 5.0);  // a real error: the turned eyes see C's plane obliquely
    EXPECT_NEAR(error.eye_arcmin, worst * kArcmin, 0.01);
    EXPECT_GE(error.eye_arcmin, worst * kArcmin - 1e-9);  // the refined maximum is no lower
}

// The error where the gaze rests (angular_error_at_point): a point straight ahead of the eyes'
// midpoint shows on the plane at (0, 0, -m) whatever s is, so each eye's error is
// atan(d / 2m) - atan(d / 2z), and atan(d / 2m) at infinity.
TEST(RigPointError, StraightAheadIsTheDifferenceOfTwoArctangents) {
    const Rig rig = build_rig(vive(3.0)).value_or_throw();
    for (const double z : {3.5, 12.0, 250.0}) {
        const double expected = (std::atan(0.032 / 3.0) - std::atan(0.032 / z)) * kArcmin;
        const PointAngularError error = angular_error_at_point(rig, {0.0, 0.0, -z});
        EXPECT_NEAR(error.eye_arcmin[kLeft], expected, 1e-9) << z;
        EXPECT_NEAR(error.eye_arcmin[kRight], expected, 1e-9) << z;
    }
    // A beam 12 m ahead in a hybrid trial at m = 3: 27.50 arcmin, 3/4 of the 36.67 at infinity.
    EXPECT_NEAR(angular_error_at_point(rig, {0.0, 0.0, -12.0}).larger_arcmin(), 27.5006, 1e-3);
    EXPECT_NEAR(angular_error_in_direction(rig, {0.0, 0.0, -1.0}).larger_arcmin(),
                std::atan(0.032 / 3.0) * kArcmin, 1e-9);
}

// In the eyes' horizontal plane the error is the horizontal one of eye_error above, for points
// at any direction and depth, infinity included.
TEST(RigPointError, InTheEyesPlaneItIsTheHorizontalGeometry) {
    const RigInputs in = vive(8.0);
    const Rig rig = build_rig(in).value_or_throw();
    for (const double x : {-9.0, -2.0, 0.5, 6.0}) {
        for (const double z : {8.5, 20.0, 400.0}) {
            const glm::dvec3 point(x, 0.0, -z);
            const PointAngularError error = angular_error_at_point(rig, point);
            for (int eye : {kLeft, kRight}) {
                const double x_e = eye == kLeft ? -in.ipd / 2 : in.ipd / 2;
                EXPECT_NEAR(error.eye_arcmin[eye], eye_error(in, eye, (x - x_e) / z, z) * kArcmin,
                            1e-9)
                    << x << " " << z << " eye " << eye;
            }
        }
        const double t = x / 10.0;
        const PointAngularError sky = angular_error_in_direction(rig, {t, 0.0, -1.0});
        for (int eye : {kLeft, kRight})
            EXPECT_NEAR(sky.eye_arcmin[eye], eye_error(in, eye, t, kInf) * kArcmin, 1e-9) << t;
    }
}

// Off the eyes' plane the vertical offset counts: the angle between the directions through the
// pixels where the rig's projections put the point in stereo and in hybrid (eye_pixel_stereo,
// eye_pixel_hybrid, through the projection matrices), for parallel and canted eyes.
TEST(RigPointError, OffThePlaneItIsTheAngleBetweenTheTwoPixelsDirections) {
    RigInputs canted = vive(4.0);
    canted.eyes[kLeft] = {-1.2, 0.9, -1.2, 1.2};
    canted.eyes[kRight] = {-0.9, 1.2, -1.2, 1.2};
    canted.cant = {0.2, -0.2};
    for (const RigInputs& in : {vive(4.0), canted}) {
        const Rig rig = build_rig(in).value_or_throw();
        const glm::dvec3 point(3.0, 2.5, -9.0);
        const PointAngularError error = angular_error_at_point(rig, point);
        for (int eye : {kLeft, kRight}) {
            const Tangents& f = in.eyes[eye];
            // Pixel (x right, y down) -> the eye's own direction (tx, ty, -1).
            const auto direction = [&](const glm::dvec2& pixel) {
                return glm::dvec3(f.left + (f.right - f.left) * pixel.x / in.eye_width,
                                  f.up - (f.up - f.down) * pixel.y / in.eye_height, -1.0);
            };
            const glm::dvec3 a = direction(eye_pixel_stereo(rig, eye, point));
            const glm::dvec3 b = direction(eye_pixel_hybrid(rig, eye, point));
            const double expected =
                std::acos(glm::dot(a, b) / (glm::length(a) * glm::length(b))) * kArcmin;
            EXPECT_GT(expected, 1.0);
            EXPECT_NEAR(error.eye_arcmin[eye], expected, 1e-4) << "eye " << eye;
        }
    }
}

TEST(RigPointError, ZeroNearerThanThePlaneAndWhereCIsSkipped) {
    const Rig rig = build_rig(vive(8.0)).value_or_throw();
    EXPECT_EQ(angular_error_at_point(rig, {2.0, 1.0, -8.0}).larger_arcmin(), 0.0);
    EXPECT_EQ(angular_error_at_point(rig, {0.0, 0.0, -0.5}).larger_arcmin(), 0.0);
    RigInputs all_stereo = vive(2000.0);
    const Rig skipped = build_rig(all_stereo).value_or_throw();
    ASSERT_TRUE(skipped.mono_skipped);
    EXPECT_EQ(angular_error_at_point(skipped, {0.0, 0.0, -3000.0}).larger_arcmin(), 0.0);
    EXPECT_EQ(angular_error_in_direction(skipped, {0.0, 0.0, -1.0}).larger_arcmin(), 0.0);
}

TEST(RigErrorBudget, DisparityBudgetInvertsTwoArctangents) {
    // The disparity supremum is 2 atan(d / 2m): within A for m >= d / (2 tan(A / 2)).
    for (const double budget : {5.0, 10.0, 27.5, 60.0}) {
        const BudgetChoice choice =
            nearest_mono_plane_within(vive(8.0), budget, ErrorMeasure::kDisparity).value_or_throw();
        const double expected = 0.064 / (2.0 * std::tan(budget / kArcmin / 2.0));
        EXPECT_NEAR(choice.mono_plane / expected, 1.0, 1e-8) << budget;
        EXPECT_FALSE(choice.stereo);
        EXPECT_LE(choice.error.disparity_arcmin, budget * (1 + 1e-9));
    }
}

TEST(RigErrorBudget, EyeBudgetIsTheNearestPlaneThatMeetsIt) {
    for (const double budget : {2.0, 15.0}) {
        const BudgetChoice choice =
            nearest_mono_plane_within(vive(8.0), budget, ErrorMeasure::kEye).value_or_throw();
        const double m = choice.mono_plane;
        EXPECT_LE(brute_eye_error(vive(m), kInf), budget + 1e-6);
        EXPECT_GT(brute_eye_error(vive(m * 0.999), kInf), budget);
    }
    // The Vive at m = 8 has 15.3 arcmin: a 15.3 budget lands just below 8 m.
    const double m =
        nearest_mono_plane_within(vive(8.0), 15.3, ErrorMeasure::kEye).value_or_throw().mono_plane;
    EXPECT_NEAR(m, 8.0, 0.05);
}

TEST(RigErrorBudget, ContentThatEndsSoonerAllowsANearerPlane) {
    // Content no farther than 20 m: the error there, not at infinity, must meet the budget.
    const BudgetChoice any =
        nearest_mono_plane_within(vive(8.0), 5.0, ErrorMeasure::kEye).value_or_throw();
    const BudgetChoice near =
        nearest_mono_plane_within(vive(8.0), 5.0, ErrorMeasure::kEye, 20.0).value_or_throw();
    EXPECT_LT(near.mono_plane, any.mono_plane);
    EXPECT_NEAR(brute_eye_error(vive(near.mono_plane), 20.0), 5.0, 1e-5);
}

TEST(RigErrorBudget, RefusalsAndStereo) {
    EXPECT_FALSE(nearest_mono_plane_within(vive(8.0), 0.0, ErrorMeasure::kEye));
    EXPECT_FALSE(nearest_mono_plane_within(vive(8.0), -1.0, ErrorMeasure::kEye));
    EXPECT_FALSE(nearest_mono_plane_within(vive(8.0), std::nan(""), ErrorMeasure::kEye));
    EXPECT_FALSE(nearest_mono_plane_within(vive(8.0), 5.0, ErrorMeasure::kEye, 0.05));
    RigInputs bad = vive(8.0);
    bad.eyes[kLeft].left = 0.5;  // wrong sign
    EXPECT_FALSE(nearest_mono_plane_within(bad, 5.0, ErrorMeasure::kEye));
    // Below the error at the far plane no m meets the budget: stereo.
    const BudgetChoice tiny =
        nearest_mono_plane_within(vive(8.0), 0.01, ErrorMeasure::kDisparity).value_or_throw();
    EXPECT_TRUE(tiny.stereo);
    EXPECT_EQ(tiny.mono_plane, 1000.0);
    // Generous budgets reach the near plane itself.
    const BudgetChoice huge =
        nearest_mono_plane_within(vive(8.0), 5000.0, ErrorMeasure::kEye).value_or_throw();
    EXPECT_NEAR(huge.mono_plane, 0.1, 1e-6);
}

}  // namespace
}  // namespace monoplane::rig
