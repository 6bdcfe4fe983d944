#include "renderer/quality/heat_map.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "renderer/quality/colormap.h"

namespace monoplane::quality {

std::vector<std::uint8_t> ssim_heat_map_rgba(const SsimResult& result, float scale) {
    // A wrong scale is a programming error; checked in release builds too, so it cannot turn a
    // researcher's figure silently black.
    if (!(std::isfinite(scale) && scale > 0.0f)) {
        std::fprintf(stderr, "ssim_heat_map_rgba: scale must be positive and finite, got %g\n",
                     static_cast<double>(scale));
        std::abort();
    }
    std::vector<std::uint8_t> rgba(result.map.size() * 4, 0);
    for (std::size_t i = 0; i < result.map.size(); ++i) {
        const float value = result.map[i];
        if (std::isnan(value)) continue;  // no SSIM here: stays transparent
        const Rgb8 colour = inferno((1.0f - value) * scale);
        rgba[4 * i + 0] = colour[0];
        rgba[4 * i + 1] = colour[1];
        rgba[4 * i + 2] = colour[2];
        rgba[4 * i + 3] = 255;
    }
    return rgba;
}

Result<std::vector<std::uint8_t>> blend_heat_map(const ImageView& base,
                                                 std::span<const std::uint8_t> heat_rgba,
                                                 float alpha) {
    if (!is_well_formed(base)) {
        return Error{
            "heat-map overlay needs a non-empty base image with 1, 3 or 4 channels and "
            "width * height * channels bytes"};
    }
    const std::size_t pixels = std::size_t{base.width} * base.height;
    if (heat_rgba.size() != pixels * 4) {
        return Error{"heat map has " + std::to_string(heat_rgba.size()) + " bytes; the " +
                     std::to_string(base.width) + "x" + std::to_string(base.height) +
                     " base image needs " + std::to_string(pixels * 4) +
                     " (compute the SSIM on this image)"};
    }
    if (!(alpha >= 0.0f && alpha <= 1.0f)) {
        return Error{"heat-map opacity must be in [0, 1], got " + std::to_string(alpha)};
    }
    std::vector<std::uint8_t> out(pixels * 4);
    for (std::size_t i = 0; i < pixels; ++i) {
        const std::uint8_t* b = base.pixels.data() + i * base.channels;
        const std::uint8_t* h = heat_rgba.data() + i * 4;
        const float a = alpha * (static_cast<float>(h[3]) / 255.0f);
        for (std::size_t c = 0; c < 3; ++c) {
            const float under = b[base.channels == 1 ? 0 : c];
            const float over = h[c];
            out[4 * i + c] = static_cast<std::uint8_t>(std::lround(under + a * (over - under)));
        }
        out[4 * i + 3] = 255;
    }
    return out;
}

}  // namespace monoplane::quality
