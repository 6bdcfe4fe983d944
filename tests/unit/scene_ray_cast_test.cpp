// Where a ray meets a scene (scenes/scene_ray_cast.h): hand-built quads at known places, whose
// hits follow from the geometry alone, and the refusals.
#include <gtest/gtest.h>

#include <cmath>

#include "scenes/scene.h"
#include "scenes/scene_ray_cast.h"

namespace monoplane::scenes {
namespace {

// A quad of two triangles in the plane z = depth (world frame), x in [x0, x1], y in [y0, y1],
// as one chunk of its own.
void add_quad(Scene& scene, float x0, float x1, float y0, float y1, float z,
              AlphaMode mode = AlphaMode::kOpaque) {
    Chunk chunk;
    chunk.first_index = static_cast<std::uint32_t>(scene.indices.size());
    chunk.vertex_offset = static_cast<std::int32_t>(scene.vertices.size());
    chunk.index_count = 6;
    chunk.alpha_mode = mode;
    for (const auto& [x, y] : {std::pair{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}) {
        scene.vertices.push_back(Vertex{{x, y, z}, {0.0f, 0.0f, 1.0f}, 0xffffffffu, 0});
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) scene.indices.push_back(i);
    scene.chunks.push_back(chunk);
}

TEST(SceneRayCast, TheNearestSurfaceAlongTheRayIsMet) {
    Scene scene;
    add_quad(scene, -5, 5, 0, 4, -12.0f);  // a wall 12 m ahead
    add_quad(scene, 1, 2, 1, 2, -7.0f);    // a panel to the right, nearer
    const auto caster = SceneRayCaster::build(scene).value_or_throw();
    // Straight ahead from eye height: the wall.
    const auto wall = caster->cast({0.0, 1.7, 0.0}, {0.0, 0.0, -1.0});
    ASSERT_TRUE(wall);
    EXPECT_NEAR(wall->distance, 12.0, 1e-5);
    EXPECT_NEAR(wall->point.z, -12.0, 1e-5);
    EXPECT_EQ(wall->chunk, 0);
    // Towards the panel's centre (1.5, 1.5, -7): it hides the wall behind it.
    const glm::dvec3 to_panel(1.5, -0.2, -7.0);
    const auto panel = caster->cast({0.0, 1.7, 0.0}, to_panel);
    ASSERT_TRUE(panel);
    EXPECT_NEAR(panel->distance, 1.0, 1e-6);  // in units of the direction's length
    EXPECT_NEAR(glm::length(panel->point - glm::dvec3(1.5, 1.5, -7.0)), 0.0, 1e-5);
    EXPECT_EQ(panel->chunk, 1);
    // 20 degrees to the left: the wall at 12 / cos 20 (x = -4.37, within it).
    const double a = 20.0 * 3.14159265358979323846 / 180.0;
    const auto oblique = caster->cast({0.0, 1.7, 0.0}, {-std::sin(a), 0.0, -std::cos(a)});
    ASSERT_TRUE(oblique);
    EXPECT_NEAR(oblique->distance, 12.0 / std::cos(a), 1e-5);
    // Over the wall, and backwards: the sky.
    EXPECT_FALSE(caster->cast({0.0, 1.7, 0.0}, {0.0, 1.0, -1.0}));
    EXPECT_FALSE(caster->cast({0.0, 1.7, 0.0}, {0.0, 0.0, 1.0}));
}

// The eye's depth passes through blended surfaces (glass writes no depth): so does the ray.
// Masked chunks count whole.
TEST(SceneRayCast, BlendedChunksArePassedThroughAndMaskedOnesCount) {
    Scene scene;
    add_quad(scene, -5, 5, 0, 4, -3.0f, AlphaMode::kBlend);
    add_quad(scene, -5, 5, 0, 4, -12.0f);
    add_quad(scene, -1, 1, 0, 4, -6.0f, AlphaMode::kMask);
    const auto caster = SceneRayCaster::build(scene).value_or_throw();
    const auto masked = caster->cast({0.0, 1.7, 0.0}, {0.0, 0.0, -1.0});
    ASSERT_TRUE(masked);
    EXPECT_NEAR(masked->distance, 6.0, 1e-5);
    EXPECT_EQ(masked->chunk, 2);
    const auto wall = caster->cast({3.0, 1.7, 0.0}, {0.0, 0.0, -1.0});
    ASSERT_TRUE(wall);
    EXPECT_NEAR(wall->distance, 12.0, 1e-5);
    EXPECT_EQ(wall->chunk, 1);
}

TEST(SceneRayCast, AnEmptySceneIsAllSkyAndABadIndexIsRefused) {
    Scene empty;
    EXPECT_FALSE(SceneRayCaster::build(empty).value_or_throw()->cast({0, 0, 0}, {0, 0, -1}));
    Scene broken;
    broken.name = "broken";
    add_quad(broken, -1, 1, -1, 1, -2.0f);
    broken.indices[4] = 9;
    const auto refused = SceneRayCaster::build(broken);
    ASSERT_FALSE(refused.ok());
    EXPECT_EQ(refused.error().message, "scene 'broken': chunk 0 indexes vertex 9 of 4");
}

}  // namespace
}  // namespace monoplane::scenes
