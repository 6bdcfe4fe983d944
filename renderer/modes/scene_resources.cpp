#include "renderer/modes/scene_resources.h"

#include <chrono>
#include <vector>

#include "renderer/passes/culling/chunk_lists.h"

namespace monoplane::modes {
namespace {

scenes::LodChain timed_lod_chain(const scenes::Scene& scene, double& seconds) {
    const auto start = std::chrono::steady_clock::now();
    scenes::LodChain chain = scenes::build_lod_chain(scene);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return chain;
}

std::vector<std::uint32_t> chunks_of(const scenes::Scene& scene, scenes::AlphaMode mode) {
    std::vector<std::uint32_t> chunks;
    for (std::uint32_t i = 0; i < scene.chunks.size(); ++i) {
        if (scene.chunks[i].alpha_mode == mode) chunks.push_back(i);
    }
    return chunks;
}

}  // namespace

SceneResources::SceneResources(const vk_core::Context& ctx, const scenes::Scene& scene,
                               const passes::ShadowParams& shadow)
    : scene_(scene),
      shadow_params_(shadow),
      lods_(timed_lod_chain(scene, lod_build_seconds_)),
      geometry_(ctx, scene, lods_),
      textures_(ctx, scene),
      chunk_table_(passes::ChunkLists::make_chunk_table(ctx, scene, lods_)),
      level_table_(passes::ChunkLists::make_level_table(ctx, scene, lods_)),
      alpha_classes_(passes::ChunkLists::class_sizes(scene)),
      shadow_(ctx, shadow),
      shadow_opaque_(ctx, scene.chunks.size()),
      shadow_masked_(ctx, scene.chunks.size()) {
    shadow_opaque_.assign(scene, chunks_of(scene, scenes::AlphaMode::kOpaque));
    shadow_masked_.assign(scene, chunks_of(scene, scenes::AlphaMode::kMask));
}

passes::UnitScene SceneResources::unit_scene() const {
    passes::UnitScene unit;
    unit.geometry = &geometry_;
    unit.textures = &textures_;
    // Blended chunks cast no shadow (passes::ShadowCasters).
    unit.shadow_casters = passes::ShadowCasters{shadow_opaque_.indirect(),
                                                shadow_masked_.indirect(), textures_.set()};
    unit.shadow = shadow_params_;
    unit.shadow_sampler = shadow_.sampler();
    unit.masked_chunks = alpha_classes_[MONOPLANE_CLASS_MASKED] > 0;
    unit.blended_chunks = alpha_classes_[MONOPLANE_CLASS_BLENDED] > 0;
    return unit;
}

}  // namespace monoplane::modes
