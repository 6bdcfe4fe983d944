// The per-vertex stand-in for texturing while the renderer samples no textures: each vertex
// takes the texture's colour around its texture coordinate, so imported textured scenes look
// roughly right (the colour varies only across vertices, not within a triangle).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "scenes/scene.h"

namespace monoplane::scenes::gltf {

// sRGB-encoded 8-bit value to linear light.
float srgb_to_linear(std::uint8_t encoded);

class TextureBake {
  public:
    // A copy of the texture box-filtered in linear light to at most kSide texels a side: a vertex
    // samples a local average rather than whatever single texel its coordinate hits, which is
    // what a vertex colour can represent at typical vertex spacing.
    static constexpr std::uint32_t kSide = 64;
    explicit TextureBake(const SceneTexture& texture);

    // Linear RGBA at texture coordinate uv (bilinear, wrapped as the texture's sampler says).
    glm::vec4 sample(glm::vec2 uv) const;

  private:
    std::uint32_t width_ = 1;
    std::uint32_t height_ = 1;
    TextureWrap wrap_u_ = TextureWrap::Repeat;
    TextureWrap wrap_v_ = TextureWrap::Repeat;
    std::vector<glm::vec4> texels_;  // linear RGBA, row 0 at v = 0
};

}  // namespace monoplane::scenes::gltf
