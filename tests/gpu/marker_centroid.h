// Where a red marker (testing::marker_scene) appears in a rendered image, to a fraction of a pixel.
#pragma once

#include <algorithm>
#include <cstdint>

#include "renderer/modes/view_setup.h"

namespace monoplane::testing {

struct Centroid {
    double x = 0.0;  // pixels, x right, pixel centres at i + 0.5
    double y = 0.0;  // pixels, y down
    double weight = 0.0;
};

// Centroid of the image's redness (red above the larger of green and blue), weighted: the marker
// is pure red with a smooth profile, the sky and the ground below the horizon are barely reddish
// (redness < 20, cut off below 40), and any symmetric blur keeps the centre.
inline Centroid red_centroid(const modes::RgbaImage& image) {
    Centroid c;
    for (std::uint32_t y = 0; y < image.height; ++y) {
        for (std::uint32_t x = 0; x < image.width; ++x) {
            const std::uint8_t* p = &image.pixels[(std::size_t{y} * image.width + x) * 4];
            const double redness = std::max(0, p[0] - std::max(p[1], p[2]) - 40);
            if (redness <= 0) continue;
            c.x += redness * (x + 0.5);
            c.y += redness * (y + 0.5);
            c.weight += redness;
        }
    }
    if (c.weight > 0) {
        c.x /= c.weight;
        c.y /= c.weight;
    }
    return c;
}

}  // namespace monoplane::testing
