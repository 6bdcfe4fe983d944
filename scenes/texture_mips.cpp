#include "scenes/texture_mips.h"

#include <algorithm>

#include "common/programming_error.h"
#include "scenes/texture_resample.h"

namespace monoplane::scenes {

std::uint32_t mip_level_count(std::uint32_t width, std::uint32_t height) {
    std::uint32_t levels = 1;
    for (std::uint32_t side = std::max(width, height); side > 1; side /= 2) ++levels;
    return levels;
}

std::vector<MipLevel> make_mip_chain(const SceneTexture& texture) {
    MONOPLANE_EXPECTS(texture.rgba8_srgb.size() == std::size_t{texture.width} * texture.height * 4);
    std::vector<MipLevel> chain;
    chain.reserve(mip_level_count(texture.width, texture.height));
    chain.push_back({texture.width, texture.height, texture.rgba8_srgb});
    // Each level from the one above in float, so rounding does not accumulate down the chain.
    LinearImage linear = decode_srgb(texture);
    while (linear.width > 1 || linear.height > 1) {
        linear = resample(linear, std::max(1u, linear.width / 2), std::max(1u, linear.height / 2),
                          texture.wrap_u, texture.wrap_v);
        chain.push_back({linear.width, linear.height, encode_srgb(linear)});
    }
    return chain;
}

}  // namespace monoplane::scenes
