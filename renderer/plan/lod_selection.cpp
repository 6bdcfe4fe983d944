#include "renderer/plan/lod_selection.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include "common/programming_error.h"

namespace monoplane::plan {
namespace {

// The coarsest level whose projected error in every view stays within the budget.
std::uint32_t coarsest_within(std::span<const float> errors, std::span<const LodView> views,
                              const LodBox& box, double budget_px) {
    std::uint32_t level = 0;
    for (std::uint32_t l = 1; l < errors.size(); ++l) {
        bool fits = true;
        for (const LodView& view : views) {
            fits = fits && projected_error_px(view, box, errors[l]) <= budget_px;
        }
        if (!fits) break;  // errors grow along the chain
        level = l;
    }
    return level;
}

}  // namespace

std::optional<bool> parse_lod_mode(const std::string& name) {
    if (name == "auto") return true;
    if (name == "off") return false;
    return std::nullopt;
}

std::string lod_mode_name(bool enabled) {
    return enabled ? "auto" : "off";
}

LodView lod_view_of(const glm::dmat4& view_proj, const glm::dvec3& position,
                    const glm::dvec2& viewport_px) {
    const glm::dmat4 rows = glm::transpose(view_proj);  // rows[i]: row i of view_proj
    // Clip w is the distance along the view axis (scaled): its gradient is the axis.
    const glm::dvec3 w_gradient(rows[3]);
    const double w_scale = glm::length(w_gradient);
    if (!(w_scale > 0.0)) programming_error("lod_view_of: not a perspective projection");
    LodView view;
    view.position = position;
    view.forward = w_gradient / w_scale;
    // NDC x = clip x / w: per unit of tangent across the axis it moves |row 0 across| / |row 3|,
    // and the viewport spans 2 NDC units.
    double pixels_per_tangent = 0.0;
    for (int axis = 0; axis < 2; ++axis) {
        glm::dvec3 across(rows[axis]);
        across -= glm::dot(across, view.forward) * view.forward;
        pixels_per_tangent =
            std::max(pixels_per_tangent, 0.5 * viewport_px[axis] * glm::length(across) / w_scale);
    }
    view.pixels_per_tangent = pixels_per_tangent;
    // The corner rays: unproject the NDC corners and measure their angle off the axis.
    const glm::dmat4 inverse = glm::inverse(view_proj);
    for (double x : {-1.0, 1.0}) {
        for (double y : {-1.0, 1.0}) {
            const glm::dvec4 point = inverse * glm::dvec4(x, y, 0.5, 1.0);
            const glm::dvec3 ray = glm::dvec3(point) / point.w - position;
            const double along = glm::dot(ray, view.forward);
            const double across_squared = glm::dot(ray, ray) - along * along;
            view.max_tangent_squared =
                std::max(view.max_tangent_squared, across_squared / (along * along));
        }
    }
    return view;
}

double projected_error_px(const LodView& view, const LodBox& box, double error_m) {
    const glm::dvec3 nearest = glm::clamp(view.position, box.min, box.max);
    const glm::dvec3 to_nearest = nearest - view.position;
    const double distance = glm::length(to_nearest);
    if (distance <= 0.0) return std::numeric_limits<double>::infinity();
    const double along = glm::dot(to_nearest, view.forward);
    // Beside or behind the camera: the widest angle the view shows.
    double tangent_squared = view.max_tangent_squared;
    if (along > 0.0) {
        tangent_squared =
            std::min(tangent_squared, (distance * distance - along * along) / (along * along));
    }
    return error_m * view.pixels_per_tangent * (1.0 + tangent_squared) / distance;
}

std::uint32_t choose_lod_level(std::span<const float> level_errors_m,
                               std::span<const LodView> views, const LodBox& box, double error_px,
                               std::uint32_t previous_level) {
    const std::uint32_t within = coarsest_within(level_errors_m, views, box, error_px);
    const std::uint32_t comfortably =
        coarsest_within(level_errors_m, views, box, kLodCoarsenFraction * error_px);
    return std::clamp(previous_level, comfortably, within);
}

}  // namespace monoplane::plan
