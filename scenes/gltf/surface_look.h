// What a glTF material (pbrMetallicRoughness) becomes in the renderer's simpler model: one
// linear albedo per vertex, roughness and a scalar specular reflectance (scenes::Material).
#pragma once

#include <cstdint>

#include <glm/vec4.hpp>

#include "common/result.h"
#include "scenes/gltf/tiny_gltf_config.h"

namespace monoplane::scenes::gltf {

struct SurfaceLook {
    glm::vec4 base_color{1.0f};         // linear RGBA, baseColorFactor clamped to [0, 1]
    std::uint32_t material_packed = 0;  // pack_material()
    int texture = -1;                   // glTF texture of the base colour, or -1
    int texcoord_set = 0;               // its TEXCOORD_n
};

// The look of material `material`, or glTF's default material for -1 (white, metallic 1,
// roughness 1). Metals are approximated: the base colour stays the diffuse albedo (the renderer
// has no metallic term) and the specular reflectance rises from 0.04 (dielectrics) towards 0.5.
Result<SurfaceLook> surface_look(const tinygltf::Model& model, int material);

}  // namespace monoplane::scenes::gltf
