// The mip chain of a base-colour texture (scenes::SceneTexture), for trilinear sampling: without
// it a textured surface seen at a distance aliases, and hybrid's C, whose pixels cover more of
// the scene than an eye's, would shimmer where the eyes do not. CPU only, no Vulkan.
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/scene.h"

namespace monoplane::scenes {

struct MipLevel {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> rgba8_srgb;  // as SceneTexture::rgba8_srgb
};

// Level 0 is the texture itself; each further level is max(1, floor(size / 2)) a side, down to
// 1 x 1 (Vulkan's rule for a full chain). A texel of level k + 1 is the area average, in linear
// light, of the footprint it covers in level k: for even sizes its 2 x 2 texels, for odd sizes a
// footprint of 2 + 1/n texels with fractional weights at its ends, so no texel of the level
// above is dropped. Colour is averaged after sRGB decoding and encoded again (averaging encoded
// values would darken edges between light and dark); alpha is averaged as it is.
// May be called with any texture whose rgba8_srgb holds width * height texels (asserted); a
// 1 x 1 texture gives one level.
std::vector<MipLevel> make_mip_chain(const SceneTexture& texture);

// The number of levels make_mip_chain gives: floor(log2(max(width, height))) + 1.
std::uint32_t mip_level_count(std::uint32_t width, std::uint32_t height);

}  // namespace monoplane::scenes
