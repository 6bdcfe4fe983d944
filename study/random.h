// The study's seeded generator (private to study/). A recorded seed must reproduce the same
// schedule and the same simulated observer on every platform, so nothing here uses
// std::uniform_int_distribution, std::shuffle or std::normal_distribution, whose outputs differ
// between standard libraries: xoshiro256** (Blackman and Vigna) seeded by splitmix64, integers by
// rejection, shuffles by Fisher-Yates. Only Rng::normal() calls libm (log, cos, sqrt), which may
// differ in the last bit between platforms; schedules never use it.
#pragma once

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "common/programming_error.h"

namespace monoplane::study {

// splitmix64's output function: a bijective mix of a 64-bit word.
constexpr std::uint64_t mix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

class Rng {
  public:
    // `stream` separates independent uses of one seed (e.g. block order and labels), so adding
    // draws to one use never changes another.
    explicit Rng(std::uint64_t seed, std::uint64_t stream = 0) {
        std::uint64_t x = seed ^ mix64(stream ^ 0x5EED5EED5EED5EEDull);
        for (std::uint64_t& word : s_) {
            x += 0x9E3779B97F4A7C15ull;
            word = mix64(x - 0x9E3779B97F4A7C15ull);  // splitmix64's sequence
        }
    }

    std::uint64_t next() {
        const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
        const std::uint64_t t = s_[1] << 17;
        s_[2] ^= s_[0];
        s_[3] ^= s_[1];
        s_[1] ^= s_[2];
        s_[0] ^= s_[3];
        s_[2] ^= t;
        s_[3] = rotl(s_[3], 45);
        return result;
    }

    // Uniform in 0..n-1 without modulo bias: rejects the lowest 2^64 mod n raw values.
    std::uint64_t below(std::uint64_t n) {
        MONOPLANE_EXPECTS(n > 0);
        const std::uint64_t threshold = (0 - n) % n;
        for (;;) {
            const std::uint64_t r = next();
            if (r >= threshold) return r % n;
        }
    }
    int below(int n) { return static_cast<int>(below(static_cast<std::uint64_t>(n))); }

    // Uniform in [0, 1) with 53 random bits.
    double uniform01() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
    bool bernoulli(double p) { return uniform01() < p; }

    // Standard normal (Box-Muller, one value per call).
    double normal() {
        const double u1 = 1.0 - uniform01();  // (0, 1]: log stays finite
        const double u2 = uniform01();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
    }

    template <class T>
    void shuffle(std::vector<T>& items) {
        for (std::size_t i = items.size(); i > 1; --i) {
            const std::size_t j = static_cast<std::size_t>(below(static_cast<std::uint64_t>(i)));
            std::swap(items[i - 1], items[j]);
        }
    }

  private:
    static constexpr std::uint64_t rotl(std::uint64_t x, int k) {
        return (x << k) | (x >> (64 - k));
    }
    std::uint64_t s_[4];
};

}  // namespace monoplane::study
