// Ground surfaces as a polar grid around a centre: rings whose spacing grows in proportion to
// their radius, so cells keep their shape and cover about the same solid angle from the centre
// (constant screen-space density for a viewer standing there) out to kilometres, with no
// T-junctions. Used by the flat grounds and the LANDSCAPE terrain.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "scenes/chunk_builder.h"

namespace monoplane::scenes {

struct PolarGrid {
    glm::vec2 centre{0.0f};     // (x, z)
    float inner_radius = 0.5f;  // the first ring; inside it a fan around the centre
    float outer_radius = 600.0f;
    int sectors = 64;  // around the full circle
    // A piece spans this many sectors and rings (even, so the diagonals alternate across pieces):
    // small pieces (256 triangles) keep the ground's chunk boxes tight, which culling needs.
    int block_sectors = 16;
    int block_rings = 8;
    // Pieces whose inner ring lies at or beyond this radius are flagged kChunkForceMono (0: none).
    float force_mono_from_radius = 0.0f;
};

// Ring radii from inner to outer: r[i+1] = r[i] * (1 + 2 pi / sectors), the last one clamped.
std::vector<float> polar_ring_radii(const PolarGrid& grid);

// The surface's height at a ground position (x, z), and its look at a point with its normal.
using HeightFunction = std::function<float(glm::vec2 position)>;
struct SurfaceLook {
    std::uint32_t albedo_rgba8 = 0xffffffffu;
    std::uint32_t material_packed = 0;
};
using LookFunction = std::function<SurfaceLook(glm::vec3 position, glm::vec3 normal)>;

// Adds the grid as pieces; returns the number of triangles added. Normals come from the grid's
// own neighbours, so they match the geometry at every detail level and cost no extra samples.
std::size_t add_polar_grid(ChunkBuilder& builder, const PolarGrid& grid,
                           const HeightFunction& height, const LookFunction& look);

}  // namespace monoplane::scenes
