// Surfaces of revolution about a vertical axis: tree trunks (cylinders) and conifer crowns
// (cones), with smooth normals around and an optional flat bottom cap.
#pragma once

#include <cstdint>

#include <glm/vec3.hpp>

#include "scenes/chunk_builder.h"

namespace monoplane::scenes {

struct Frustum {
    glm::vec3 base{0.0f};  // centre of the bottom circle
    float bottom_radius = 1.0f;
    float top_radius = 0.0f;  // 0 makes a cone
    float height = 1.0f;
    int sides = 8;
    bool bottom_cap = false;
    std::uint32_t albedo_rgba8 = 0xffffffffu;
    std::uint32_t material_packed = 0;
};

inline std::size_t frustum_triangle_count(const Frustum& f) {
    const auto sides = static_cast<std::size_t>(f.sides);
    return (f.top_radius > 0.0f ? 2 * sides : sides) + (f.bottom_cap ? sides - 2 : 0);
}

// Adds the frustum to the current piece (the caller begins pieces: a tree is one piece).
void add_frustum(ChunkBuilder& builder, const Frustum& frustum);

}  // namespace monoplane::scenes
