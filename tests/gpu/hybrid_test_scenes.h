// Small hand-built scenes for the hybrid accuracy tests: every number in them is known, so the
// tests can derive expected pixels without the renderer.
#pragma once

#include <cmath>

#include "scenes/scene.h"

namespace monoplane::testing {

// Appends a quad (two counter-clockwise triangles seen from the side edge_u x edge_v points to),
// split into n x n cells so chunks and clipping have real work, as one chunk.
inline void add_quad(scenes::Scene& scene, glm::vec3 corner, glm::vec3 edge_u, glm::vec3 edge_v,
                     std::uint32_t albedo, int cells = 1) {
    const glm::vec3 normal = glm::normalize(glm::cross(edge_u, edge_v));
    const std::uint32_t material = scenes::pack_material({0.8f, 0.04f, 0});
    scenes::Chunk chunk;
    chunk.first_index = static_cast<std::uint32_t>(scene.indices.size());
    chunk.vertex_offset = static_cast<std::int32_t>(scene.vertices.size());
    for (int j = 0; j <= cells; ++j) {
        for (int i = 0; i <= cells; ++i) {
            const glm::vec3 p = corner + edge_u * (static_cast<float>(i) / cells) +
                                edge_v * (static_cast<float>(j) / cells);
            scene.vertices.push_back({p, normal, albedo, material});
        }
    }
    for (int j = 0; j < cells; ++j) {
        for (int i = 0; i < cells; ++i) {
            const auto a = static_cast<std::uint32_t>(j * (cells + 1) + i);
            const auto b = a + 1;
            const auto c = a + static_cast<std::uint32_t>(cells + 1) + 1;
            const auto d = a + static_cast<std::uint32_t>(cells + 1);
            for (std::uint32_t index : {a, b, c, a, c, d}) scene.indices.push_back(index);
        }
    }
    chunk.index_count = static_cast<std::uint32_t>(scene.indices.size()) - chunk.first_index;
    const glm::vec3 far_corner = corner + edge_u + edge_v;
    chunk.bounds = {
        glm::min(glm::min(corner, far_corner), glm::min(corner + edge_u, corner + edge_v)),
        glm::max(glm::max(corner, far_corner), glm::max(corner + edge_u, corner + edge_v))};
    scene.chunks.push_back(chunk);
}

inline void finish_bounds(scenes::Scene& scene) {
    scene.bounds = scene.chunks.front().bounds;
    for (const auto& c : scene.chunks) {
        scene.bounds.min = glm::min(scene.bounds.min, c.bounds.min);
        scene.bounds.max = glm::max(scene.bounds.max, c.bounds.max);
    }
}

// An open corridor 3 m wide running 400 m ahead of a viewer at (0, 1.6, 0): a floor and two
// walls, steep to the view, cross every mono plane; above and beyond them is sky, so a gap along
// the plane would show background.
inline scenes::Scene corridor_scene() {
    scenes::Scene scene;
    scene.name = "corridor";
    const float length = 400.0f;
    const std::uint32_t floor = scenes::pack_rgba8(0.55f, 0.5f, 0.45f);
    const std::uint32_t wall = scenes::pack_rgba8(0.35f, 0.45f, 0.6f);
    add_quad(scene, {-1.5f, 0.0f, 2.0f}, {3.0f, 0.0f, 0.0f}, {0.0f, 0.0f, -length}, floor, 24);
    add_quad(scene, {-1.5f, 0.0f, 2.0f}, {0.0f, 0.0f, -length}, {0.0f, 3.0f, 0.0f}, wall, 24);
    add_quad(scene, {1.5f, 0.0f, 2.0f}, {0.0f, 3.0f, 0.0f}, {0.0f, 0.0f, -length}, wall, 24);
    finish_bounds(scene);
    scene.lighting.sun_direction = glm::normalize(glm::vec3(0.3f, 0.9f, 0.2f));
    return scene;
}

// Slabs tilted 35 to 55 degrees to the view axis, staggered in depth from 1.3 m to 70 m in
// front of a viewer at (0, 1.6, 0), so every mono plane crosses steep surfaces (the cutting-line
// case of Sect. 4.3) while sky remains visible between them.
inline scenes::Scene steep_slabs_scene() {
    scenes::Scene scene;
    scene.name = "steep-slabs";
    const int count = 28;
    for (int i = 0; i < count; ++i) {
        const float depth = 1.3f * std::pow(70.0f / 1.3f, static_cast<float>(i) / (count - 1));
        const float side = (i % 3 == 0) ? -1.0f : ((i % 3 == 1) ? 1.0f : 0.0f);
        const float yaw = (35.0f + 20.0f * static_cast<float>((i * 7) % 5) / 4.0f) * 0.0174533f;
        const glm::vec3 centre(side * 0.35f * depth, 1.6f + ((i % 2) ? 0.08f : -0.1f) * depth,
                               -depth);
        const float half = 0.3f * depth;
        // Along the slab: towards the viewer's side and into the depth, at `yaw` to the axis.
        const glm::vec3 along(std::sin(yaw) * (side == 0.0f ? 1.0f : -side), 0.0f, -std::cos(yaw));
        const glm::vec3 up(0.0f, 1.0f, 0.0f);
        const glm::vec3 edge_u = along * (2.0f * half);
        const glm::vec3 edge_v = up * (1.2f * half);
        glm::vec3 corner = centre - 0.5f * edge_u - 0.5f * edge_v;
        const std::uint32_t albedo = scenes::pack_rgba8(0.3f + 0.02f * (i % 10), 0.5f, 0.4f);
        // Facing the viewer: flip the winding if the normal points away.
        const glm::vec3 normal = glm::cross(edge_u, edge_v);
        if (glm::dot(normal, glm::vec3(0.0f, 1.6f, 0.0f) - centre) < 0.0f) {
            add_quad(scene, corner, edge_v, edge_u, albedo, 8);
        } else {
            add_quad(scene, corner, edge_u, edge_v, albedo, 8);
        }
    }
    finish_bounds(scene);
    scene.lighting.sun_direction = glm::normalize(glm::vec3(0.3f, 0.9f, 0.4f));
    return scene;
}

// A square facing the viewer (+z), centred at `centre`, whose red albedo rises smoothly from 0
// at its border to 1 at its centre: an intensity-weighted centroid of it is sub-pixel exact,
// where a hard-edged marker's centroid is quantised by rasterisation (up to half a pixel).
inline scenes::Scene marker_scene(glm::vec3 centre, float half_size) {
    scenes::Scene scene;
    scene.name = "marker";
    const glm::vec3 corner = centre - glm::vec3(half_size, half_size, 0.0f);
    add_quad(scene, corner, {2 * half_size, 0.0f, 0.0f}, {0.0f, 2 * half_size, 0.0f}, 0u, 32);
    for (scenes::Vertex& v : scene.vertices) {
        const glm::vec2 r = (glm::vec2(v.position) - glm::vec2(centre)) / half_size;
        const float bump = (1.0f - r.x * r.x) * (1.0f - r.y * r.y);
        v.albedo_rgba8 = scenes::pack_rgba8(bump * bump, 0.0f, 0.0f);
    }
    finish_bounds(scene);
    scene.lighting.sun_direction = glm::normalize(glm::vec3(0.2f, 0.5f, 1.0f));
    return scene;
}

}  // namespace monoplane::testing
