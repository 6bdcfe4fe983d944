// Smooth spheres as latitude-longitude meshes with pole fans (no degenerate triangles).
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "scenes/chunk_builder.h"

namespace monoplane::scenes {

struct SphereTessellation {
    int segments = 16;  // around the equator
    int rings = 8;      // pole to pole
};

inline std::size_t sphere_triangle_count(const SphereTessellation& t) {
    return 2 * static_cast<std::size_t>(t.segments) * static_cast<std::size_t>(t.rings - 1);
}

// Adds one sphere as one piece.
void add_sphere(ChunkBuilder& builder, glm::vec3 centre, float radius,
                const SphereTessellation& tessellation, std::uint32_t albedo_rgba8,
                std::uint32_t material_packed);

}  // namespace monoplane::scenes
