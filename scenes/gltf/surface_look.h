// What a glTF material (pbrMetallicRoughness) becomes in the renderer's simpler model: one
// linear albedo per vertex, roughness and a scalar specular reflectance (scenes::Material), and
// how the surface covers what lies behind it (alphaMode, alphaCutoff: scenes::AlphaMode).
#pragma once

#include <cstdint>

#include <glm/vec4.hpp>

#include "common/result.h"
#include "scenes/gltf/tiny_gltf_config.h"
#include "scenes/scene.h"

namespace monoplane::scenes::gltf {

struct SurfaceLook {
    glm::vec4 base_color{1.0f};         // linear RGBA, baseColorFactor clamped to [0, 1]
    std::uint32_t material_packed = 0;  // pack_material()
    int texture = -1;                   // glTF texture of the base colour, or -1
    int texcoord_set = 0;               // its TEXCOORD_n
    // glTF's doubleSided: back faces are drawn too (the importer adds them as triangles of their
    // own, since the renderer culls back faces of every chunk alike).
    bool double_sided = false;
    // glTF's alphaMode ("OPAQUE", the default, "MASK" or "BLEND") and, for MASK only,
    // alphaCutoff (default 0.5; the specification has other modes ignore it, so they keep 0.5).
    AlphaMode alpha_mode = AlphaMode::kOpaque;
    float alpha_cutoff = 0.5f;
};

// Whether material `material` is double-sided; false for -1 (glTF's default material) and for an
// index that names no material (surface_look() reports that). Any time.
bool is_double_sided(const tinygltf::Model& model, int material);

// The look of material `material`, or glTF's default material for -1 (white, metallic 1,
// roughness 1, opaque). Metals are approximated: the base colour stays the diffuse albedo (the
// renderer has no metallic term) and the specular reflectance rises from 0.04 (dielectrics)
// towards 0.5. An alphaMode other than the three, or a negative alphaCutoff, is an error naming
// the material.
Result<SurfaceLook> surface_look(const tinygltf::Model& model, int material);

}  // namespace monoplane::scenes::gltf
