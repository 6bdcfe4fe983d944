// Unit tests of the level-of-detail choice (renderer/plan/lod_selection.h), against values
// derived by hand: a view's pixels per unit of tangent and its widest corner from the frustum's
// tangents, the projected error at a box's nearest point, and the hysteresis band.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

#include "renderer/plan/lod_selection.h"

namespace monoplane::plan {
namespace {

// A Vulkan-style off-axis projection (clip z in [0, w], y down) from the frustum's tangents at
// unit distance, written out rather than taken from glm so the test does not share its maths with
// the code: x_ndc = (2 tan_x - (r + l)) / (r - l) with tan_x = x / -z, likewise y, w = -z.
glm::dmat4 projection(double left, double right, double down, double up, double near) {
    glm::dmat4 p(0.0);
    p[0][0] = 2.0 / (right - left);
    p[2][0] = (right + left) / (right - left);
    p[1][1] = -2.0 / (up - down);
    p[2][1] = -(up + down) / (up - down);
    // Reversed Z with an infinite far plane: z_ndc = near / -z.
    p[3][2] = near;
    p[2][3] = -1.0;
    return p;
}

TEST(LodSelection, AViewsPixelsAndCornersComeFromItsFrustum) {
    // 1000 x 800 pixels over tangents [-1, 1] x [-0.8, 0.8]: 500 pixels per unit of tangent on
    // both axes; the corner ray's tan^2 off the axis is 1 + 0.64.
    const glm::dvec3 eye(2.0, 1.5, -3.0);
    const glm::dmat4 view = glm::rotate(glm::dmat4(1.0), glm::radians(-30.0), glm::dvec3(0, 1, 0)) *
                            glm::translate(glm::dmat4(1.0), -eye);
    const LodView v =
        lod_view_of(projection(-1.0, 1.0, -0.8, 0.8, 0.1) * view, eye, glm::dvec2(1000.0, 800.0));
    EXPECT_NEAR(v.pixels_per_tangent, 500.0, 1e-9);
    EXPECT_NEAR(v.max_tangent_squared, 1.64, 1e-9);
    // The view matrix turns the world by -30 degrees about +y, so the camera's -z points 30
    // degrees to the left of the world's: (-sin 30, 0, -cos 30).
    const glm::dvec3 turned_forward(-std::sin(glm::radians(30.0)), 0.0,
                                    -std::cos(glm::radians(30.0)));
    EXPECT_NEAR(glm::dot(v.forward, turned_forward), 1.0, 1e-12);
    EXPECT_EQ(v.position, eye);
}

TEST(LodSelection, AnOffAxisFrustumTakesItsWidestSideAndCorner) {
    // A canted display's eye: tangents [-1.2, 0.6] x [-1.0, 0.5] on 900 x 750 pixels: 500 per
    // unit of tangent across, 500 up; the widest corner is (-1.2, -1.0): tan^2 = 1.44 + 1.
    const LodView v = lod_view_of(projection(-1.2, 0.6, -1.0, 0.5, 0.05), glm::dvec3(0.0),
                                  glm::dvec2(900.0, 750.0));
    EXPECT_NEAR(v.pixels_per_tangent, 500.0, 1e-9);
    EXPECT_NEAR(v.max_tangent_squared, 2.44, 1e-9);
    EXPECT_NEAR(v.forward.z, -1.0, 1e-12);
}

LodView straight_ahead(double pixels_per_tangent = 1000.0) {
    LodView v;
    v.position = glm::dvec3(0.0);
    v.forward = glm::dvec3(0.0, 0.0, -1.0);
    v.pixels_per_tangent = pixels_per_tangent;
    v.max_tangent_squared = 2.0;
    return v;
}

TEST(LodSelection, TheErrorIsProjectedAtTheBoxsNearestPoint) {
    const LodView v = straight_ahead();
    // On the axis, 10 m away: 1 cm covers 1000 * 0.01 / 10 = 1 pixel.
    EXPECT_NEAR(projected_error_px(v, {{-1, -1, -12}, {1, 1, -10}}, 0.01), 1.0, 1e-12);
    // Nearest point (3, 0, -4): 5 m away at tan^2 = 9/16 off the axis: 1000 * 0.01 * 25/16 / 5.
    EXPECT_NEAR(projected_error_px(v, {{3, 0, -6}, {5, 0, -4}}, 0.01), 3.125, 1e-12);
    // Beside the camera (nearest point at z = 0): the widest angle, tan^2 = 2.
    EXPECT_NEAR(projected_error_px(v, {{2, -1, -1}, {3, 1, 1}}, 0.01), 1000 * 0.01 * 3 / 2, 1e-12);
    // Far off the axis but within the frustum's corner: tan^2 capped at 2 (here 4 -> 2).
    EXPECT_NEAR(projected_error_px(v, {{8, 0, -4}, {8, 0, -4}}, 0.01),
                1000 * 0.01 * 3 / std::sqrt(80.0), 1e-12);
    // Inside the box: no simplified level will do.
    EXPECT_EQ(projected_error_px(v, {{-1, -1, -1}, {1, 1, 1}}, 0.01),
              std::numeric_limits<double>::infinity());
}

// Levels 1..3 with errors 1, 2 and 4 cm; a box on the axis at distance d in a view of 1000
// pixels per unit tangent: level l shows e_l * 1000 / d pixels.
std::uint32_t level_at(double d, std::uint32_t previous, double budget = 0.5) {
    const std::array<float, 4> errors = {0.0f, 0.01f, 0.02f, 0.04f};
    const std::array<LodView, 1> view = {straight_ahead()};
    return choose_lod_level(errors, view, {{-0.5, -0.5, -d - 1.0}, {0.5, 0.5, -d}}, budget,
                            previous);
}

TEST(LodSelection, CoarserOnlyWithMarginFinerAtOnce) {
    // d = 40: levels show 0.25, 0.5 and 1 px. Within 0.5 px: level 2; within 0.375 px (the
    // coarsening band, 0.75 of the budget): level 1.
    EXPECT_EQ(level_at(40.0, 0), 1u);  // from full detail: only as coarse as the band allows
    EXPECT_EQ(level_at(40.0, 1), 1u);
    EXPECT_EQ(level_at(40.0, 2), 2u);  // already coarser and still within the budget: kept
    EXPECT_EQ(level_at(40.0, 3), 2u);  // level 3 exceeds the budget: finer at once
    // d = 60: level 2 shows 0.333 px (within the band), level 3 0.667 px: level 2 from any
    // previous level at or below it, and 2 from 3 as well.
    EXPECT_EQ(level_at(60.0, 0), 2u);
    EXPECT_EQ(level_at(60.0, 3), 2u);
    // d = 35: level 2 shows 0.571 px > 0.5: level 1 whatever came before.
    EXPECT_EQ(level_at(35.0, 2), 1u);
    // A budget of 1 px at d = 40: level 3 (1 px) is within it but not within the band
    // (0.75 px), level 2 (0.5 px) within both.
    EXPECT_EQ(level_at(40.0, 0, 1.0), 2u);
    EXPECT_EQ(level_at(40.0, 3, 1.0), 3u);
}

TEST(LodSelection, ASwayingHeadDoesNotMakeALevelFlicker) {
    // The distance sways between 38 and 42 m about the 40 m where level 2 just meets the budget
    // (0.526 px at 38 m, 0.476 px at 42 m): the coarsest level within the budget would flip
    // between 1 and 2 every few frames; with the band the level stays 1.
    std::uint32_t level = 0;
    std::vector<std::uint32_t> levels;
    for (int frame = 0; frame < 40; ++frame) {
        const double d = 40.0 + 2.0 * std::sin(frame * 0.4);
        level = level_at(d, level);
        levels.push_back(level);
    }
    EXPECT_EQ(levels[0], 1u);
    for (std::size_t i = 1; i < levels.size(); ++i) EXPECT_EQ(levels[i], levels[0]) << i;
    // Without the band the same path flickers: check that the path does cross the edge.
    EXPECT_EQ(level_at(38.0, 2), 1u);
    EXPECT_EQ(level_at(42.0, 2), 2u);
}

TEST(LodSelection, SeveralViewsTakeTheFinerChoice) {
    // Two eyes, one 40 m and one 80 m from the box (from level 3, so the band does not bind):
    // alone the near eye allows level 2, the far one level 3; together the finer, 2.
    const std::array<float, 4> errors = {0.0f, 0.01f, 0.02f, 0.04f};
    std::array<LodView, 2> eyes = {straight_ahead(), straight_ahead()};
    eyes[1].position = glm::dvec3(0.0, 0.0, 40.0);  // 40 m further back
    const LodBox box{{-0.5, -0.5, -41.0}, {0.5, 0.5, -40.0}};
    EXPECT_EQ(choose_lod_level(errors, std::span(eyes).first(1), box, 0.5, 3), 2u);
    EXPECT_EQ(choose_lod_level(errors, std::span(eyes).last(1), box, 0.5, 3), 3u);
    EXPECT_EQ(choose_lod_level(errors, eyes, box, 0.5, 3), 2u);
}

TEST(LodSelection, ModeNames) {
    EXPECT_EQ(parse_lod_mode("auto"), true);
    EXPECT_EQ(parse_lod_mode("off"), false);
    EXPECT_FALSE(parse_lod_mode("on").has_value());
    EXPECT_EQ(lod_mode_name(true), "auto");
    EXPECT_EQ(lod_mode_name(false), "off");
}

}  // namespace
}  // namespace monoplane::plan
