#include "scenes/polar_grid.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "common/programming_error.h"

namespace monoplane::scenes {

std::vector<float> polar_ring_radii(const PolarGrid& grid) {
    MONOPLANE_EXPECTS(grid.inner_radius > 0.0f && grid.outer_radius > grid.inner_radius &&
                      grid.sectors >= 3);
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

namespace {

// Every grid point sampled once, ring by ring, sector by sector; the pieces copy from here, so
// the vertices that neighbouring pieces share are identical.
struct GridSamples {
    std::vector<float> radii;
    int rings = 0;
    int sectors = 0;
    std::vector<glm::vec3> positions;  // at index(ring, sector)
    glm::vec3 centre_position{0.0f};
    std::vector<Vertex> points;  // positions with their normals and looks
    Vertex centre{};

    // Sectors wrap around the circle: -1 is the last one.
    std::size_t index(int ring, int sector) const {
        return static_cast<std::size_t>(ring) * static_cast<std::size_t>(sectors) +
               static_cast<std::size_t>((sector + sectors) % sectors);
    }
    const Vertex& point(int ring, int sector) const { return points[index(ring, sector)]; }
};

// The grid points' positions on the surface. Sector 0 points straight ahead (-z).
void sample_positions(const PolarGrid& grid, const HeightFunction& height, GridSamples& samples) {
    const int sectors = samples.sectors;
    const double sector_angle = 2.0 * std::numbers::pi / sectors;
    std::vector<glm::vec2> directions(static_cast<std::size_t>(sectors));
    for (int s = 0; s < sectors; ++s) {
        const double angle = sector_angle * s;
        directions[static_cast<std::size_t>(s)] = {static_cast<float>(std::sin(angle)),
                                                   static_cast<float>(-std::cos(angle))};
    }
    samples.positions.resize(static_cast<std::size_t>(samples.rings) *
                             static_cast<std::size_t>(sectors));
    for (int i = 0; i < samples.rings; ++i) {
        for (int s = 0; s < sectors; ++s) {
            const glm::vec2 p = grid.centre + directions[static_cast<std::size_t>(s)] *
                                                  samples.radii[static_cast<std::size_t>(i)];
            samples.positions[samples.index(i, s)] = {p.x, height(p), p.y};
        }
    }
    samples.centre_position = {grid.centre.x, height(grid.centre), grid.centre.y};
}

// Normals by central differences across the rings and around them, one-sided at the rims; the
// centre's is the mean of the first ring's. Then each point's look.
void shade_points(const LookFunction& look, GridSamples& samples) {
    const std::vector<glm::vec3>& positions = samples.positions;
    const int rings = samples.rings;
    samples.points.resize(positions.size());
    glm::vec3 centre_normal{0.0f};
    for (int i = 0; i < rings; ++i) {
        for (int s = 0; s < samples.sectors; ++s) {
            const glm::vec3 inner =
                i == 0 ? samples.centre_position : positions[samples.index(i - 1, s)];
            const glm::vec3 outer = positions[samples.index(std::min(i + 1, rings - 1), s)];
            const glm::vec3 around =
                positions[samples.index(i, s + 1)] - positions[samples.index(i, s - 1)];
            glm::vec3 normal = glm::normalize(glm::cross(outer - inner, around));
            if (normal.y < 0.0f) normal = -normal;
            if (i == 0) centre_normal += normal;
            Vertex& vertex = samples.points[samples.index(i, s)];
            vertex.position = positions[samples.index(i, s)];
            vertex.normal = normal;
            const SurfaceLook surface = look(vertex.position, normal);
            vertex.albedo_rgba8 = surface.albedo_rgba8;
            vertex.material_packed = surface.material_packed;
        }
    }
    Vertex& centre = samples.centre;
    centre.position = samples.centre_position;
    centre.normal = glm::normalize(centre_normal);
    const SurfaceLook centre_look = look(centre.position, centre.normal);
    centre.albedo_rgba8 = centre_look.albedo_rgba8;
    centre.material_packed = centre_look.material_packed;
}

GridSamples sample_grid(const PolarGrid& grid, const HeightFunction& height,
                        const LookFunction& look) {
    GridSamples samples;
    samples.radii = polar_ring_radii(grid);
    samples.rings = static_cast<int>(samples.radii.size());
    samples.sectors = grid.sectors;
    sample_positions(grid, height, samples);
    shade_points(look, samples);
    return samples;
}

// The fan inside the first ring, one piece per block of sectors.
void add_centre_fan(ChunkBuilder& builder, const PolarGrid& grid, const GridSamples& samples) {
    const int sectors = samples.sectors;
    for (int first = 0; first < sectors; first += grid.block_sectors) {
        const int last = std::min(sectors, first + grid.block_sectors);
        builder.begin_piece();
        const std::uint32_t hub = builder.add_vertex(samples.centre);
        for (int s = first; s <= last; ++s) builder.add_vertex(samples.point(0, s));
        for (int s = 0; s < last - first; ++s) {
            builder.add_triangle(hub, hub + 1 + static_cast<std::uint32_t>(s),
                                 hub + 2 + static_cast<std::uint32_t>(s));
        }
    }
}

// Pieces of block_rings x block_sectors cells between the rings.
void add_ring_blocks(ChunkBuilder& builder, const PolarGrid& grid, const GridSamples& samples) {
    const int rings = samples.rings;
    const int sectors = samples.sectors;
    for (int ring_first = 0; ring_first + 1 < rings; ring_first += grid.block_rings) {
        const int ring_last = std::min(rings - 1, ring_first + grid.block_rings);
        for (int first = 0; first < sectors; first += grid.block_sectors) {
            const int last = std::min(sectors, first + grid.block_sectors);
            const auto columns = static_cast<std::uint32_t>(last - first + 1);
            const bool force_mono =
                grid.force_mono_from_radius > 0.0f &&
                samples.radii[static_cast<std::size_t>(ring_first)] >= grid.force_mono_from_radius;
            builder.begin_piece(force_mono ? kChunkForceMono : kChunkNone);
            for (int i = ring_first; i <= ring_last; ++i) {
                for (int s = first; s <= last; ++s) builder.add_vertex(samples.point(i, s));
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
}

}  // namespace

std::size_t add_polar_grid(ChunkBuilder& builder, const PolarGrid& grid,
                           const HeightFunction& height, const LookFunction& look) {
    const GridSamples samples = sample_grid(grid, height, look);
    const std::size_t triangles_before = builder.triangle_count();
    add_centre_fan(builder, grid, samples);
    add_ring_blocks(builder, grid, samples);
    return builder.triangle_count() - triangles_before;
}

}  // namespace monoplane::scenes
