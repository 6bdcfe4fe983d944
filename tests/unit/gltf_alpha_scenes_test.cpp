// The alpha-mode scenes the GPU tests render (tests/gpu/alpha_scenes.h), written and loaded on the
// CPU: their chunks per alpha mode and cut-off, textures, texture coordinates against the exported
// geometry, viewpoint, and the panes' layout seen from the eye.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include <glm/geometric.hpp>

#include "scenes/gltf/load_gltf.h"
#include "scenes/lod_chain.h"
#include "tests/gpu/alpha_scenes.h"
#include "tests/unit/gltf_scene_checks.h"
#include "tests/unit/gltf_test_files.h"

namespace monoplane::scenes {
namespace {

namespace alpha = monoplane::testing;

Scene load(const std::filesystem::path& file) {
    Result<Scene> scene = load_gltf_scene(file, testing::quiet());
    EXPECT_TRUE(scene.ok()) << scene.error().message;
    if (!scene.ok()) return Scene{};
    testing::expect_well_formed(*scene);
    return std::move(scene).value();
}

std::map<AlphaMode, int> chunks_per_mode(const Scene& scene) {
    std::map<AlphaMode, int> count;
    for (const Chunk& chunk : scene.chunks) ++count[chunk.alpha_mode];
    return count;
}

bool near(const glm::vec3& a, const glm::vec3& b) {
    return glm::length(a - b) < 1e-4f;
}

// Whether every vertex of the chunk lies on the quad at its texture coordinates.
bool chunk_follows(const Scene& scene, const Chunk& chunk, const alpha::AlphaQuad& quad) {
    for (std::uint32_t i = 0; i < chunk.index_count; ++i) {
        const std::size_t v =
            scene.indices[chunk.first_index + i] + static_cast<std::size_t>(chunk.vertex_offset);
        if (!near(scene.vertices[v].position, quad.at(scene.texcoords[v]))) return false;
    }
    return true;
}

std::uint32_t alpha_byte(std::uint32_t rgba8) {
    return rgba8 >> 24;
}

TEST(AlphaScenes, QuadGeometry) {
    EXPECT_TRUE(near(alpha::kFenceChecker.normal(), {0, 0, 1}));
    EXPECT_TRUE(near(alpha::kFenceChecker.centre(), {0.0f, 1.75f, -4.0f}));
    EXPECT_TRUE(near(alpha::kFenceHigh.normal(), {0, 1, 0}));
    EXPECT_TRUE(near(alpha::kFenceHigh.centre(), {0.0f, 3.5f, -4.0f}));
    EXPECT_TRUE(near(alpha::kAlphaGround.normal(), {0, 1, 0}));
    EXPECT_TRUE(near(alpha::kAlphaBackdrop.normal(), {0, 0, 1}));
    EXPECT_TRUE(near(alpha::kNearRedPane.quad.centre(), {-1.2f, 1.6f, -3.0f}));
    EXPECT_TRUE(near(alpha::kFarBluePane.quad.centre(), {1.5f, 1.6f, -14.0f}));
    EXPECT_TRUE(near(alpha::kBehindNearPane.quad.centre(), {-1.2f, 1.6f, -6.0f}));
    EXPECT_TRUE(alpha::checker_opaque({0.01f, 0.01f}));
    EXPECT_FALSE(alpha::checker_opaque({0.13f, 0.01f}));
    EXPECT_FALSE(alpha::checker_opaque({0.01f, 0.13f}));
    EXPECT_TRUE(alpha::checker_opaque({0.99f, 0.99f}));
    EXPECT_FLOAT_EQ(alpha::gradient_alpha({0.3f, 0.9f}), 0.3f);
    const glm::vec3 shadow = alpha::ground_shadow({0.0f, 3.5f, -4.0f}, {0.3f, 0.8f, 0.4f});
    EXPECT_TRUE(near(shadow, {-1.3125f, 0.0f, -5.75f}));
}

TEST(AlphaScenes, FenceSceneLoadsWithItsCutOuts) {
    const auto dir = testing::test_directory("alpha_fence");
    const Scene scene = load(alpha::write_fence_scene(dir, {.gradient_cutoff = 0.3f}));
    EXPECT_EQ(chunks_per_mode(scene),
              (std::map<AlphaMode, int>{{AlphaMode::kOpaque, 1}, {AlphaMode::kMask, 2}}));
    ASSERT_EQ(scene.textures.size(), 2u);
    ASSERT_EQ(scene.texcoords.size(), scene.vertices.size());
    int checked = 0;
    for (const Chunk& chunk : scene.chunks) {
        if (chunk.alpha_mode == AlphaMode::kOpaque) {
            EXPECT_EQ(chunk.texture, -1);
            EXPECT_EQ(chunk.index_count, 12u);  // ground and backdrop
            continue;
        }
        ASSERT_GE(chunk.texture, 0);
        const SceneTexture& texture = scene.textures[static_cast<std::size_t>(chunk.texture)];
        ASSERT_EQ(texture.width, static_cast<std::uint32_t>(alpha::kAlphaTextureSize));
        ASSERT_EQ(texture.height, static_cast<std::uint32_t>(alpha::kAlphaTextureSize));
        EXPECT_EQ(texture.wrap_u, TextureWrap::ClampToEdge);
        EXPECT_EQ(texture.wrap_v, TextureWrap::ClampToEdge);
        const bool checker = texture.name.find("checker") != std::string::npos;
        if (checker) {
            EXPECT_FLOAT_EQ(chunk.alpha_cutoff, 0.5f);
            // The fence (2 triangles) and the double-sided high quad (4).
            EXPECT_EQ(chunk.index_count, 18u);
            EXPECT_NEAR(chunk.bounds.max.y, 3.5f, 1e-5f);
        } else {
            EXPECT_FLOAT_EQ(chunk.alpha_cutoff, 0.3f);
            EXPECT_EQ(chunk.index_count, 6u);
            EXPECT_TRUE(chunk_follows(scene, chunk, alpha::kFenceGradient));
        }
        // Every texel's alpha is what the header says, row 0 at v = 0.
        const int n = alpha::kAlphaTextureSize;
        for (int row = 0; row < n; ++row) {
            for (int column = 0; column < n; ++column) {
                const std::uint8_t* texel =
                    &texture.rgba8_srgb[4 * (static_cast<std::size_t>(row) * n + column)];
                const glm::vec2 uv((column + 0.5f) / n, (row + 0.5f) / n);
                if (checker) {
                    EXPECT_EQ(texel[3], alpha::checker_opaque(uv) ? 255 : 0);
                    EXPECT_EQ(texel[0], alpha::kCheckerTexel[0]);
                } else {
                    EXPECT_NEAR(texel[3], 255.0f * alpha::gradient_alpha(uv), 0.5f);
                    EXPECT_EQ(texel[2], alpha::kGradientTexel[2]);
                }
            }
        }
        ++checked;
    }
    EXPECT_EQ(checked, 2);
    // The fence's and the high quad's vertices lie where their texture coordinates say.
    for (std::size_t v = 0; v < scene.vertices.size(); ++v) {
        const glm::vec3& p = scene.vertices[v].position;
        if (std::fabs(p.y - 3.5f) < 1e-5f) {
            EXPECT_TRUE(near(p, alpha::kFenceHigh.at(scene.texcoords[v])));
        } else if (std::fabs(p.z + 4.0f) < 1e-5f && p.x < 2.1f) {
            EXPECT_TRUE(near(p, alpha::kFenceChecker.at(scene.texcoords[v])));
        }
    }
    // Masked chunks keep full detail only.
    const LodChain chain = build_lod_chain(scene);
    for (std::size_t c = 0; c < scene.chunks.size(); ++c) {
        if (scene.chunks[c].alpha_mode == AlphaMode::kMask) {
            EXPECT_EQ(chain.chunks[c].level_count, 0u);
        }
    }
    // The default viewpoint is the glTF camera's.
    ASSERT_FALSE(scene.viewpoints.empty());
    EXPECT_EQ(scene.viewpoints[0].name, "default");
    EXPECT_TRUE(near(glm::vec3(scene.viewpoints[0].head.position), alpha::kAlphaSceneEye));
    const glm::dvec3 forward = scene.viewpoints[0].head.orientation * glm::dvec3(0, 0, -1);
    EXPECT_NEAR(forward.z, -1.0, 1e-9);
}

TEST(AlphaScenes, FenceVariants) {
    const auto dir = testing::test_directory("alpha_fence_variants");
    const auto half = alpha::write_fence_scene(dir);
    const auto opaque = alpha::write_fence_scene(dir, {.masked = false});
    EXPECT_NE(half, opaque);
    EXPECT_EQ(half.filename(), "fence_mask_0.500.gltf");
    const Scene masked = load(half);
    for (const Chunk& chunk : masked.chunks) EXPECT_FLOAT_EQ(chunk.alpha_cutoff, 0.5f);
    EXPECT_EQ(chunks_per_mode(masked)[AlphaMode::kMask], 2);
    const Scene reference = load(opaque);
    EXPECT_EQ(chunks_per_mode(reference), (std::map<AlphaMode, int>{{AlphaMode::kOpaque, 3}}));
    EXPECT_EQ(reference.triangle_count(), masked.triangle_count());
}

TEST(AlphaScenes, PaneSceneHasOneBlendedChunkPerPane) {
    const auto dir = testing::test_directory("alpha_panes");
    const Scene scene = load(alpha::write_pane_scene(dir));
    EXPECT_EQ(chunks_per_mode(scene),
              (std::map<AlphaMode, int>{{AlphaMode::kOpaque, 1}, {AlphaMode::kBlend, 4}}));
    std::vector<std::string> found;
    for (const Chunk& chunk : scene.chunks) {
        if (chunk.alpha_mode != AlphaMode::kBlend) continue;
        EXPECT_FLOAT_EQ(chunk.alpha_cutoff, 0.5f);
        EXPECT_EQ(chunk.index_count, 6u);
        const glm::vec3 centre = 0.5f * (chunk.bounds.min + chunk.bounds.max);
        for (const alpha::AlphaPane& pane : alpha::kAlphaPanes) {
            if (!near(centre, pane.quad.centre())) continue;
            found.push_back(pane.quad.name);
            EXPECT_EQ(chunk.texture >= 0, pane.textured) << pane.quad.name;
            const Vertex& v = scene.vertices[static_cast<std::size_t>(chunk.vertex_offset)];
            EXPECT_EQ(alpha_byte(v.albedo_rgba8),
                      static_cast<std::uint32_t>(std::lround(pane.colour.a * 255.0f)))
                << pane.quad.name;
            EXPECT_EQ(v.albedo_rgba8 & 0xffu,
                      static_cast<std::uint32_t>(std::lround(pane.colour.r * 255.0f)));
            if (pane.textured) {
                EXPECT_TRUE(chunk_follows(scene, chunk, pane.quad));
            }
        }
    }
    std::sort(found.begin(), found.end());
    EXPECT_EQ(found, (std::vector<std::string>{"behind_near", "far_blue", "gradient", "near_red"}));
    const LodChain chain = build_lod_chain(scene);
    for (std::size_t c = 0; c < scene.chunks.size(); ++c) {
        if (scene.chunks[c].alpha_mode == AlphaMode::kBlend) {
            EXPECT_EQ(chain.chunks[c].level_count, 0u);
        }
    }
}

TEST(AlphaScenes, PaneVariants) {
    const auto dir = testing::test_directory("alpha_pane_variants");
    const Scene opaque = load(alpha::write_pane_scene(dir, {.blended = false}));
    EXPECT_EQ(chunks_per_mode(opaque), (std::map<AlphaMode, int>{{AlphaMode::kOpaque, 2}}));
    EXPECT_EQ(opaque.triangle_count(), 12u);
    const Scene empty = load(alpha::write_pane_scene(dir, {.with_panes = false}));
    EXPECT_EQ(chunks_per_mode(empty), (std::map<AlphaMode, int>{{AlphaMode::kOpaque, 1}}));
    EXPECT_EQ(empty.triangle_count(), 4u);
    EXPECT_TRUE(empty.textures.empty());
    const Scene blended = load(alpha::write_pane_scene(dir));
    EXPECT_EQ(blended.triangle_count(), 12u);
}

// The layout the header states: seen from the eye, only near_red and behind_near overlap, and
// every pane is within 37 degrees of the view axis.
TEST(AlphaScenes, PanesSeenFromTheEye) {
    struct Extent {
        float x0, x1, y0, y1;
    };
    const auto extent = [](const alpha::AlphaQuad& quad) {
        const glm::vec3 a = quad.at({0, 0}) - alpha::kAlphaSceneEye;
        const glm::vec3 b = quad.at({1, 1}) - alpha::kAlphaSceneEye;
        const float distance = -a.z;
        return Extent{std::min(a.x, b.x) / distance, std::max(a.x, b.x) / distance,
                      std::min(a.y, b.y) / distance, std::max(a.y, b.y) / distance};
    };
    const auto overlap = [](const Extent& a, const Extent& b) {
        return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
    };
    for (std::size_t i = 0; i < alpha::kAlphaPanes.size(); ++i) {
        const Extent e = extent(alpha::kAlphaPanes[i].quad);
        const float limit = std::tan(37.0f * 3.14159265f / 180.0f);
        EXPECT_LT(std::max({std::fabs(e.x0), std::fabs(e.x1), std::fabs(e.y0), std::fabs(e.y1)}),
                  limit);
        for (std::size_t j = i + 1; j < alpha::kAlphaPanes.size(); ++j) {
            const std::string pair = std::string(alpha::kAlphaPanes[i].quad.name) + "+" +
                                     alpha::kAlphaPanes[j].quad.name;
            EXPECT_EQ(overlap(e, extent(alpha::kAlphaPanes[j].quad)),
                      pair == "near_red+behind_near")
                << pair;
        }
    }
    const Extent red = extent(alpha::kNearRedPane.quad);
    const Extent behind = extent(alpha::kBehindNearPane.quad);
    EXPECT_NEAR(red.x1, -0.2333f, 1e-3f);
    EXPECT_LT(behind.x0, red.x1);
    EXPECT_GT(behind.x1, red.x1);  // partly uncovered
    EXPECT_GT(behind.y0, red.y0);
    EXPECT_LT(behind.y1, red.y1);
}

}  // namespace
}  // namespace monoplane::scenes
