// Seeded gradient noise (Perlin-style, lattice hashed with the seed, no permutation table) and its
// fractal sums. Values are roughly in [-1, 1]; everything is deterministic for a given seed.
#pragma once

#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace monoplane::scenes {

float gradient_noise(glm::vec2 p, std::uint64_t seed);
float gradient_noise(glm::vec3 p, std::uint64_t seed);

struct Fractal {
    int octaves = 5;
    float lacunarity = 2.0f;  // frequency factor per octave
    float gain = 0.5f;        // amplitude factor per octave
};

// Sum of octaves normalised by the total amplitude: roughly in [-1, 1].
float fractal_noise(glm::vec2 p, std::uint64_t seed, const Fractal& fractal = {});
float fractal_noise(glm::vec3 p, std::uint64_t seed, const Fractal& fractal = {});

// Ridged multifractal for mountain crests: in [0, 1], sharp ridges where the noise crosses zero,
// rougher detail on the ridges than in the valleys.
float ridged_noise(glm::vec2 p, std::uint64_t seed, const Fractal& fractal = {});

}  // namespace monoplane::scenes
