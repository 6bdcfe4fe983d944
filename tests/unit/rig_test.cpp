// The camera rig (rig/rig.h) against values derived by hand here, independently of the
// rig's code: the HTC Vive calibration of Fink et al. 2019 (papers/000 Sect. 4.2), eq. 1-8 and
// the Fig. 2 error. docs/rig.md explains the geometry.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <glm/ext/matrix_double4x4.hpp>

#include "rig/rig.h"

namespace monoplane::rig {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The Vive as quoted by the paper, in the XrFovf convention (hmd/profiles/vive.toml).
constexpr Tangents kViveLeft{-1.391937, 1.247409, -1.468819, 1.464287};
constexpr Tangents kViveRight{-1.246557, 1.398447, -1.465505, 1.472458};
constexpr double kViveIpd = 0.064;
constexpr int kViveWidth = 1344;
constexpr int kViveHeight = 1512;

RigInputs vive_inputs(double mono_plane) {
    RigInputs in;
    in.eyes = {kViveLeft, kViveRight};
    in.eye_width = kViveWidth;
    in.eye_height = kViveHeight;
    in.ipd = kViveIpd;
    in.mono_plane = mono_plane;
    in.near = 0.1;
    in.far = 1000.0;
    in.overlap_k = 2.0;
    return in;
}

Rig built(const RigInputs& in) {
    Result<Rig> rig = build_rig(in);
    EXPECT_TRUE(rig.ok()) << (rig.ok() ? "" : rig.error().message);
    return rig.ok() ? rig.value() : Rig{};
}

glm::dvec3 ndc_of(const glm::dmat4& m, const glm::dvec4& p) {
    const glm::dvec4 clip = m * p;
    return glm::dvec3(clip) / clip.w;
}

TEST(Rig, ViveOffsetBehindEyesIsTheFartherBackOuterPlaneCrossing) {
    // Left outer plane x = -d/2 + tan_left(L) dist crosses x = 0 at dist = d / (2 tan_left(L)):
    // 0.064 / (2 * -1.391937) = -0.0229895 m. Right: -0.064 / (2 * 1.398447) = -0.0228825 m.
    const double left_behind = 0.064 / (2.0 * 1.391937);
    const double right_behind = 0.064 / (2.0 * 1.398447);
    ASSERT_GT(left_behind, right_behind);  // the left eye's plane crosses farther back
    const Rig rig = built(vive_inputs(8.0));
    EXPECT_NEAR(rig.mono.offset_behind_eyes, left_behind, 1e-15);
    EXPECT_NEAR(rig.mono.offset_behind_eyes, 0.0230, 5e-5);  // docs/hybrid.md, "Measured"
    EXPECT_EQ(rig.mono_position, glm::dvec3(0.0, 0.0, left_behind));
    EXPECT_EQ(rig.eye_positions[kLeft], glm::dvec3(-0.032, 0.0, 0.0));
    EXPECT_EQ(rig.eye_positions[kRight], glm::dvec3(0.032, 0.0, 0.0));
}

TEST(Rig, ViveOverlapNearFarAndMonoTangents) {
    const double m = 8.0;
    const double s = 0.064 / (2.0 * 1.391937);
    RigInputs paper = vive_inputs(m);
    paper.grazing_angle = 0.0;  // the paper's overlap alone
    const Rig rig = built(paper);
    // eq. 3: eps = k s m with k = 2.
    EXPECT_NEAR(rig.overlap, 2.0 * s * m, 1e-15);
    // eq. 4 from C: near = m - eps + s, far = f + s.
    EXPECT_NEAR(rig.mono.near, m - 2.0 * s * m + s, 1e-12);
    EXPECT_NEAR(rig.mono.far, 1000.0 + s, 1e-12);
    // C's tangents: slopes from C (m + s from the plane) to the outer edges of the cross-sections.
    // Left edge: left eye -0.032 - 1.391937 * 8 = -11.167496 vs right eye 0.032 - 1.246557 * 8.
    const double from_c = m + s;
    EXPECT_NEAR(rig.mono.tangents.left,
                std::min(-0.032 - 1.391937 * m, 0.032 - 1.246557 * m) / from_c, 1e-14);
    EXPECT_NEAR(rig.mono.tangents.left, (-0.032 - 1.391937 * m) / from_c, 1e-14);
    EXPECT_NEAR(rig.mono.tangents.right,
                std::max(-0.032 + 1.247409 * m, 0.032 + 1.398447 * m) / from_c, 1e-14);
    EXPECT_NEAR(rig.mono.tangents.down, std::min(-1.468819, -1.465505) * m / from_c, 1e-14);
    EXPECT_NEAR(rig.mono.tangents.up, std::max(1.464287, 1.472458) * m / from_c, 1e-14);
}

TEST(Rig, ViveMaxErrorMatchesTheHandComputation) {
    const double m = 8.0;
    const double s = 0.064 / (2.0 * 1.391937);
    // In the limit z -> infinity the horizontal tangent offset is (t s - x_e) / m. For the left
    // eye (x_e = -d/2) it is largest at its inner (right) edge: (tanR_L s + d/2) / m; for the right
    // eye at its inner (left) edge: (|tanL_R| s + d/2) / m. Pixels per tangent: 1344 / field.
    const double left_px = (1.247409 * s + 0.032) / m * 1344.0 / (1.247409 + 1.391937);
    const double right_px = (1.246557 * s + 0.032) / m * 1344.0 / (1.398447 + 1.246557);
    const Rig rig = built(vive_inputs(m));
    EXPECT_NEAR(rig.max_error_px, std::max(left_px, right_px), 1e-12);
    EXPECT_NEAR(rig.max_error_px, 3.86, 0.005);  // the paper: "4 pixels"
    // Vertically t_y s / m at the larger of |tan_down|, tan_up, per eye, at a corner with the
    // horizontal maximum: the Euclidean supremum is the larger eye's hypot.
    const double left_v = 1.468819 * s / m * 1512.0 / (1.464287 + 1.468819);
    const double right_v = 1.472458 * s / m * 1512.0 / (1.472458 + 1.465505);
    EXPECT_NEAR(rig.max_error_px_2d,
                std::max(std::hypot(left_px, left_v), std::hypot(right_px, right_v)), 1e-12);
}

TEST(Rig, MonoViewportEqualsTheClosedFormOfEq8) {
    for (double m : {0.5, 1.6, 8.0, 39.5, 500.0}) {
        const Rig rig = built(vive_inputs(m));
        const double s = rig.mono.offset_behind_eyes;
        const Tangents& c = rig.mono.tangents;
        // The mono-plane quad is (tanR_C - tanL_C)(m + s) wide, i.e. that over m in the eye's
        // tangents; in pixels of eye e: * W / (tanR_e - tanL_e). eq. 8 takes the smaller.
        double width = kInfinity;
        double height = kInfinity;
        for (const Tangents& e : {kViveLeft, kViveRight}) {
            width =
                std::min(width, (c.right - c.left) * (m + s) / m * kViveWidth / (e.right - e.left));
            height =
                std::min(height, (c.up - c.down) * (m + s) / m * kViveHeight / (e.up - e.down));
        }
        EXPECT_NEAR(rig.mono.width, width, 1e-9) << m;
        EXPECT_NEAR(rig.mono.height, height, 1e-9) << m;
        EXPECT_EQ(rig.mono.viewport_width, static_cast<int>(std::ceil(width))) << m;
        EXPECT_EQ(rig.mono.viewport_height, static_cast<int>(std::ceil(height))) << m;
        // Allocated for m itself by default.
        EXPECT_EQ(rig.mono.allocated_width, rig.mono.viewport_width);
        EXPECT_EQ(rig.mono.uv_scale, glm::dvec2(1.0));
    }
    // At m = 8 for the record: C's image is about 6% wider than an eye's (1421.9 px).
    EXPECT_NEAR(built(vive_inputs(8.0)).mono.width, 1421.9, 0.1);
}

TEST(Rig, AllocationForTheNearestMonoPlaneGivesAUvSubRange) {
    RigInputs in = vive_inputs(8.0);
    in.nearest_mono_plane = 1.6;
    const Rig rig = built(in);
    const Rig nearest = built(vive_inputs(1.6));
    EXPECT_EQ(rig.mono.allocated_width, nearest.mono.viewport_width);
    EXPECT_EQ(rig.mono.allocated_height, nearest.mono.viewport_height);
    EXPECT_LT(rig.mono.viewport_width, rig.mono.allocated_width);
    EXPECT_DOUBLE_EQ(rig.mono.uv_scale.x,
                     double(rig.mono.viewport_width) / rig.mono.allocated_width);
    EXPECT_DOUBLE_EQ(rig.mono.uv_scale.y,
                     double(rig.mono.viewport_height) / rig.mono.allocated_height);
}

TEST(Rig, MappingsAgreeWithDirectProjection) {
    const Rig rig = built(vive_inputs(8.0));
    const double s = rig.mono.offset_behind_eyes;
    // C's NDC depth of the mono plane is where the composite's quad lies.
    EXPECT_NEAR(ndc_of(rig.mono_projection, {0.0, 0.0, -(8.0 + s), 1.0}).z,
                rig.mono.mono_plane_ndc_depth, 1e-15);
    for (int eye : {kLeft, kRight}) {
        // Any point (on the plane or not): C's clip coordinates through M_{C->E} are the eye's.
        for (const glm::dvec3 p : {glm::dvec3(0.3, -0.7, -8.0), glm::dvec3(-5.0, 4.0, -23.0),
                                   glm::dvec3(1.0, 0.2, -2.5)}) {
            const glm::dvec4 mono_clip = rig.mono_projection * glm::dvec4(p - rig.mono_position, 1);
            const glm::dvec3 eye_ndc = ndc_of(rig.mono_to_eye[eye], mono_clip);
            const glm::dvec3 direct =
                ndc_of(rig.eye_projection[eye], glm::dvec4(p - rig.eye_positions[eye], 1.0));
            EXPECT_NEAR(eye_ndc.x, direct.x, 1e-12);
            EXPECT_NEAR(eye_ndc.y, direct.y, 1e-12);
            EXPECT_NEAR(eye_ndc.z, direct.z, 1e-9);
            const glm::dvec2 pixel =
                (glm::dvec2(direct) * 0.5 + 0.5) * glm::dvec2(kViveWidth, kViveHeight);
            const glm::dvec2 stereo = eye_pixel_stereo(rig, eye, p);
            EXPECT_NEAR(stereo.x, pixel.x, 1e-9);
            EXPECT_NEAR(stereo.y, pixel.y, 1e-9);
        }
        // On the mono plane hybrid and stereo agree (the continuity of Sect. 3).
        const glm::dvec3 on_plane(0.9, -1.1, -8.0);
        const glm::dvec2 d =
            eye_pixel_hybrid(rig, eye, on_plane) - eye_pixel_stereo(rig, eye, on_plane);
        EXPECT_NEAR(glm::length(d), 0.0, 1e-9);
        // The eye's reversed-Z depth of the mono plane is 0: its far plane is m.
        EXPECT_NEAR(ndc_of(rig.eye_projection[eye], {0.0, 0.0, -8.0, 1.0}).z, 0.0, 1e-15);
        // And M_{E->C} inverts M_{C->E}.
        const glm::dmat4 product = rig.eye_to_mono[eye] * rig.mono_to_eye[eye];
        for (int c = 0; c < 4; ++c) {
            for (int r = 0; r < 4; ++r) EXPECT_NEAR(product[c][r], c == r ? 1.0 : 0.0, 1e-12);
        }
    }
}

TEST(Rig, MonoPixelToEyePixelIsWhereHybridShowsAPointBeyondThePlane) {
    for (const double m : {1.6, 8.0, 39.5}) {
        const Rig rig = built(vive_inputs(m));
        const glm::dvec2 viewport(rig.mono.viewport_width, rig.mono.viewport_height);
        for (int eye : {kLeft, kRight}) {
            const glm::dmat3 h = mono_pixel_to_eye_pixel(rig, eye);
            for (const glm::dvec3 p :
                 {glm::dvec3(0.3, -0.7, -(m + 0.5)), glm::dvec3(-5.0, 4.0, -(m + 20.0)),
                  glm::dvec3(40.0, -9.0, -(3.0 * m + 100.0))}) {
                // C's pixel of p as the renderer rasterises it (C's viewport of whole pixels),
                // then where hybrid shows p in the eye (central projection from C onto the plane,
                // then the eye's own projection).
                const glm::dvec3 ndc =
                    ndc_of(rig.mono_projection, glm::dvec4(p - rig.mono_position, 1.0));
                const glm::dvec2 mono_pixel = (glm::dvec2(ndc) * 0.5 + 0.5) * viewport;
                const glm::dvec3 mapped = h * glm::dvec3(mono_pixel, 1.0);
                const glm::dvec2 expected = eye_pixel_hybrid(rig, eye, p);
                EXPECT_NEAR(mapped.x / mapped.z, expected.x, 1e-6) << "m " << m;
                EXPECT_NEAR(mapped.y / mapped.z, expected.y, 1e-6) << "m " << m;
            }
        }
    }
}

TEST(Rig, ErrorGrowsFromZeroAtTheMonoPlaneToTheSupremum) {
    const Rig rig = built(vive_inputs(8.0));
    EXPECT_EQ(error_at_depth(rig, 8.0).horizontal_px, 0.0);
    EXPECT_EQ(error_at_depth(rig, 8.0).euclidean_px, 0.0);
    EXPECT_EQ(error_at_depth(rig, 3.0).euclidean_px, 0.0);  // stereo content
    double previous = 0.0;
    for (double depth = 8.01; depth < 1e7; depth *= 1.5) {
        const PixelError e = error_at_depth(rig, depth);
        EXPECT_GT(e.horizontal_px, previous) << depth;
        EXPECT_LT(e.horizontal_px, rig.max_error_px) << depth;
        EXPECT_LE(e.euclidean_px, rig.max_error_px_2d) << depth;
        previous = e.horizontal_px;
    }
    EXPECT_NEAR(error_at_depth(rig, 1e9).horizontal_px, rig.max_error_px, 1e-6);
    EXPECT_EQ(error_at_depth(rig, kInfinity).horizontal_px, rig.max_error_px);
    EXPECT_EQ(error_at_depth(rig, kInfinity).euclidean_px, rig.max_error_px_2d);
}

TEST(Rig, ErrorAtDepthMatchesHybridMinusStereoPixels) {
    // The closed form of error_at_depth against brute force through the pixel functions, which
    // only project points: for points on a grid over each eye's field at several depths the
    // largest |hybrid - stereo| must reach error_at_depth (at an edge or a corner) and not exceed
    // it.
    const Rig rig = built(vive_inputs(3.0));
    for (double depth : {3.5, 10.0, 100.0, 5000.0}) {
        const PixelError bound = error_at_depth(rig, depth);
        double worst_horizontal = 0.0;
        double worst_vertical = 0.0;
        double worst_euclidean = 0.0;
        for (int eye : {kLeft, kRight}) {
            const Tangents& t = rig.inputs.eyes[eye];
            constexpr int kSteps = 20;
            for (int i = 0; i <= kSteps; ++i) {
                for (int j = 0; j <= kSteps; ++j) {
                    const double tx = t.left + (t.right - t.left) * i / kSteps;
                    const double ty = t.down + (t.up - t.down) * j / kSteps;
                    const glm::dvec3 p(rig.eye_positions[eye].x + tx * depth, ty * depth, -depth);
                    const glm::dvec2 d =
                        eye_pixel_hybrid(rig, eye, p) - eye_pixel_stereo(rig, eye, p);
                    worst_horizontal = std::max(worst_horizontal, std::abs(d.x));
                    worst_vertical = std::max(worst_vertical, std::abs(d.y));
                    worst_euclidean = std::max(worst_euclidean, glm::length(d));
                }
            }
        }
        EXPECT_NEAR(worst_horizontal, bound.horizontal_px, 1e-9) << depth;
        EXPECT_NEAR(worst_vertical, bound.vertical_px, 1e-9) << depth;
        EXPECT_NEAR(worst_euclidean, bound.euclidean_px, 1e-9) << depth;
    }
}

// The overlap for grazing surfaces (docs/hybrid.md, "surfaces almost parallel to the view
// rays"): one of C's texels on the plane, tau (m + s), over tan(1 degree), capped where C's extra
// near content would stray more than one eye pixel, alpha_e m^2 / (d/2 + alpha_e m).
TEST(Rig, OverlapCoversGrazingSurfacesUpToTheGhostCap) {
    const double s = 0.064 / (2.0 * 1.391937);
    const double tan_1deg = std::tan(3.14159265358979323846 / 180.0);
    // The finest eye pixel in tangent units: the Vive's right eye horizontally.
    const double alpha_e = std::min({(1.247409 + 1.391937) / 1344, (1.398447 + 1.246557) / 1344,
                                     (1.464287 + 1.468819) / 1512, (1.472458 + 1.465505) / 1512});
    for (double m : {1.6, 8.0, 39.5}) {
        SCOPED_TRACE(m);
        const Rig rig = built(vive_inputs(m));
        const Tangents& c = rig.mono.tangents;
        const double texel =
            std::max((c.right - c.left) / rig.mono.width, (c.up - c.down) / rig.mono.height);
        const double footprint = texel * (m + s) / tan_1deg;
        const double cap = alpha_e * m * m / (0.032 + alpha_e * m);
        const double expected = std::max(2.0 * s * m, std::min(footprint, cap));
        EXPECT_NEAR(rig.overlap, expected, 1e-12 * m);
        EXPECT_NEAR(rig.mono.near, m - expected + s, 1e-12 * m);
        EXPECT_GT(rig.overlap, 2.0 * s * m);  // the paper's eps would leave grazing cuts
    }
    // At m = 1.6 the cap binds (C would otherwise start where its near content shows), at 8 the
    // footprint: about 0.9 m, against the paper's 0.37 m.
    EXPECT_NEAR(built(vive_inputs(1.6)).overlap, alpha_e * 2.56 / (0.032 + alpha_e * 1.6), 1e-12);
    EXPECT_NEAR(built(vive_inputs(8.0)).overlap, 0.905, 0.01);
    // k = 0 switches every overlap off.
    RigInputs none = vive_inputs(8.0);
    none.overlap_k = 0.0;
    EXPECT_EQ(built(none).overlap, 0.0);
}

TEST(Rig, ZeroIpdPutsCAtTheEyesWithoutError) {
    RigInputs in = vive_inputs(8.0);
    in.ipd = 0.0;
    const Rig rig = built(in);
    EXPECT_EQ(rig.mono.offset_behind_eyes, 0.0);
    EXPECT_FALSE(std::signbit(rig.mono.offset_behind_eyes));
    EXPECT_EQ(rig.overlap, 0.0);
    EXPECT_EQ(rig.max_error_px, 0.0);
    EXPECT_EQ(rig.max_error_px_2d, 0.0);
    EXPECT_EQ(error_at_depth(rig, 100.0).euclidean_px, 0.0);
    // C is the union of the eyes' frusta.
    EXPECT_NEAR(rig.mono.tangents.left, kViveLeft.left, 1e-15);
    EXPECT_NEAR(rig.mono.tangents.right, kViveRight.right, 1e-15);
    EXPECT_NEAR(rig.mono.near, 8.0, 1e-15);
}

TEST(Rig, MonoPlaneAtOrBeyondFarSkipsC) {
    for (double m : {1000.0, 2000.0}) {
        const Rig rig = built(vive_inputs(m));
        EXPECT_TRUE(rig.mono_skipped);
        EXPECT_EQ(rig.max_error_px, 0.0);
        EXPECT_EQ(rig.max_error_px_2d, 0.0);
        EXPECT_EQ(rig.overlap, 0.0);
        EXPECT_EQ(rig.mono.offset_behind_eyes, 0.0);
        EXPECT_EQ(rig.mono.width, 0.0);
        EXPECT_EQ(rig.mono.viewport_width, 0);
        EXPECT_EQ(rig.mono.allocated_width, 0);
        EXPECT_EQ(rig.mono.near, 0.0);
        EXPECT_EQ(rig.mono.far, 0.0);
        EXPECT_EQ(error_at_depth(rig, 5000.0).euclidean_px, 0.0);
        // The eyes then render everything, n..f.
        EXPECT_NEAR(ndc_of(rig.eye_projection[kLeft], {0.0, 0.0, -1000.0, 1.0}).z, 0.0, 1e-15);
        EXPECT_NEAR(ndc_of(rig.eye_projection[kLeft], {0.0, 0.0, -0.1, 1.0}).z, 1.0, 1e-15);
        const glm::dvec3 p(1.0, 2.0, -50.0);
        EXPECT_EQ(eye_pixel_hybrid(rig, kRight, p), eye_pixel_stereo(rig, kRight, p));
    }
    EXPECT_FALSE(built(vive_inputs(999.0)).mono_skipped);
}

struct Degenerate {
    std::string expected;  // part of the message: the input's name
    std::function<void(RigInputs&)> mutate;
};

TEST(Rig, DegenerateInputsGiveErrorsNamingTheInput) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    const std::vector<Degenerate> cases = {
        {"mono_plane", [](RigInputs& in) { in.mono_plane = 0.1; }},
        {"mono_plane", [](RigInputs& in) { in.mono_plane = 0.05; }},
        {"mono_plane", [nan](RigInputs& in) { in.mono_plane = nan; }},
        {"mono_plane", [](RigInputs& in) { in.mono_plane = kInfinity; }},
        {"near", [](RigInputs& in) { in.near = 0.0; }},
        {"near", [](RigInputs& in) { in.near = -1.0; }},
        {"near", [nan](RigInputs& in) { in.near = nan; }},
        {"far", [](RigInputs& in) { in.far = 0.1; }},
        {"far", [](RigInputs& in) { in.far = 0.05; }},
        {"far", [](RigInputs& in) { in.far = kInfinity; }},
        {"ipd", [](RigInputs& in) { in.ipd = -0.01; }},
        {"ipd", [nan](RigInputs& in) { in.ipd = nan; }},
        {"overlap_k", [](RigInputs& in) { in.overlap_k = -1.0; }},
        {"overlap_k", [nan](RigInputs& in) { in.overlap_k = nan; }},
        {"overlap_k", [](RigInputs& in) { in.overlap_k = 1.0 / 0.0229; }},  // k s >= 1
        {"eye_width", [](RigInputs& in) { in.eye_width = 0; }},
        {"eye_height", [](RigInputs& in) { in.eye_height = -5; }},
        {"nearest_mono_plane", [](RigInputs& in) { in.nearest_mono_plane = 9.0; }},
        {"nearest_mono_plane", [](RigInputs& in) { in.nearest_mono_plane = 0.1; }},
        {"nearest_mono_plane", [](RigInputs& in) { in.nearest_mono_plane = -2.0; }},
        {"nearest_mono_plane", [nan](RigInputs& in) { in.nearest_mono_plane = nan; }},
        {"eyes[left].tan_left", [](RigInputs& in) { in.eyes[kLeft].left = 0.2; }},
        {"eyes[left].tan_left", [](RigInputs& in) { in.eyes[kLeft].left = 0.0; }},
        {"eyes[right].tan_right", [](RigInputs& in) { in.eyes[kRight].right = -1.0; }},
        {"eyes[left].tan_down", [](RigInputs& in) { in.eyes[kLeft].down = 1.4; }},
        {"eyes[right].tan_up", [](RigInputs& in) { in.eyes[kRight].up = -1.4; }},
        {"eyes[right].tan_up", [](RigInputs& in) { in.eyes[kRight].up = 10.5; }},
        {"eyes[left].tan_right", [nan](RigInputs& in) { in.eyes[kLeft].right = nan; }},
        {"eyes[right].tan_down", [](RigInputs& in) { in.eyes[kRight].down = -kInfinity; }},
    };
    for (const Degenerate& c : cases) {
        RigInputs in = vive_inputs(8.0);
        c.mutate(in);
        const Result<Rig> rig = build_rig(in);
        ASSERT_FALSE(rig.ok()) << c.expected;
        EXPECT_NE(rig.error().message.find(c.expected), std::string::npos)
            << "expected '" << c.expected << "' in: " << rig.error().message;
    }
    // The boundaries that are allowed.
    RigInputs ok = vive_inputs(8.0);
    ok.eyes[kLeft].left = -kMaxTangent;
    ok.nearest_mono_plane = 8.0;
    ok.overlap_k = 0.0;
    EXPECT_TRUE(build_rig(ok).ok());
}

}  // namespace
}  // namespace monoplane::rig
