#include "renderer/modes/scene_resources.h"

#include <numeric>
#include <vector>

#include "renderer/passes/culling/chunk_culling_pass.h"

namespace monoplane::modes {

SceneResources::SceneResources(const vk_core::Context& ctx, const scenes::Scene& scene,
                               const passes::ShadowParams& shadow)
    : scene_(scene),
      shadow_params_(shadow),
      geometry_(ctx, scene),
      textures_(ctx, scene),
      chunk_table_(passes::ChunkCullingPass::make_chunk_table(ctx, scene)),
      shadow_(ctx, shadow),
      shadow_draws_(ctx, scene.chunks.size()) {
    std::vector<std::uint32_t> all(scene.chunks.size());
    std::iota(all.begin(), all.end(), 0u);
    shadow_draws_.assign(scene, all);
}

void SceneResources::record_shadow(const vk::raii::CommandBuffer& cmd,
                                   const glm::dmat4& light_view_proj) {
    shadow_.record(cmd, geometry_, shadow_draws_, glm::mat4(light_view_proj));
    // Frames are waited for before the next is recorded, so the map holds this from now on.
    shadow_light_view_proj_ = light_view_proj;
}

}  // namespace monoplane::modes
