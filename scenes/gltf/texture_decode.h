// Base-colour images, decoded from PNG or JPEG (the formats core glTF allows) into RGBA8 with
// size limits: a small compressed image can claim gigapixels.
#pragma once

#include <cstdint>
#include <filesystem>

#include "common/result.h"
#include "scenes/gltf/gltf_document.h"
#include "scenes/scene.h"

namespace monoplane::scenes::gltf {

// glTF texture `texture` (its image and sampler) as a SceneTexture. Refuses images of more than
// max_texels texels; the error names the texture and image, e.g. "texture 0 (image 0
// 'CesiumLogoFlat.png'): file not found in models/box".
Result<SceneTexture> decode_texture(const GltfDocument& document, int texture,
                                    std::uint64_t max_texels);

}  // namespace monoplane::scenes::gltf
