#include "scenes/spheres.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include <glm/geometric.hpp>

#include "scenes/chunk_builder.h"
#include "scenes/color.h"
#include "scenes/detail.h"
#include "scenes/polar_grid.h"
#include "scenes/random.h"
#include "scenes/sphere_mesh.h"

namespace monoplane::scenes {
namespace {

struct SpheresParameters {
    int spheres;
    SphereTessellation tessellation;
    int ground_sectors;
};

const PerDetail<SpheresParameters> kSpheresParameters = {{
    {200, {12, 7}, 48},
    {520, {20, 10}, 96},
    {840, {28, 14}, 192},
    {1560, {40, 20}, 256},
    {3000, {56, 28}, 384},
}};

const glm::dvec3 kEye{0.0, 1.7, 0.0};
// Half the field of view, as tangents: about 110 degrees across, a little less vertically.
constexpr float kTanHorizontal = 1.43f;
constexpr float kTanUp = 0.8f;
constexpr float kTanDown = 1.0f;

enum SpheresStream : std::uint64_t { kPlacement = 1, kAppearance };

// Sphere i's depth, uniform in depth as papers/000 Sect. 6 has it ("geometry which is uniformly
// distributed across space"): stratified, sphere i in the i-th of count equal depth strata from
// kSpheresNearest to kSpheresFarthest, jittered within it, so every seed and detail level keeps the
// spread. Uniform in metres leaves few spheres in front of the nearest mono planes at low sphere
// counts (about 0.7 % of them nearer than 1.6 m, one or two at detail test): that is the paper's
// design, and docs/scenes.md gives the resulting fractions per mono plane.
float depth_of(int i, int count, Random& random) {
    const float u =
        (static_cast<float>(i) + random.uniform(0.05f, 0.95f)) / static_cast<float>(count);
    return kSpheresNearest + (kSpheresFarthest - kSpheresNearest) * u;
}

// Radius growing with depth, so spheres subtend a similar angle near and far.
float radius_at(float depth, Random& random) {
    return (0.045f + 0.03f * depth) * random.uniform(0.6f, 1.4f);
}

std::vector<PlacedSphere> place_balls(int count, std::uint64_t seed) {
    Random random(seed, kPlacement);
    std::vector<PlacedSphere> balls;
    balls.reserve(static_cast<std::size_t>(count));
    for (int i = 0; i < count; ++i) {
        const float depth = depth_of(i, count, random);
        for (int attempt = 0; attempt < 30; ++attempt) {
            float radius = radius_at(depth, random);
            float across = random.uniform(-kTanHorizontal, kTanHorizontal);
            const float vertical = random.uniform(-kTanDown, kTanUp);
            // Keep arm's-length spheres out of the line of sight: comfortable to look past.
            if (depth < 2.5f && std::fabs(across) < 0.3f && std::fabs(vertical) < 0.3f) {
                across = std::copysign(0.3f + std::fabs(across), across);
            }
            glm::vec3 centre{depth * across, static_cast<float>(kEye.y) + depth * vertical, -depth};
            // Below the ground line: rest on the ground instead; some rest there anyway.
            if (centre.y < radius || random.chance(0.2)) centre.y = radius;
            const glm::vec3 eye{kEye};
            if (glm::length(centre - eye) < radius + 0.35f) continue;
            const bool free = std::none_of(balls.begin(), balls.end(), [&](const PlacedSphere& b) {
                return glm::length(b.centre - centre) < b.radius + radius + 0.02f;
            });
            if (free) {
                balls.push_back({centre, radius});
                break;
            }
        }
    }
    return balls;
}

}  // namespace

std::vector<PlacedSphere> spheres_layout(Detail detail, std::uint64_t seed) {
    return place_balls(for_detail(kSpheresParameters, detail).spheres, seed);
}

Scene generate_spheres(Detail detail, std::uint64_t seed) {
    const SpheresParameters& parameters = for_detail(kSpheresParameters, detail);
    ChunkBuilder builder(chunk_triangle_target(detail));

    PolarGrid ground;
    ground.sectors = parameters.ground_sectors;
    ground.outer_radius = 700.0f;
    SurfaceLook lawn;
    lawn.albedo_rgba8 = pack_albedo(from_srgb(0x7d8a6a));
    lawn.material_packed = pack_material({0.9f, 0.03f, 1});
    add_polar_grid(
        builder, ground, [](glm::vec2) { return 0.0f; },
        [&](glm::vec3, glm::vec3) { return lawn; });

    Random appearance(seed, kAppearance);
    for (const PlacedSphere& ball : place_balls(parameters.spheres, seed)) {
        const float hue = appearance.uniform(0.0f, 1.0f);
        const float saturation = appearance.uniform(0.35f, 0.85f);
        const float value = appearance.uniform(0.55f, 0.95f);
        const glm::vec3 albedo = srgb_to_linear(hsv_to_srgb(hue, saturation, value));
        // A third are glossy: low roughness and a strong specular, so they mirror the sky.
        const bool glossy = appearance.chance(0.33);
        const Material material = glossy ? Material{appearance.uniform(0.05f, 0.2f), 0.5f, 0}
                                         : Material{appearance.uniform(0.45f, 0.8f), 0.04f, 0};
        add_sphere(builder, ball.centre, ball.radius, parameters.tessellation, pack_albedo(albedo),
                   pack_material(material));
    }

    Scene scene;
    scene.id = SceneId::Spheres;
    scene.detail = detail;
    scene.seed = seed;
    builder.build_into(scene);
    scene.viewpoints = {
        make_viewpoint("default", kEye),
        make_viewpoint("bench-forward", {0.0, 2.5, 2.0}, 0.0, -3.0),
        make_viewpoint("bench-ground", {0.0, 1.0, 0.0}, 0.0, -20.0),
        make_viewpoint("bench-side", kEye, -40.0, 5.0),
    };
    scene.lighting.sun_direction = glm::normalize(glm::vec3(0.35f, 0.85f, 0.3f));
    scene.lighting.sun_radiance = {3.0f, 2.9f, 2.7f};
    scene.lighting.sky_zenith = {0.16f, 0.34f, 0.76f};
    scene.lighting.sky_horizon = {0.70f, 0.79f, 0.92f};
    scene.lighting.ground_albedo = {0.22f, 0.25f, 0.18f};
    return scene;
}

}  // namespace monoplane::scenes
