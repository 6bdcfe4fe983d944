#include "scenes/gltf/texture_set.h"

#include <utility>

#include "scenes/gltf/texture_decode.h"

namespace monoplane::scenes::gltf {

TextureSet::TextureSet(const GltfDocument& document, std::uint64_t max_texels)
    : document_(document), texels_left_(max_texels) {}

Result<int> TextureSet::use(int texture) {
    const auto found = scene_index_of_.find(texture);
    if (found != scene_index_of_.end()) return found->second;
    Result<SceneTexture> decoded = decode_texture(document_, texture, texels_left_);
    MONOPLANE_TRY(decoded);
    texels_left_ -= std::uint64_t{decoded->width} * decoded->height;
    const int index = static_cast<int>(textures_.size());
    textures_.push_back(std::move(decoded).value());
    scene_index_of_.emplace(texture, index);
    return index;
}

std::vector<SceneTexture> TextureSet::take() {
    scene_index_of_.clear();
    return std::exchange(textures_, {});
}

}  // namespace monoplane::scenes::gltf
