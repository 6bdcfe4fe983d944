// Reading an imported scene back for the glTF tests: its triangles in world space, and the
// structural invariants every scene must keep (scene.h, chunk_builder.h).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include <glm/geometric.hpp>

#include "scenes/chunk_builder.h"
#include "scenes/scene.h"

namespace monoplane::scenes::testing {

struct WorldTriangle {
    std::array<glm::vec3, 3> p;
    std::array<glm::vec3, 3> n;
    std::array<std::uint32_t, 3> albedo;
    std::int32_t texture = -1;
};

inline std::vector<WorldTriangle> triangles_of(const Scene& scene) {
    std::vector<WorldTriangle> result;
    for (const Chunk& chunk : scene.chunks) {
        for (std::uint32_t i = chunk.first_index; i < chunk.first_index + chunk.index_count;
             i += 3) {
            WorldTriangle t;
            for (std::uint32_t k = 0; k < 3; ++k) {
                const Vertex& v = scene.vertices[scene.indices[i + k] +
                                                 static_cast<std::uint32_t>(chunk.vertex_offset)];
                t.p[k] = v.position;
                t.n[k] = v.normal;
                t.albedo[k] = v.albedo_rgba8;
            }
            t.texture = chunk.texture;
            result.push_back(t);
        }
    }
    return result;
}

inline bool near(const glm::vec3& a, const glm::vec3& b, float tolerance = 1e-5f) {
    return glm::length(a - b) <= tolerance;
}

// Whether the scene has a triangle a, b, c in this cyclic order (same winding, any start).
inline bool has_triangle(const Scene& scene, const glm::vec3& a, const glm::vec3& b,
                         const glm::vec3& c, float tolerance = 1e-5f) {
    for (const WorldTriangle& t : triangles_of(scene)) {
        for (int r = 0; r < 3; ++r) {
            if (near(t.p[r], a, tolerance) && near(t.p[(r + 1) % 3], b, tolerance) &&
                near(t.p[(r + 2) % 3], c, tolerance)) {
                return true;
            }
        }
    }
    return false;
}

inline bool finite3(const glm::vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Chunks tile the index buffer, indices stay in range, bounds are tight, chunk sizes are within
// the limit, textures are in range and texcoords parallel, normals unit, triangles wind
// counter-clockwise about their normals.
inline void expect_well_formed(const Scene& scene,
                               std::uint32_t max_chunk_triangles = kMaxChunkTriangles) {
    ASSERT_FALSE(scene.chunks.empty());
    ASSERT_EQ(scene.indices.size() % 3, 0u);
    if (!scene.textures.empty()) {
        ASSERT_EQ(scene.texcoords.size(), scene.vertices.size());
    }
    std::uint64_t next = 0;
    for (const Chunk& chunk : scene.chunks) {
        ASSERT_EQ(chunk.first_index, next);
        next += chunk.index_count;
        ASSERT_EQ(chunk.index_count % 3, 0u);
        ASSERT_GT(chunk.index_count, 0u);
        EXPECT_LE(chunk.index_count / 3, max_chunk_triangles);
        ASSERT_GE(chunk.vertex_offset, 0);
        ASSERT_TRUE(chunk.texture == -1 ||
                    (chunk.texture >= 0 &&
                     static_cast<std::size_t>(chunk.texture) < scene.textures.size()));
        Aabb tight{glm::vec3(std::numeric_limits<float>::max()),
                   glm::vec3(std::numeric_limits<float>::lowest())};
        for (std::uint32_t i = chunk.first_index; i < chunk.first_index + chunk.index_count; ++i) {
            const std::uint64_t v =
                std::uint64_t{scene.indices[i]} + static_cast<std::uint64_t>(chunk.vertex_offset);
            ASSERT_LT(v, scene.vertices.size());
            tight.min = glm::min(tight.min, scene.vertices[v].position);
            tight.max = glm::max(tight.max, scene.vertices[v].position);
        }
        EXPECT_EQ(chunk.bounds.min, tight.min);
        EXPECT_EQ(chunk.bounds.max, tight.max);
        EXPECT_TRUE(glm::all(glm::lessThanEqual(scene.bounds.min, chunk.bounds.min)));
        EXPECT_TRUE(glm::all(glm::greaterThanEqual(scene.bounds.max, chunk.bounds.max)));
    }
    EXPECT_EQ(next, scene.indices.size());
    std::size_t wrong = 0;
    for (const WorldTriangle& t : triangles_of(scene)) {
        for (int k = 0; k < 3; ++k) {
            ASSERT_TRUE(finite3(t.p[k]) && finite3(t.n[k]));
            ASSERT_NEAR(glm::length(t.n[k]), 1.0f, 1e-3f);
        }
        const glm::vec3 face = glm::cross(t.p[1] - t.p[0], t.p[2] - t.p[0]);
        wrong += glm::dot(face, t.n[0] + t.n[1] + t.n[2]) < 0.0f;
    }
    EXPECT_EQ(wrong, 0u);
}

}  // namespace monoplane::scenes::testing
