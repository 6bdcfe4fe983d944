#include "scenes/lathe_mesh.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "common/programming_error.h"

namespace monoplane::scenes {

void add_frustum(ChunkBuilder& builder, const Frustum& f) {
    MONOPLANE_EXPECTS(f.sides >= 3 && f.height > 0.0f && f.bottom_radius > 0.0f);
    Vertex vertex{};
    vertex.albedo_rgba8 = f.albedo_rgba8;
    vertex.material_packed = f.material_packed;
    const float slope = (f.bottom_radius - f.top_radius) / f.height;  // outward normal tilt
    const auto direction = [&](double angle) {
        return glm::vec3(static_cast<float>(std::cos(angle)), 0.0f,
                         static_cast<float>(std::sin(angle)));
    };
    const auto side_normal = [&](double angle) {
        return glm::normalize(direction(angle) + glm::vec3(0.0f, slope, 0.0f));
    };
    const double step = 2.0 * std::numbers::pi / f.sides;
    const glm::vec3 top_centre = f.base + glm::vec3(0.0f, f.height, 0.0f);
    const bool cone = f.top_radius <= 0.0f;

    const std::uint32_t first = builder.piece_vertex_count();
    for (int s = 0; s < f.sides; ++s) {
        const double angle = step * s;
        vertex.normal = side_normal(angle);
        vertex.position = f.base + f.bottom_radius * direction(angle);
        builder.add_vertex(vertex);
        if (cone) {
            // One apex per side, with the normal of the side's middle: smooth without a pinch.
            vertex.normal = side_normal(angle + 0.5 * step);
            vertex.position = top_centre;
        } else {
            vertex.position = top_centre + f.top_radius * direction(angle);
        }
        builder.add_vertex(vertex);
    }
    const auto bottom = [&](int s) { return first + 2 * static_cast<std::uint32_t>(s % f.sides); };
    for (int s = 0; s < f.sides; ++s) {
        if (cone) {
            builder.add_triangle(bottom(s), bottom(s + 1), bottom(s) + 1);
        } else {
            builder.add_quad(bottom(s), bottom(s + 1), bottom(s + 1) + 1, bottom(s) + 1);
        }
    }
    if (f.bottom_cap) {
        vertex.normal = {0.0f, -1.0f, 0.0f};
        const std::uint32_t cap = builder.piece_vertex_count();
        for (int s = 0; s < f.sides; ++s) {
            vertex.position = f.base + f.bottom_radius * direction(step * s);
            builder.add_vertex(vertex);
        }
        for (int s = 1; s + 1 < f.sides; ++s) {
            builder.add_triangle(cap, cap + static_cast<std::uint32_t>(s),
                                 cap + static_cast<std::uint32_t>(s + 1));
        }
    }
}

}  // namespace monoplane::scenes
