#include "scenes/terrain.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "scenes/color.h"
#include "scenes/noise.h"
#include "scenes/random.h"

namespace monoplane::scenes {
namespace {

float smoothstep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

// Noise seeds per feature, derived from the scene seed.
enum Feature : std::uint64_t { kBumps = 1, kRolling, kHills, kMountains, kColour };

}  // namespace

Terrain::Terrain(std::uint64_t seed) : seed_(seed) {}

float Terrain::height(glm::vec2 p) const {
    const float r = glm::length(p);
    const float ahead = std::clamp(-p.y / std::max(r, 1.0f), -1.0f, 1.0f);  // 1 straight ahead
    const auto seed = [&](Feature f) { return mix64(seed_ * 16 + f); };

    // Small bumps and gentle rolling ground, faded in around the standing spot.
    const float bumps =
        0.12f * smoothstep(1.0f, 6.0f, r) * fractal_noise(p / 5.0f, seed(kBumps), {3, 2.0f, 0.5f});
    const float rolling = 1.6f * smoothstep(3.0f, 40.0f, r) *
                          fractal_noise(p / 45.0f, seed(kRolling), {4, 2.0f, 0.5f});
    // Hills that only rise: the ground climbs with distance.
    const float hills = 16.0f * smoothstep(25.0f, 220.0f, r) *
                        (0.6f + 0.4f * fractal_noise(p / 130.0f, seed(kHills), {5, 2.0f, 0.5f}));
    // Mountains ringing the valley, tallest straight ahead.
    const float mountains = (110.0f + 50.0f * ahead) * smoothstep(140.0f, 480.0f, r) *
                            ridged_noise(p / 320.0f, seed(kMountains), {6, 2.0f, 0.5f});
    // A shallow bowl, so the far rim stands higher still.
    const float bowl = 0.025f * std::max(r - 30.0f, 0.0f);
    return bumps + rolling + hills + mountains + bowl;
}

glm::vec3 Terrain::normal(glm::vec2 p, float cell_size) const {
    const float e = std::max(0.05f, 0.5f * cell_size);
    const float dx = height(p + glm::vec2(e, 0.0f)) - height(p - glm::vec2(e, 0.0f));
    const float dz = height(p + glm::vec2(0.0f, e)) - height(p - glm::vec2(0.0f, e));
    return glm::normalize(glm::vec3(-dx, 2.0f * e, -dz));
}

glm::vec3 Terrain::albedo(glm::vec2 p, float h, glm::vec3 n) const {
    static const glm::vec3 kGrass = from_srgb(0x5d7a34);
    static const glm::vec3 kDryGrass = from_srgb(0x8f8a4e);
    static const glm::vec3 kRock = from_srgb(0x7a726a);
    static const glm::vec3 kSnow = from_srgb(0xeef0f4);
    const float variation = fractal_noise(p / 30.0f, mix64(seed_ * 16 + kColour), {3, 2.0f, 0.5f});
    const float steepness = 1.0f - n.y;  // 0 flat, about 0.3 at 45 degrees

    glm::vec3 colour =
        glm::mix(kGrass, kDryGrass, std::clamp(0.5f + 0.8f * variation + h / 120.0f, 0.0f, 1.0f));
    colour = glm::mix(colour, kRock, smoothstep(0.12f, 0.3f, steepness + 0.05f * variation));
    colour = glm::mix(colour, kRock, smoothstep(Terrain::kTreeLine, Terrain::kTreeLine + 35.0f, h));
    const float snow = smoothstep(kSnowLine - 10.0f, kSnowLine + 10.0f, h + 15.0f * variation) *
                       (1.0f - smoothstep(0.35f, 0.55f, steepness));
    return glm::mix(colour, kSnow, snow);
}

}  // namespace monoplane::scenes
