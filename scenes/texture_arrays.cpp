#include "scenes/texture_arrays.h"

#include <algorithm>

#include "scenes/texture_resample.h"

namespace monoplane::scenes {

std::uint32_t texture_array_for(std::uint32_t width, std::uint32_t height) {
    const std::uint32_t larger = std::max(width, height);
    for (std::uint32_t array = 0; array < kTextureArrayCount; ++array) {
        if (larger <= TextureArrayLayout::side(array)) return array;
    }
    return kTextureArrayCount - 1;
}

TextureArrayLayout layout_texture_arrays(std::span<const SceneTexture> textures) {
    TextureArrayLayout layout;
    layout.slots.reserve(textures.size());
    for (const SceneTexture& texture : textures) {
        const std::uint32_t array = texture_array_for(texture.width, texture.height);
        layout.slots.push_back({array, layout.layers[array]++});
    }
    return layout;
}

SceneTexture texture_as_layer(const SceneTexture& texture, std::uint32_t side) {
    SceneTexture layer = texture;
    if (texture.width == side && texture.height == side) return layer;
    const LinearImage scaled =
        resample(decode_srgb(texture), side, side, texture.wrap_u, texture.wrap_v);
    layer.width = side;
    layer.height = side;
    layer.rgba8_srgb = encode_srgb(scaled);
    return layer;
}

}  // namespace monoplane::scenes
