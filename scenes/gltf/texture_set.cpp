#include "scenes/gltf/texture_set.h"

#include <cassert>
#include <utility>

#include "scenes/gltf/texture_decode.h"

namespace monoplane::scenes::gltf {

TextureSet::TextureSet(const GltfDocument& document, std::uint64_t max_texels)
    : document_(document), texels_left_(max_texels) {}

Result<int> TextureSet::use(int texture) {
    const auto found = scene_index_of_.find(texture);
    if (found != scene_index_of_.end()) return found->second;
    Result<SceneTexture> decoded = decode_texture(document_, texture, texels_left_);
    if (!decoded) return decoded.error();
    texels_left_ -= std::uint64_t{decoded->width} * decoded->height;
    const int index = static_cast<int>(textures_.size());
    bakes_.emplace_back(*decoded);
    textures_.push_back(std::move(decoded).value());
    scene_index_of_.emplace(texture, index);
    return index;
}

const TextureBake& TextureSet::bake(int scene_texture) const {
    assert(scene_texture >= 0 && static_cast<std::size_t>(scene_texture) < bakes_.size());
    return bakes_[static_cast<std::size_t>(scene_texture)];
}

std::vector<SceneTexture> TextureSet::take() {
    scene_index_of_.clear();
    bakes_.clear();
    return std::exchange(textures_, {});
}

}  // namespace monoplane::scenes::gltf
