// The cutting line of Sect. 4.3 counted on rendered depth: used by the hybrid accuracy tests.
#pragma once

#include <cmath>
#include <cstddef>
#include <vector>

namespace monoplane::testing {

inline constexpr float kSky = 1.0e29f;  // linear depth at or beyond this: background (the sky)

// Pixels inside a surface that crosses the mono plane in stereo (within 5 % of m, away from
// silhouettes, where sub-pixel drift may legitimately move an edge) but that show background in
// hybrid: the cutting line of Sect. 4.3.
inline int cut_pixels(const std::vector<float>& stereo, const std::vector<float>& hybrid, int width,
                      int height, double m) {
    int count = 0;
    for (int y = 1; y + 1 < height; ++y) {
        for (int x = 1; x + 1 < width; ++x) {
            const std::size_t i = static_cast<std::size_t>(y) * width + x;
            if (std::abs(stereo[i] - m) > 0.05 * m || hybrid[i] < kSky) continue;
            bool interior = true;
            for (int dy = -1; dy <= 1; ++dy) {
                for (int dx = -1; dx <= 1; ++dx) {
                    interior = interior && stereo[i + dy * width + dx] < kSky;
                }
            }
            if (interior) ++count;
        }
    }
    return count;
}

}  // namespace monoplane::testing
