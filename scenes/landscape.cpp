#include "scenes/landscape.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "scenes/chunk_builder.h"
#include "scenes/color.h"
#include "scenes/detail.h"
#include "scenes/icosphere.h"
#include "scenes/lathe_mesh.h"
#include "scenes/noise.h"
#include "scenes/polar_grid.h"
#include "scenes/random.h"
#include "scenes/terrain.h"

namespace monoplane::scenes {
namespace {

struct LandscapeParameters {
    int terrain_sectors;
    int rocks;
    int rock_subdivisions;
    int trees;
    int tree_sides;
    int crown_subdivisions;
};

const PerDetail<LandscapeParameters> kLandscapeParameters = {{
    {96, 120, 1, 150, 5, 1},
    {256, 500, 1, 800, 7, 1},
    {384, 800, 2, 1500, 10, 2},
    {768, 2500, 2, 4000, 14, 2},
    {1280, 5000, 2, 9000, 18, 3},
}};

constexpr float kTerrainRadius = 700.0f;
// Terrain blocks beginning this far from the centre are forced to the mono camera (the polar
// grid's blocks begin at about 0.5, 2.2, 10, 45 and 200 m).
constexpr float kForceMonoTerrainRadius = 40.0f;
constexpr float kFarthestObject = 450.0f;

enum LandscapeStream : std::uint64_t { kRockPlacement = 1, kRockShape, kTreePlacement, kTreeShape };

// Ground position at this distance from the origin: mostly ahead, some all around (a
// participant may look about).
glm::vec2 scatter(float distance, Random& random, double ahead_probability) {
    const float pi = static_cast<float>(std::numbers::pi);
    const float bearing =
        random.chance(ahead_probability) ? random.uniform(-1.4f, 1.4f) : random.uniform(-pi, pi);
    return {distance * std::sin(bearing), -distance * std::cos(bearing)};
}

// Distance for object i of count: mostly uniform over the ground's area, as things lie in
// nature (few near, many far), plus a log-uniform share so that arm's length and every
// mono-plane distance get some. Stratified, so every detail level keeps the same spread.
float spread_distance(int i, int count, float nearest, float farthest, int log_share_percent,
                      Random& random) {
    const bool log_uniform = (i * 37) % 100 < log_share_percent;
    const float u =
        (static_cast<float>(i) + random.uniform(0.0f, 1.0f)) / static_cast<float>(count);
    if (log_uniform) return nearest * std::pow(farthest / nearest, u);
    return std::sqrt(nearest * nearest + (farthest * farthest - nearest * nearest) * u);
}

// Rocks: icospheres displaced by 3D noise, squashed, flat shaded with a tint per face.
void add_rocks(ChunkBuilder& builder, const Terrain& terrain, const LandscapeParameters& parameters,
               std::uint64_t seed) {
    const IcosphereMesh sphere = make_icosphere(parameters.rock_subdivisions);
    const glm::vec3 kRockColours[] = {from_srgb(0x8a847c), from_srgb(0x6f6a63),
                                      from_srgb(0x9a8f80)};
    const std::uint32_t material = pack_material({0.8f, 0.04f, 0});
    Random placement(seed, kRockPlacement);
    Random shape(seed, kRockShape);
    std::vector<glm::vec3> corners(sphere.directions.size());
    for (int i = 0; i < parameters.rocks; ++i) {
        const float distance =
            spread_distance(i, parameters.rocks, 1.6f, kFarthestObject, 25, placement);
        const glm::vec2 ground = scatter(distance, placement, 0.8);
        const float size = (0.12f + 0.012f * distance) * placement.uniform(0.5f, 1.6f);
        const glm::vec3 stretch{shape.uniform(0.8f, 1.3f), shape.uniform(0.45f, 0.8f),
                                shape.uniform(0.8f, 1.3f)};
        const float yaw = shape.uniform(0.0f, 6.2832f);
        const std::uint64_t noise_seed = shape.next_u64();
        const glm::vec3 base_colour = kRockColours[shape.uniform_int(0, 2)];
        // Sunk by a third of its height below the lowest ground under its footprint, so that it
        // sits in the ground rather than on it, also on a slope.
        const float reach = size * std::max(stretch.x, stretch.z);
        float lowest = terrain.height(ground);
        for (const glm::vec2 offset : {glm::vec2(reach, 0.0f), glm::vec2(-reach, 0.0f),
                                       glm::vec2(0.0f, reach), glm::vec2(0.0f, -reach)}) {
            lowest = std::min(lowest, terrain.height(ground + offset));
        }
        const glm::vec3 centre{ground.x, lowest - 0.3f * size * stretch.y, ground.y};
        const float c = std::cos(yaw);
        const float s = std::sin(yaw);
        for (std::size_t v = 0; v < corners.size(); ++v) {
            const glm::vec3 d = sphere.directions[v];
            const float bump = 1.0f + 0.3f * fractal_noise(d * 1.7f, noise_seed, {3, 2.0f, 0.5f});
            const glm::vec3 local = d * stretch * (bump * size);
            corners[v] =
                centre + glm::vec3(c * local.x + s * local.z, local.y, -s * local.x + c * local.z);
        }
        builder.begin_piece();
        for (const auto& triangle : sphere.triangles) {
            const glm::vec3 a = corners[triangle[0]];
            const glm::vec3 b = corners[triangle[1]];
            const glm::vec3 e = corners[triangle[2]];
            const glm::vec3 face = glm::cross(b - a, e - a);
            if (glm::dot(face, face) < 1e-14f) continue;  // squashed flat: nothing to see
            Vertex vertex{};
            vertex.normal = glm::normalize(face);
            vertex.albedo_rgba8 = pack_albedo(base_colour * shape.uniform(0.85f, 1.1f));
            vertex.material_packed = material;
            const std::uint32_t first = builder.piece_vertex_count();
            for (const glm::vec3& p : {a, b, e}) {
                vertex.position = p;
                builder.add_vertex(vertex);
            }
            builder.add_triangle(first, first + 1, first + 2);
        }
    }
}

// A leafy crown: an icosphere with a lumpy outline and smooth (unperturbed) normals.
void add_crown(ChunkBuilder& builder, const IcosphereMesh& sphere, glm::vec3 centre,
               glm::vec3 radii, std::uint64_t noise_seed, std::uint32_t albedo) {
    Vertex vertex{};
    vertex.albedo_rgba8 = albedo;
    vertex.material_packed = pack_material({0.85f, 0.03f, 0});
    const std::uint32_t first = builder.piece_vertex_count();
    for (const glm::vec3& d : sphere.directions) {
        const float lump = 1.0f + 0.18f * gradient_noise(d * 2.5f, noise_seed);
        vertex.position = centre + d * radii * lump;
        vertex.normal = d;
        builder.add_vertex(vertex);
    }
    for (const auto& t : sphere.triangles)
        builder.add_triangle(first + t[0], first + t[1], first + t[2]);
}

// Trees in loose forests below the tree line: conifers (stacked cones) and broadleaves (a
// trunk and a round crown), at their natural size, so far ones shrink with distance.
void add_trees(ChunkBuilder& builder, const Terrain& terrain, const LandscapeParameters& parameters,
               std::uint64_t seed) {
    const IcosphereMesh crown_sphere = make_icosphere(parameters.crown_subdivisions);
    const std::uint32_t bark = pack_albedo(from_srgb(0x5a4330));
    const std::uint32_t bark_material = pack_material({0.9f, 0.02f, 0});
    const std::uint32_t foliage_material = pack_material({0.85f, 0.03f, 0});
    const glm::vec3 kConifer = from_srgb(0x2f4f26);
    const glm::vec3 kBroadleaf = from_srgb(0x4f7a2a);
    Random placement(seed, kTreePlacement);
    Random shape(seed, kTreeShape);
    const std::uint64_t forest_seed = mix64(seed ^ 0x666f72657374ULL);
    for (int i = 0; i < parameters.trees; ++i) {
        glm::vec2 ground{0.0f};
        bool found = false;
        for (int attempt = 0; attempt < 20 && !found; ++attempt) {
            const float distance =
                spread_distance(i, parameters.trees, 6.0f, kFarthestObject, 4, placement);
            ground = scatter(distance, placement, 0.8);
            // Keep the view straight ahead open: no trunk right in front of the participant.
            const bool in_the_way =
                distance < 25.0f && ground.y < 0.0f && std::fabs(ground.x) < 4.0f;
            const float forest = fractal_noise(ground / 90.0f, forest_seed, {3, 2.0f, 0.5f});
            const float h = terrain.height(ground);
            const glm::vec3 n = terrain.normal(ground, 1.0f);
            found = !in_the_way && forest > -0.15f && h < Terrain::kTreeLine && n.y > 0.85f;
        }
        if (!found) continue;
        const float height = shape.uniform(5.0f, 13.0f);
        const glm::vec3 base{ground.x, terrain.height(ground) - 0.3f, ground.y};
        const float tint = shape.uniform(0.8f, 1.15f);
        builder.begin_piece();
        Frustum trunk;
        trunk.base = base;
        trunk.sides = parameters.tree_sides;
        trunk.albedo_rgba8 = bark;
        trunk.material_packed = bark_material;
        if (shape.chance(0.6)) {
            trunk.bottom_radius = 0.025f * height;
            trunk.top_radius = 0.6f * trunk.bottom_radius;
            trunk.height = 0.35f * height;
            add_frustum(builder, trunk);
            const float crown_radius = 0.22f * height * shape.uniform(0.85f, 1.15f);
            for (int tier = 0; tier < 3; ++tier) {
                Frustum cone;
                cone.base =
                    base +
                    glm::vec3(0.0f, height * (0.25f + 0.2f * static_cast<float>(tier)), 0.0f);
                cone.bottom_radius = crown_radius * (1.0f - 0.25f * static_cast<float>(tier));
                cone.top_radius = 0.0f;
                cone.height = height * (0.45f - 0.05f * static_cast<float>(tier));
                cone.sides = parameters.tree_sides;
                cone.bottom_cap = true;
                cone.albedo_rgba8 = pack_albedo(kConifer * tint);
                cone.material_packed = foliage_material;
                add_frustum(builder, cone);
            }
        } else {
            trunk.bottom_radius = 0.03f * height;
            trunk.top_radius = 0.7f * trunk.bottom_radius;
            trunk.height = 0.55f * height;
            add_frustum(builder, trunk);
            const float radius = 0.3f * height * shape.uniform(0.85f, 1.15f);
            const glm::vec3 radii{radius, 0.8f * radius, radius};
            add_crown(builder, crown_sphere, base + glm::vec3(0.0f, height - 0.8f * radius, 0.0f),
                      radii, shape.next_u64(), pack_albedo(kBroadleaf * tint));
        }
    }
}

}  // namespace

Scene generate_landscape(Detail detail, std::uint64_t seed) {
    const LandscapeParameters& parameters = for_detail(kLandscapeParameters, detail);
    const Terrain terrain(seed);
    ChunkBuilder builder(chunk_triangle_target(detail));

    PolarGrid grid;
    grid.sectors = parameters.terrain_sectors;
    grid.inner_radius = 0.5f;
    grid.outer_radius = kTerrainRadius;
    // The terrain's outer blocks span a quarter circle each: their boxes reach back to the viewer
    // although their pixels are far (papers/003's far-terrain case); force them to C.
    grid.force_mono_from_radius = kForceMonoTerrainRadius;
    const std::uint32_t ground_material = pack_material({0.9f, 0.03f, 1});
    add_polar_grid(
        builder, grid, [&](glm::vec2 p) { return terrain.height(p); },
        [&](glm::vec3 p, glm::vec3 n) {
            return SurfaceLook{pack_albedo(terrain.albedo({p.x, p.z}, p.y, n)), ground_material};
        });
    add_rocks(builder, terrain, parameters, seed);
    add_trees(builder, terrain, parameters, seed);

    Scene scene;
    scene.id = SceneId::Landscape;
    scene.detail = detail;
    scene.seed = seed;
    builder.build_into(scene);
    scene.routing.force_mono_outside_radius = kForceMonoTerrainRadius;
    const auto standing = [&](double x, double z, double eye_height) {
        return glm::dvec3(
            x, terrain.height({static_cast<float>(x), static_cast<float>(z)}) + eye_height, z);
    };
    scene.viewpoints = {
        make_viewpoint("default", standing(0.0, 0.0, 1.7)),
        // Up on a tall step: the valley and the mountains ahead.
        make_viewpoint("bench-forward", standing(0.0, 3.0, 4.0), 0.0, -5.0),
        // Looking down at the ground before one's feet: the terrain's finest cells.
        make_viewpoint("bench-ground", standing(0.0, 0.0, 1.7), 0.0, -30.0),
        make_viewpoint("bench-side", standing(0.0, 0.0, 1.7), 70.0, 2.0),
    };
    // Afternoon sun from behind and to the right: long shadows across the view.
    scene.lighting.sun_direction = glm::normalize(glm::vec3(0.6f, 0.45f, 0.45f));
    scene.lighting.sun_radiance = {3.2f, 2.9f, 2.45f};
    scene.lighting.sky_zenith = {0.15f, 0.32f, 0.70f};
    scene.lighting.sky_horizon = {0.76f, 0.82f, 0.90f};
    scene.lighting.ground_albedo = {0.17f, 0.22f, 0.10f};
    return scene;
}

}  // namespace monoplane::scenes
