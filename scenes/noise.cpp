#include "scenes/noise.h"

#include <cmath>

#include "scenes/random.h"

namespace monoplane::scenes {
namespace {

constexpr float kDiagonal = 0.70710678f;
constexpr glm::vec2 kGradients2[8] = {{1, 0},
                                      {-1, 0},
                                      {0, 1},
                                      {0, -1},
                                      {kDiagonal, kDiagonal},
                                      {-kDiagonal, kDiagonal},
                                      {kDiagonal, -kDiagonal},
                                      {-kDiagonal, -kDiagonal}};
// The twelve cube-edge directions of Perlin's improved noise, padded to sixteen.
constexpr glm::vec3 kGradients3[16] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {-1, 1, 0}, {0, -1, 1}, {0, -1, -1}};

std::uint64_t lattice_hash(std::int64_t x, std::int64_t y, std::int64_t z, std::uint64_t seed) {
    std::uint64_t h = seed;
    h = mix64(h ^ static_cast<std::uint64_t>(x) * 0x9e3779b97f4a7c15ULL);
    h = mix64(h ^ static_cast<std::uint64_t>(y) * 0xc2b2ae3d27d4eb4fULL);
    h = mix64(h ^ static_cast<std::uint64_t>(z) * 0x165667b19e3779f9ULL);
    return h;
}

// Quintic fade: continuous second derivative, so normals from the height field are smooth.
float fade(float t) {
    return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f);
}

float lerp(float a, float b, float t) {
    return a + (b - a) * t;
}

float corner2(std::int64_t x, std::int64_t y, glm::vec2 offset, std::uint64_t seed) {
    const glm::vec2 g = kGradients2[lattice_hash(x, y, 0, seed) >> 61];
    return g.x * offset.x + g.y * offset.y;
}

float corner3(std::int64_t x, std::int64_t y, std::int64_t z, glm::vec3 offset,
              std::uint64_t seed) {
    const glm::vec3 g = kGradients3[lattice_hash(x, y, z, seed) >> 60];
    return g.x * offset.x + g.y * offset.y + g.z * offset.z;
}

}  // namespace

float gradient_noise(glm::vec2 p, std::uint64_t seed) {
    const float fx = std::floor(p.x);
    const float fy = std::floor(p.y);
    const auto x = static_cast<std::int64_t>(fx);
    const auto y = static_cast<std::int64_t>(fy);
    const glm::vec2 f{p.x - fx, p.y - fy};
    const float n00 = corner2(x, y, f, seed);
    const float n10 = corner2(x + 1, y, f - glm::vec2(1, 0), seed);
    const float n01 = corner2(x, y + 1, f - glm::vec2(0, 1), seed);
    const float n11 = corner2(x + 1, y + 1, f - glm::vec2(1, 1), seed);
    const float u = fade(f.x);
    const float v = fade(f.y);
    // The largest magnitude of 2D gradient noise is about 0.7; scale towards [-1, 1].
    return 1.4f * lerp(lerp(n00, n10, u), lerp(n01, n11, u), v);
}

float gradient_noise(glm::vec3 p, std::uint64_t seed) {
    const glm::vec3 floor{std::floor(p.x), std::floor(p.y), std::floor(p.z)};
    const auto x = static_cast<std::int64_t>(floor.x);
    const auto y = static_cast<std::int64_t>(floor.y);
    const auto z = static_cast<std::int64_t>(floor.z);
    const glm::vec3 f = p - floor;
    const float n000 = corner3(x, y, z, f, seed);
    const float n100 = corner3(x + 1, y, z, f - glm::vec3(1, 0, 0), seed);
    const float n010 = corner3(x, y + 1, z, f - glm::vec3(0, 1, 0), seed);
    const float n110 = corner3(x + 1, y + 1, z, f - glm::vec3(1, 1, 0), seed);
    const float n001 = corner3(x, y, z + 1, f - glm::vec3(0, 0, 1), seed);
    const float n101 = corner3(x + 1, y, z + 1, f - glm::vec3(1, 0, 1), seed);
    const float n011 = corner3(x, y + 1, z + 1, f - glm::vec3(0, 1, 1), seed);
    const float n111 = corner3(x + 1, y + 1, z + 1, f - glm::vec3(1, 1, 1), seed);
    const float u = fade(f.x);
    const float v = fade(f.y);
    const float w = fade(f.z);
    const float near = lerp(lerp(n000, n100, u), lerp(n010, n110, u), v);
    const float far = lerp(lerp(n001, n101, u), lerp(n011, n111, u), v);
    return lerp(near, far, w);
}

namespace {
// Octaves of gradient noise, each `lacunarity` times finer and `gain` times weaker, normalised.
template <class Point>
float fractal_sum(Point p, std::uint64_t seed, const Fractal& fractal) {
    float sum = 0.0f;
    float amplitude = 1.0f;
    float total = 0.0f;
    for (int octave = 0; octave < fractal.octaves; ++octave) {
        sum += amplitude * gradient_noise(p, seed + static_cast<std::uint64_t>(octave));
        total += amplitude;
        amplitude *= fractal.gain;
        p *= fractal.lacunarity;
    }
    return sum / total;
}
}  // namespace

float fractal_noise(glm::vec2 p, std::uint64_t seed, const Fractal& fractal) {
    return fractal_sum(p, seed, fractal);
}

float fractal_noise(glm::vec3 p, std::uint64_t seed, const Fractal& fractal) {
    return fractal_sum(p, seed, fractal);
}

float ridged_noise(glm::vec2 p, std::uint64_t seed, const Fractal& fractal) {
    float sum = 0.0f;
    float amplitude = 1.0f;
    float total = 0.0f;
    float weight = 1.0f;  // the previous octave's ridge: detail grows on the crests
    for (int octave = 0; octave < fractal.octaves; ++octave) {
        float ridge =
            1.0f - std::fabs(gradient_noise(p, seed + static_cast<std::uint64_t>(octave)));
        ridge *= ridge;
        sum += amplitude * ridge * weight;
        total += amplitude;
        weight = ridge;
        amplitude *= fractal.gain;
        p *= fractal.lacunarity;
    }
    return sum / total;
}

}  // namespace monoplane::scenes
