#include "scenes/gltf/surface_look.h"

#include <algorithm>
#include <string>

#include "scenes/scene.h"

namespace monoplane::scenes::gltf {
namespace {

constexpr float kDielectricSpecular = 0.04f;
constexpr float kMetalSpecular = 0.5f;

float unit(double value) {
    return static_cast<float>(std::clamp(value, 0.0, 1.0));
}

}  // namespace

Result<SurfaceLook> surface_look(const tinygltf::Model& model, int material_index) {
    SurfaceLook look;
    Material material;
    material.roughness = 1.0f;
    material.specular = kMetalSpecular;
    if (material_index >= 0) {
        if (static_cast<std::size_t>(material_index) >= model.materials.size()) {
            return Error{"material " + std::to_string(material_index) + " does not exist"};
        }
        const tinygltf::PbrMetallicRoughness& pbr =
            model.materials[static_cast<std::size_t>(material_index)].pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() != 4) {
            return Error{"material " + std::to_string(material_index) +
                         ": baseColorFactor must have 4 elements"};
        }
        // glTF's factor is linear already, like Vertex::albedo_rgba8.
        look.base_color = {unit(pbr.baseColorFactor[0]), unit(pbr.baseColorFactor[1]),
                           unit(pbr.baseColorFactor[2]), unit(pbr.baseColorFactor[3])};
        material.roughness = unit(pbr.roughnessFactor);
        const float metallic = unit(pbr.metallicFactor);
        material.specular = kDielectricSpecular + (kMetalSpecular - kDielectricSpecular) * metallic;
        look.texture = pbr.baseColorTexture.index;
        look.texcoord_set = pbr.baseColorTexture.texCoord;
        if (look.texture >= static_cast<int>(model.textures.size())) {
            return Error{"material " + std::to_string(material_index) + ": texture " +
                         std::to_string(look.texture) + " does not exist"};
        }
        if (look.texcoord_set < 0) {
            return Error{"material " + std::to_string(material_index) + ": texCoord is negative"};
        }
    }
    look.material_packed = pack_material(material);
    look.double_sided = is_double_sided(model, material_index);
    return look;
}

bool is_double_sided(const tinygltf::Model& model, int material) {
    return material >= 0 && static_cast<std::size_t>(material) < model.materials.size() &&
           model.materials[static_cast<std::size_t>(material)].doubleSided;
}

}  // namespace monoplane::scenes::gltf
