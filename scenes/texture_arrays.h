// How an imported scene's base-colour textures are laid out for the renderer: as layers of a few
// square, power-of-two texture arrays, one array per side length. The forward pass then samples
// any chunk's texture from one draw of many chunks without descriptor indexing, which Mesa's
// lavapipe (the CPU Vulkan driver the tests run on) does not offer: the array is chosen with a
// constant index in a switch, the layer is a coordinate. Textures are scaled up to their
// array's side (never down, below kMaxTextureArraySide), so no texel is lost. CPU only.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "scenes/scene.h"

namespace monoplane::scenes {

// Array a holds layers of side kTextureArraySmallestSide << a.
inline constexpr std::uint32_t kTextureArrayCount = 7;
inline constexpr std::uint32_t kTextureArraySmallestSide = 128;
inline constexpr std::uint32_t kMaxTextureArraySide = kTextureArraySmallestSide
                                                      << (kTextureArrayCount - 1);  // 8192

struct TextureSlot {
    std::uint32_t array = 0;  // < kTextureArrayCount
    std::uint32_t layer = 0;
};

struct TextureArrayLayout {
    std::vector<TextureSlot> slots;                          // per Scene::textures entry
    std::array<std::uint32_t, kTextureArrayCount> layers{};  // layers per array (0: unused)

    static constexpr std::uint32_t side(std::uint32_t array) {
        return kTextureArraySmallestSide << array;
    }
};

// The array for a texture of width x height: the smallest whose side is at least the larger of
// the two, the largest array for anything bigger (which is then scaled down). Any time.
std::uint32_t texture_array_for(std::uint32_t width, std::uint32_t height);

// Each texture's array and layer, layers numbered in texture order within each array. Any time.
TextureArrayLayout layout_texture_arrays(std::span<const SceneTexture> textures);

// The texture as a layer of `side` x `side` texels, resampled in linear light with its wrap
// modes (scenes/texture_resample.h); its mip chain is made from this. Any time.
SceneTexture texture_as_layer(const SceneTexture& texture, std::uint32_t side);

}  // namespace monoplane::scenes
