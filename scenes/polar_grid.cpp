#include "scenes/polar_grid.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

namespace monoplane::scenes {

std::vector<float> polar_ring_radii(const PolarGrid& grid) {
    assert(grid.inner_radius > 0.0f && grid.outer_radius > grid.inner_radius && grid.sectors >= 3);
    const double growth = 1.0 + 2.0 * std::numbers::pi / grid.sectors;
    std::vector<float> radii;
    for (double r = grid.inner_radius; r < grid.outer_radius; r *= growth) {
        radii.push_back(static_cast<float>(r));
    }
    // Clamp the last ring to the outer radius unless it would make a sliver.
    if (grid.outer_radius - radii.back() < 0.3 * radii.back() * (growth - 1.0) &&
        radii.size() > 1) {
        radii.back() = grid.outer_radius;
    } else {
        radii.push_back(grid.outer_radius);
    }
    return radii;
}

std::size_t add_polar_grid(ChunkBuilder& builder, const PolarGrid& grid,
                           const HeightFunction& height, const LookFunction& look) {
    const std::vector<float> radii = polar_ring_radii(grid);
    const int rings = static_cast<int>(radii.size());
    const int sectors = grid.sectors;
    const double sector_angle = 2.0 * std::numbers::pi / sectors;

    // Sample every grid point once; the pieces copy from here, so the vertices that
    // neighbouring pieces share are identical. Sector 0 points straight ahead (-z).
    std::vector<glm::vec2> directions(static_cast<std::size_t>(sectors));
    for (int s = 0; s < sectors; ++s) {
        const double angle = sector_angle * s;
        directions[static_cast<std::size_t>(s)] = {static_cast<float>(std::sin(angle)),
                                                   static_cast<float>(-std::cos(angle))};
    }
    const auto index = [&](int ring, int sector) {
        return static_cast<std::size_t>(ring) * static_cast<std::size_t>(sectors) +
               static_cast<std::size_t>((sector + sectors) % sectors);
    };
    std::vector<glm::vec3> positions(static_cast<std::size_t>(rings) *
                                     static_cast<std::size_t>(sectors));
    for (int i = 0; i < rings; ++i) {
        for (int s = 0; s < sectors; ++s) {
            const glm::vec2 p = grid.centre + directions[static_cast<std::size_t>(s)] *
                                                  radii[static_cast<std::size_t>(i)];
            positions[index(i, s)] = {p.x, height(p), p.y};
        }
    }
    const glm::vec3 centre_position{grid.centre.x, height(grid.centre), grid.centre.y};

    // Central differences across the rings and around them; one-sided at the rims.
    std::vector<Vertex> points(positions.size());
    glm::vec3 centre_normal{0.0f};
    for (int i = 0; i < rings; ++i) {
        for (int s = 0; s < sectors; ++s) {
            const glm::vec3 inner = i == 0 ? centre_position : positions[index(i - 1, s)];
            const glm::vec3 outer = positions[index(std::min(i + 1, rings - 1), s)];
            const glm::vec3 around = positions[index(i, s + 1)] - positions[index(i, s - 1)];
            glm::vec3 normal = glm::normalize(glm::cross(outer - inner, around));
            if (normal.y < 0.0f) normal = -normal;
            if (i == 0) centre_normal += normal;
            Vertex& vertex = points[index(i, s)];
            vertex.position = positions[index(i, s)];
            vertex.normal = normal;
            const SurfaceLook surface = look(vertex.position, normal);
            vertex.albedo_rgba8 = surface.albedo_rgba8;
            vertex.material_packed = surface.material_packed;
        }
    }
    Vertex centre{};
    centre.position = centre_position;
    centre.normal = glm::normalize(centre_normal);
    const SurfaceLook centre_look = look(centre.position, centre.normal);
    centre.albedo_rgba8 = centre_look.albedo_rgba8;
    centre.material_packed = centre_look.material_packed;
    const auto point = [&](int ring, int sector) -> const Vertex& {
        return points[index(ring, sector)];
    };

    const std::size_t triangles_before = builder.triangle_count();
    // The fan inside the first ring.
    for (int first = 0; first < sectors; first += grid.block_sectors) {
        const int last = std::min(sectors, first + grid.block_sectors);
        builder.begin_piece();
        const std::uint32_t hub = builder.add_vertex(centre);
        for (int s = first; s <= last; ++s) builder.add_vertex(point(0, s));
        for (int s = 0; s < last - first; ++s) {
            builder.add_triangle(hub, hub + 1 + static_cast<std::uint32_t>(s),
                                 hub + 2 + static_cast<std::uint32_t>(s));
        }
    }
    // Blocks of rings x sectors.
    for (int ring_first = 0; ring_first + 1 < rings; ring_first += grid.block_rings) {
        const int ring_last = std::min(rings - 1, ring_first + grid.block_rings);
        for (int first = 0; first < sectors; first += grid.block_sectors) {
            const int last = std::min(sectors, first + grid.block_sectors);
            const auto columns = static_cast<std::uint32_t>(last - first + 1);
            const bool force_mono =
                grid.force_mono_from_radius > 0.0f &&
                radii[static_cast<std::size_t>(ring_first)] >= grid.force_mono_from_radius;
            builder.begin_piece(force_mono ? kChunkForceMono : kChunkNone);
            for (int i = ring_first; i <= ring_last; ++i) {
                for (int s = first; s <= last; ++s) builder.add_vertex(point(i, s));
            }
            for (int i = 0; i < ring_last - ring_first; ++i) {
                for (std::uint32_t s = 0; s + 1 < columns; ++s) {
                    const std::uint32_t inner = static_cast<std::uint32_t>(i) * columns + s;
                    const std::uint32_t outer = inner + columns;
                    // Alternate the diagonal so the triangulation has no preferred direction.
                    if ((static_cast<std::uint32_t>(i) + s) % 2 == 0) {
                        builder.add_quad(inner, inner + 1, outer + 1, outer);
                    } else {
                        builder.add_quad(inner + 1, outer + 1, outer, inner);
                    }
                }
            }
        }
    }
    return builder.triangle_count() - triangles_before;
}

}  // namespace monoplane::scenes
