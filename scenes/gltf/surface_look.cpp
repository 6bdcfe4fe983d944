#include "scenes/gltf/surface_look.h"

#include <algorithm>
#include <sstream>
#include <string>

#include "scenes/scene.h"

namespace monoplane::scenes::gltf {
namespace {

constexpr float kDielectricSpecular = 0.04f;
constexpr float kMetalSpecular = 0.5f;

float unit(double value) {
    return static_cast<float>(std::clamp(value, 0.0, 1.0));
}

// "material 2 'Glass'" (or "material 2" for an unnamed one), for messages.
std::string describe_material(const tinygltf::Model& model, int index) {
    const std::string& name = model.materials[static_cast<std::size_t>(index)].name;
    return "material " + std::to_string(index) + (name.empty() ? "" : " '" + name + "'");
}

// glTF's alphaMode and alphaCutoff. The cut-off must not be negative whatever the mode (the
// schema's minimum), but only MASK uses it: other modes keep the default, as the specification
// has them ignore it.
Result<void> read_alpha(const tinygltf::Material& material, const std::string& where,
                        SurfaceLook& look) {
    if (material.alphaMode == "OPAQUE") {
        look.alpha_mode = AlphaMode::kOpaque;
    } else if (material.alphaMode == "MASK") {
        look.alpha_mode = AlphaMode::kMask;
    } else if (material.alphaMode == "BLEND") {
        look.alpha_mode = AlphaMode::kBlend;
    } else {
        return Error{where + ": alphaMode '" + material.alphaMode +
                     "' is not OPAQUE, MASK or BLEND"};
    }
    if (!(material.alphaCutoff >= 0.0)) {
        std::ostringstream text;
        text << where << ": alphaCutoff " << material.alphaCutoff << " is negative";
        return Error{text.str()};
    }
    if (look.alpha_mode == AlphaMode::kMask) {
        look.alpha_cutoff = static_cast<float>(material.alphaCutoff);
    }
    return Ok{};
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
        const tinygltf::Material& source =
            model.materials[static_cast<std::size_t>(material_index)];
        const std::string where = describe_material(model, material_index);
        const tinygltf::PbrMetallicRoughness& pbr = source.pbrMetallicRoughness;
        if (pbr.baseColorFactor.size() != 4) {
            return Error{where + ": baseColorFactor must have 4 elements"};
        }
        // glTF's factor is linear already, like Vertex::albedo_rgba8; its alpha is the surface's
        // alpha (times COLOR_0's and the texture's) wherever alphaMode is MASK or BLEND.
        look.base_color = {unit(pbr.baseColorFactor[0]), unit(pbr.baseColorFactor[1]),
                           unit(pbr.baseColorFactor[2]), unit(pbr.baseColorFactor[3])};
        material.roughness = unit(pbr.roughnessFactor);
        const float metallic = unit(pbr.metallicFactor);
        material.specular = kDielectricSpecular + (kMetalSpecular - kDielectricSpecular) * metallic;
        look.texture = pbr.baseColorTexture.index;
        look.texcoord_set = pbr.baseColorTexture.texCoord;
        if (look.texture >= static_cast<int>(model.textures.size())) {
            return Error{where + ": texture " + std::to_string(look.texture) + " does not exist"};
        }
        if (look.texcoord_set < 0) return Error{where + ": texCoord is negative"};
        MONOPLANE_TRY(read_alpha(source, where, look));
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
