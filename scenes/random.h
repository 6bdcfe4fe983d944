// A small seeded random generator with its own distributions. The standard library's
// distributions are implementation-defined, so the same seed would give different scenes with
// libstdc++ and libc++; this one gives the same numbers everywhere.
#pragma once

#include <cstdint>

namespace monoplane::scenes {

// The SplitMix64 finaliser: a bijective 64-bit mix, also used to hash lattice points and bytes.
std::uint64_t mix64(std::uint64_t value);

// xoshiro256** seeded through SplitMix64. A stream tag derives independent sequences from one
// scene seed, so adding objects of one kind does not reshuffle the others.
class Random {
  public:
    explicit Random(std::uint64_t seed, std::uint64_t stream = 0);

    std::uint64_t next_u64();
    // Uniform in [0, 1) with 53 random bits.
    double uniform();
    // Uniform in [low, high).
    float uniform(float low, float high);
    // Uniform integer in [low, high], without modulo bias.
    int uniform_int(int low, int high);
    // Normal deviate (Box-Muller, one of the pair; simple and deterministic).
    float normal(float mean = 0.0f, float standard_deviation = 1.0f);
    bool chance(double probability) { return uniform() < probability; }

  private:
    std::uint64_t state_[4];
};

}  // namespace monoplane::scenes
