// Which level of detail (scenes/lod_chain.h) a view draws of a chunk: the coarsest level whose
// geometric error, projected at the chunk's nearest point, stays within `error_px` of that view's
// pixels. The GPU culling pass (renderer/passes/culling/cull_chunks.comp) decides this every
// frame for every chunk; these functions are its reference, in double precision, for tests and
// for the docs' numbers.
//
// The projection: a surface displaced by e metres at distance d, seen at angle theta off the
// view's axis, moves by at most e / d radians, and a radian there covers f (1 + tan^2 theta)
// pixels (f: pixels per unit of tangent; x = f tan theta differentiated), so
//     error_px = e * f * (1 + tan^2 theta) / d,
// with theta taken at the nearest point and clamped to the view's widest corner.
//
// Both eyes draw the same level, the finer of their two choices: a level that differed between
// the eyes would show each eye another surface (a binocular mismatch the paper's method exists to
// avoid), and single-pass stereo, which draws both eyes with one command, needs one level. C, which
// has its own pixel size (eq. 8), chooses for itself.
//
// Hysteresis: a chunk moves to a coarser level only once that level's error is within
// kLodCoarsenFraction of the budget, and to a finer one as soon as its current level exceeds the
// budget. Every frame's level thus meets the budget, and a head that sways a little about a
// switching distance does not make a level flicker. The choice is a function of the pose and the
// chunk's previous level (the first frame's previous level is 0, the finest).
//
// When may this be called: any time; pure.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/vector_double2.hpp>
#include <glm/ext/vector_double3.hpp>

namespace monoplane::plan {

// --lod off|auto and --lod-error-px (default 0.5).
struct LodOptions {
    bool enabled = true;
    double error_px = 0.5;
};
std::optional<bool> parse_lod_mode(const std::string& name);  // "auto" -> true, "off" -> false
std::string lod_mode_name(bool enabled);

inline constexpr double kLodCoarsenFraction = 0.75;

// What the error projection needs of a view.
struct LodView {
    glm::dvec3 position{0.0};            // the camera, world space
    glm::dvec3 forward{0.0, 0.0, -1.0};  // unit view axis, world space
    double pixels_per_tangent = 1.0;     // f: the larger of the two axes'
    double max_tangent_squared = 0.0;    // tan^2 of the widest corner ray
};

// From a world -> clip perspective matrix (any handedness, reversed Z or not, off-axis frusta
// included), the camera's position and the viewport the clip space maps to. Throws
// a programming error (common/programming_error.h) for a matrix with no perspective row (an orthographic projection).
LodView lod_view_of(const glm::dmat4& view_proj, const glm::dvec3& position,
                    const glm::dvec2& viewport_px);

// A chunk's bounds (scenes::Aabb in double precision: the plan knows no scenes).
struct LodBox {
    glm::dvec3 min{0.0};
    glm::dvec3 max{0.0};
};

// The projected error (pixels) of an error of error_m metres at the box's nearest point to the
// view's camera; +inf when the camera lies inside the box (only level 0 will do).
double projected_error_px(const LodView& view, const LodBox& box, double error_m);

// The chain's errors, level 0 first (0), then each simplified level's: the coarsest level
// within the budget, after the hysteresis rule above. previous_level: the chunk's level last
// frame for this view group (0 the first time).
std::uint32_t choose_lod_level(std::span<const float> level_errors_m,
                               std::span<const LodView> views, const LodBox& box, double error_px,
                               std::uint32_t previous_level);

}  // namespace monoplane::plan
