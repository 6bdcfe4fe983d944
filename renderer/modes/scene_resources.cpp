#include "renderer/modes/scene_resources.h"

#include <chrono>
#include <numeric>
#include <vector>

#include "renderer/passes/culling/chunk_culling_pass.h"

namespace monoplane::modes {
namespace {

scenes::LodChain timed_lod_chain(const scenes::Scene& scene, double& seconds) {
    const auto start = std::chrono::steady_clock::now();
    scenes::LodChain chain = scenes::build_lod_chain(scene);
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return chain;
}

}  // namespace

SceneResources::SceneResources(const vk_core::Context& ctx, const scenes::Scene& scene,
                               const passes::ShadowParams& shadow)
    : scene_(scene),
      shadow_params_(shadow),
      lods_(timed_lod_chain(scene, lod_build_seconds_)),
      geometry_(ctx, scene, lods_),
      textures_(ctx, scene),
      chunk_table_(passes::ChunkCullingPass::make_chunk_table(ctx, scene, lods_)),
      level_table_(passes::ChunkCullingPass::make_level_table(ctx, scene, lods_)),
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
