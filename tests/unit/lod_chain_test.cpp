// Unit tests of the levels of detail (scenes/lod_chain.h): the chain's shape, its errors checked
// against geometry whose true deviation is known analytically (a sphere), locked borders (no
// crack between chunks), and the chains of the built-in scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <span>
#include <utility>

#include <glm/geometric.hpp>

#include "scenes/chunk_builder.h"
#include "scenes/generate.h"
#include "scenes/icosphere.h"
#include "scenes/lod_chain.h"

namespace monoplane::scenes {
namespace {

Vertex vertex_at(const glm::vec3& position, const glm::vec3& normal) {
    return {position, normal, pack_rgba8(0.5f, 0.5f, 0.5f), pack_material({})};
}

// One chunk: an icosphere of 4 subdivisions (5,120 triangles) of this radius and centre.
Scene sphere_scene(const glm::vec3& centre, float radius) {
    const IcosphereMesh mesh = make_icosphere(4);
    ChunkBuilder builder(kMaxChunkTriangles);
    builder.begin_piece();
    for (const glm::vec3& d : mesh.directions)
        builder.add_vertex(vertex_at(centre + radius * d, d));
    for (const auto& t : mesh.triangles) builder.add_triangle(t[0], t[1], t[2]);
    Scene scene;
    builder.build_into(scene);
    return scene;
}

// An n x n grid of unit squares in the xz plane with a bump, as one open chunk.
Scene bumpy_grid(int n) {
    ChunkBuilder builder(kMaxChunkTriangles);
    builder.begin_piece();
    for (int z = 0; z <= n; ++z) {
        for (int x = 0; x <= n; ++x) {
            const float u =
                (static_cast<float>(x) - 0.5f * static_cast<float>(n)) / static_cast<float>(n);
            const float v =
                (static_cast<float>(z) - 0.5f * static_cast<float>(n)) / static_cast<float>(n);
            const float height = 2.0f * std::exp(-8.0f * (u * u + v * v));
            builder.add_vertex(vertex_at({static_cast<float>(x), height, static_cast<float>(z)},
                                         {0.0f, 1.0f, 0.0f}));
        }
    }
    const auto at = [n](int x, int z) { return static_cast<std::uint32_t>(z * (n + 1) + x); };
    for (int z = 0; z < n; ++z) {
        for (int x = 0; x < n; ++x) {
            builder.add_quad(at(x, z), at(x, z + 1), at(x + 1, z + 1), at(x + 1, z));
        }
    }
    Scene scene;
    builder.build_into(scene);
    return scene;
}

std::span<const std::uint32_t> level_indices(const LodChain& chain, const LodLevel& level) {
    return std::span(chain.indices).subspan(level.first_index, level.index_count);
}

TEST(LodChain, LevelsHalveTheTrianglesAndTheirErrorsGrow) {
    const Scene scene = sphere_scene(glm::vec3(0.0f), 1.0f);
    ASSERT_EQ(scene.chunks.size(), 1u);
    const LodChain chain = build_lod_chain(scene);
    ASSERT_EQ(chain.chunks.size(), scene.chunks.size());
    for (std::size_t c = 0; c < scene.chunks.size(); ++c) {
        const ChunkLods& lods = chain.chunks[c];
        EXPECT_GE(lods.level_count, 4u) << "chunk " << c;
        EXPECT_LT(lods.level_count, kMaxLodLevels);
        std::uint32_t previous_count = scene.chunks[c].index_count;
        float previous_error = 0.0f;
        for (std::uint32_t l = 0; l < lods.level_count; ++l) {
            const LodLevel& level = chain.levels[lods.first_level + l];
            EXPECT_EQ(level.index_count % 3, 0u);
            EXPECT_LE(level.index_count, previous_count * 85 / 100);
            // meshopt aims at 1/2^k of the chunk: within a tenth of it (closed sphere, no
            // locked vertices).
            EXPECT_LE(level.index_count, (scene.chunks[c].index_count >> (l + 1)) * 11 / 10);
            EXPECT_GE(level.error_m, previous_error);
            EXPECT_GT(level.error_m, 0.0f);
            previous_count = level.index_count;
            previous_error = level.error_m;
        }
    }
}

// The true deviation of a level from a sphere of radius r: how far inside the sphere its
// triangles' centroids fall (for a flat triangle with its vertices on the sphere, the centroid is
// near its deepest point), beyond the full-detail mesh's own deviation.
TEST(LodChain, RecordedErrorsBoundTheTrueDeviationFromASphere) {
    const glm::vec3 centre(3.0f, 1.0f, -20.0f);
    const float radius = 2.0f;
    const Scene scene = sphere_scene(centre, radius);
    const LodChain chain = build_lod_chain(scene);
    for (std::size_t c = 0; c < scene.chunks.size(); ++c) {
        const Chunk& chunk = scene.chunks[c];
        const ChunkLods& lods = chain.chunks[c];
        double level0_deviation = 0.0;
        for (std::uint32_t i = 0; i + 2 < chunk.index_count; i += 3) {
            glm::dvec3 sum(0.0);
            for (int k = 0; k < 3; ++k)
                sum +=
                    glm::dvec3(scene.vertices[scene.indices[chunk.first_index + i + k]].position);
            level0_deviation =
                std::max(level0_deviation, radius - glm::length(sum / 3.0 - glm::dvec3(centre)));
        }
        for (std::uint32_t l = 0; l < lods.level_count; ++l) {
            const LodLevel& level = chain.levels[lods.first_level + l];
            const std::span<const std::uint32_t> indices = level_indices(chain, level);
            double deviation = 0.0;
            for (std::size_t i = 0; i + 2 < indices.size(); i += 3) {
                glm::dvec3 sum(0.0);
                for (int k = 0; k < 3; ++k) {
                    sum += glm::dvec3(scene
                                          .vertices[static_cast<std::size_t>(chunk.vertex_offset) +
                                                    indices[i + k]]
                                          .position);
                }
                deviation =
                    std::max(deviation, radius - glm::length(sum / 3.0 - glm::dvec3(centre)));
            }
            // What the level adds to the full-detail mesh's own deviation: within the recorded
            // error, and no gross overestimate either (a budget would then waste triangles).
            const double added = deviation - level0_deviation;
            EXPECT_LE(added, level.error_m) << "level " << l + 1;
            EXPECT_GE(added, level.error_m / 3.0) << "level " << l + 1;
        }
    }
}

// Every boundary edge of an open chunk survives in every level: a neighbouring chunk drawn at
// another level meets it without a crack.
TEST(LodChain, OpenBordersAreKeptInEveryLevel) {
    const Scene scene = bumpy_grid(40);
    ASSERT_EQ(scene.chunks.size(), 1u);
    const LodChain chain = build_lod_chain(scene);
    ASSERT_GE(chain.chunks[0].level_count, 2u);
    // Boundary vertices of the full grid: x or z at 0 or 40.
    std::set<std::uint32_t> border;
    for (std::uint32_t i = 0; i < scene.vertices.size(); ++i) {
        const glm::vec3 p = scene.vertices[i].position;
        if (p.x == 0.0f || p.x == 40.0f || p.z == 0.0f || p.z == 40.0f) border.insert(i);
    }
    ASSERT_EQ(border.size(), 160u);
    for (std::uint32_t l = 0; l < chain.chunks[0].level_count; ++l) {
        const LodLevel& level = chain.levels[chain.chunks[0].first_level + l];
        std::set<std::uint32_t> used;
        for (std::uint32_t index : level_indices(chain, level)) used.insert(index);
        for (std::uint32_t b : border)
            EXPECT_TRUE(used.count(b)) << "level " << l + 1 << " lost " << b;
    }
}

// A flat grid simplifies without moving its surface at all; its levels' error is 0 when it has
// one colour. With a colour gradient (a red bump painted on, as a marker) the dropped vertices
// carried colour the level loses: each level's error is at least its mean edge length.
TEST(LodChain, ColoursTheSimplifierCannotSeeCountAsTheLevelsEdgeLength) {
    for (bool painted : {false, true}) {
        Scene scene = bumpy_grid(32);
        for (Vertex& v : scene.vertices) {
            v.position.y = 0.0f;  // flat
            const float r = (v.position.x - 16.0f) / 16.0f;
            if (painted) v.albedo_rgba8 = pack_rgba8(1.0f - r * r, 0.0f, 0.0f);
        }
        const LodChain chain = build_lod_chain(scene);
        ASSERT_GE(chain.chunks[0].level_count, 3u);
        for (std::uint32_t l = 0; l < chain.chunks[0].level_count; ++l) {
            const LodLevel& level = chain.levels[chain.chunks[0].first_level + l];
            // 32 x 32 m in level.index_count / 3 triangles: an equilateral triangle's edge.
            const double edge =
                std::sqrt(4.0 / std::sqrt(3.0) * 1024.0 / (level.index_count / 3.0));
            if (painted) {
                EXPECT_GE(level.error_m, edge * 0.999) << "level " << l + 1;
            } else {
                EXPECT_LT(level.error_m, 1e-4f) << "level " << l + 1;
            }
        }
    }
}

TEST(LodChain, IsDeterministicAndStaysInsideEachChunksVertexRange) {
    for (SceneId id : {SceneId::Beams, SceneId::Landscape, SceneId::Spheres}) {
        const Scene scene = generate_scene(id, Detail::Test);
        const LodChain chain = build_lod_chain(scene);
        const LodChain again = build_lod_chain(scene);
        EXPECT_EQ(chain.indices, again.indices);
        ASSERT_EQ(chain.chunks.size(), scene.chunks.size());
        std::size_t full = 0;
        std::size_t coarsest = 0;
        for (std::size_t c = 0; c < scene.chunks.size(); ++c) {
            const Chunk& chunk = scene.chunks[c];
            std::uint32_t highest = 0;
            for (std::uint32_t i = 0; i < chunk.index_count; ++i)
                highest = std::max(highest, scene.indices[chunk.first_index + i]);
            const ChunkLods& lods = chain.chunks[c];
            full += chunk.index_count / 3;
            coarsest += (lods.level_count == 0
                             ? chunk.index_count
                             : chain.levels[lods.first_level + lods.level_count - 1].index_count) /
                        3;
            for (std::uint32_t l = 0; l < lods.level_count; ++l) {
                for (std::uint32_t index : level_indices(chain, chain.levels[lods.first_level + l]))
                    ASSERT_LE(index, highest) << scene_name(id) << " chunk " << c;
            }
        }
        std::cerr << scene_name(id) << ": " << full << " triangles, coarsest levels " << coarsest
                  << ", chain " << chain.triangle_count() << "\n";
    }
}

}  // namespace
}  // namespace monoplane::scenes
