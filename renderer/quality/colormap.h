// Perceptual colour map for the SSIM heat maps: matplotlib's "inferno" (Smith and van der Walt,
// CC0). Its lightness rises monotonically from black to pale yellow, so larger differences read
// as brighter in colour and in greyscale print alike, and zero difference is near black, which
// stands out least on top of a rendering.
#pragma once

#include <array>
#include <cstdint>

namespace monoplane::quality {

using Rgb8 = std::array<std::uint8_t, 3>;

// inferno(t) for t in [0, 1] (clamped; NaN maps to 0): piecewise-linear interpolation through 17
// of matplotlib's 256 entries (every 16th, and the last), rounded to 8 bits. Exact at
// t = k / 16; elsewhere within a few 8-bit levels of matplotlib, invisible in a heat map.
// inferno(0) = (0, 0, 4), inferno(0.5) = (188, 55, 84), inferno(1) = (252, 255, 164).
Rgb8 inferno(float t);

}  // namespace monoplane::quality
