#include "scenes/random.h"

#include <cmath>
#include <numbers>

#include "common/programming_error.h"

namespace monoplane::scenes {
namespace {

std::uint64_t rotate_left(std::uint64_t x, int k) {
    return (x << k) | (x >> (64 - k));
}

std::uint64_t splitmix64_next(std::uint64_t& state) {
    state += 0x9e3779b97f4a7c15ULL;
    return mix64(state);
}

}  // namespace

std::uint64_t mix64(std::uint64_t value) {
    value = (value ^ (value >> 30)) * 0xbf58476d1ce4e5b9ULL;
    value = (value ^ (value >> 27)) * 0x94d049bb133111ebULL;
    return value ^ (value >> 31);
}

Random::Random(std::uint64_t seed, std::uint64_t stream) {
    std::uint64_t state = seed ^ mix64(stream + 0x632be59bd9b4e019ULL);
    for (std::uint64_t& word : state_) word = splitmix64_next(state);
}

std::uint64_t Random::next_u64() {
    const std::uint64_t result = rotate_left(state_[1] * 5, 7) * 9;
    const std::uint64_t t = state_[1] << 17;
    state_[2] ^= state_[0];
    state_[3] ^= state_[1];
    state_[1] ^= state_[2];
    state_[0] ^= state_[3];
    state_[2] ^= t;
    state_[3] = rotate_left(state_[3], 45);
    return result;
}

double Random::uniform() {
    return static_cast<double>(next_u64() >> 11) * 0x1.0p-53;
}

float Random::uniform(float low, float high) {
    return low + static_cast<float>(uniform()) * (high - low);
}

int Random::uniform_int(int low, int high) {
    MONOPLANE_EXPECTS(low <= high);
    const std::uint64_t range = static_cast<std::uint64_t>(high - low) + 1;
    // Rejection from the largest multiple of range keeps every value equally likely.
    const std::uint64_t limit = UINT64_MAX - UINT64_MAX % range;
    std::uint64_t draw = next_u64();
    while (draw >= limit) draw = next_u64();
    return low + static_cast<int>(draw % range);
}

float Random::normal(float mean, float standard_deviation) {
    const double u1 = 1.0 - uniform();  // in (0, 1]: log stays finite
    const double u2 = uniform();
    const double radius = std::sqrt(-2.0 * std::log(u1));
    return mean +
           standard_deviation * static_cast<float>(radius * std::cos(2.0 * std::numbers::pi * u2));
}

}  // namespace monoplane::scenes
