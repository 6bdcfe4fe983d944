// Resampling of base-colour textures in linear light, for the renderer's texture arrays (square,
// power-of-two layers, scenes/texture_arrays.h) and their mip chains (scenes/texture_mips.h).
// CPU only, no Vulkan.
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/scene.h"

namespace monoplane::scenes {

// An image in linear light: four floats a texel (RGB linear, alpha as stored), row 0 at v = 0.
struct LinearImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<float> rgba;
};

// The texture's texels decoded from sRGB (alpha unchanged, / 255). Any time.
LinearImage decode_srgb(const SceneTexture& texture);
// The image as RGBA8 bytes, colour sRGB-encoded and rounded to nearest, alpha linear; values
// outside [0, 1] are clamped. Any time.
std::vector<std::uint8_t> encode_srgb(const LinearImage& image);

// The image at width x height (both > 0), each axis resampled on its own: shrinking averages the
// footprint each new texel covers (a box filter with fractional end weights, so no source texel
// is dropped and the mean is kept), growing interpolates linearly between texel centres, with
// the neighbours beyond an edge found by the axis's wrap mode (a repeating texture continues
// from its other side). The same size returns a copy. Any time; the image must hold
// width * height texels (asserted).
LinearImage resample(const LinearImage& image, std::uint32_t width, std::uint32_t height,
                     TextureWrap wrap_u, TextureWrap wrap_v);

}  // namespace monoplane::scenes
