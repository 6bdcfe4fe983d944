// The base-colour textures an import uses, each decoded once however many primitives share it,
// within one texel budget for the whole scene.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "common/result.h"
#include "scenes/gltf/gltf_document.h"
#include "scenes/scene.h"

namespace monoplane::scenes::gltf {

class TextureSet {
  public:
    // max_texels: all textures together (GltfLoadOptions::max_texture_texels).
    TextureSet(const GltfDocument& document, std::uint64_t max_texels);

    // The Scene::textures index of glTF texture `texture`, decoding it on first use.
    Result<int> use(int texture);
    // The decoded textures, in Scene::textures order; the set is empty afterwards.
    std::vector<SceneTexture> take();

  private:
    const GltfDocument& document_;
    std::uint64_t texels_left_;
    std::map<int, int> scene_index_of_;
    std::vector<SceneTexture> textures_;
};

}  // namespace monoplane::scenes::gltf
