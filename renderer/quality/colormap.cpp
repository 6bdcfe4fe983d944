#include "renderer/quality/colormap.h"

#include <cmath>
#include <cstddef>

namespace monoplane::quality {
namespace {

// matplotlib _cm_listed._inferno_data entries 0, 16, 32, ..., 240 and 255.
constexpr std::size_t kSamples = 17;
constexpr float kInferno[kSamples][3] = {
    {0.001462f, 0.000466f, 0.013866f}, {0.042253f, 0.028139f, 0.141141f},
    {0.129285f, 0.047293f, 0.290788f}, {0.238273f, 0.036621f, 0.396353f},
    {0.341500f, 0.062325f, 0.429425f}, {0.441207f, 0.099338f, 0.431594f},
    {0.540920f, 0.134729f, 0.415123f}, {0.640135f, 0.171438f, 0.381065f},
    {0.735683f, 0.215906f, 0.330245f}, {0.822386f, 0.275197f, 0.266085f},
    {0.894305f, 0.353399f, 0.193584f}, {0.946965f, 0.449191f, 0.115272f},
    {0.978422f, 0.557937f, 0.034931f}, {0.987874f, 0.675267f, 0.065257f},
    {0.974638f, 0.797692f, 0.206332f}, {0.947594f, 0.917399f, 0.410665f},
    {0.988362f, 0.998364f, 0.644924f},
};

std::uint8_t to_byte(float unit) {
    return static_cast<std::uint8_t>(std::lround(unit * 255.0f));
}

}  // namespace

Rgb8 inferno(float t) {
    if (!(t > 0.0f)) t = 0.0f;  // also catches NaN
    if (t > 1.0f) t = 1.0f;
    const float position = t * static_cast<float>(kSamples - 1);
    const auto lower = static_cast<std::size_t>(position);
    if (lower >= kSamples - 1) {
        return {to_byte(kInferno[kSamples - 1][0]), to_byte(kInferno[kSamples - 1][1]),
                to_byte(kInferno[kSamples - 1][2])};
    }
    const float f = position - static_cast<float>(lower);
    Rgb8 colour{};
    for (std::size_t c = 0; c < 3; ++c) {
        const float value = kInferno[lower][c] + f * (kInferno[lower + 1][c] - kInferno[lower][c]);
        colour[c] = to_byte(value);
    }
    return colour;
}

}  // namespace monoplane::quality
