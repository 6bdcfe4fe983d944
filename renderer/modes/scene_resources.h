// What every renderer of one scene shares on the GPU: its geometry (vertex and index buffers,
// the levels of detail built at creation included), its textures, its chunk and level tables for
// the culling pass, the shadow map's draw list and the shadow map itself. A study with 3 scenes x 2
// alternatives uploads each scene once, not once per renderer (study run prints the device memory
// it holds).
//
// When may this be used: by renderers whose frames do not overlap on the GPU (each frame is
// submitted and waited for, as ModeRenderer does); the shadow map is redrawn by whichever
// renderer first needs another light region. The scene must outlive the resources.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <glm/mat4x4.hpp>

#include "renderer/graph/frame_graph.h"
#include "renderer/passes/culling/cull_constants.h"
#include "renderer/passes/shadow/shadow_map.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/passes/shared/scene_geometry.h"
#include "renderer/passes/shared/scene_textures.h"
#include "renderer/vk/buffer.h"
#include "scenes/lod_chain.h"
#include "scenes/scene.h"

namespace monoplane::modes {

class SceneResources {
  public:
    SceneResources(const vk_core::Context& ctx, const scenes::Scene& scene,
                   const passes::ShadowParams& shadow);

    const scenes::Scene& scene() const { return scene_; }
    const passes::SceneGeometry& geometry() const { return geometry_; }
    const passes::SceneTextures& textures() const { return textures_; }
    const vk_core::Buffer& chunk_table() const { return chunk_table_; }
    const vk_core::Buffer& level_table() const { return level_table_; }
    // How many chunks of each alpha class (MONOPLANE_CLASS_*) the scene has: the pipelines and
    // passes a renderer of it needs.
    const std::array<std::uint32_t, MONOPLANE_CLASSES>& alpha_classes() const {
        return alpha_classes_;
    }
    const scenes::LodChain& lods() const { return lods_; }
    // How long building the levels of detail took (meshoptimizer's simplifier, every chunk).
    double lod_build_seconds() const { return lod_build_seconds_; }
    const passes::ShadowParams& shadow_params() const { return shadow_params_; }
    const passes::ShadowMap& shadow() const { return shadow_; }
    // The scene as the renderers' pass units use it (the shadow unit draws this shadow map).
    passes::UnitScene unit_scene() const;

    // Whether the shadow map must be drawn for this light transform (it holds another, or none).
    bool shadow_needed(const glm::dmat4& light_view_proj) const {
        return shadow_light_view_proj_ != light_view_proj;
    }
    // A renderer recorded the shadow map for the light transform (when shadow_needed said so),
    // in a submission that completes before another renderer reads the map.
    void shadow_drawn(const glm::dmat4& light_view_proj) {
        shadow_light_view_proj_ = light_view_proj;
    }
    // The shadow map's synchronisation state, shared by every renderer of the scene: each
    // renderer's render graph starts from what the last frame of any of them left.
    graph::ResourceState& shadow_map_state() { return shadow_map_state_; }

  private:
    const scenes::Scene& scene_;
    passes::ShadowParams shadow_params_;
    double lod_build_seconds_ = 0.0;
    scenes::LodChain lods_;
    passes::SceneGeometry geometry_;
    passes::SceneTextures textures_;
    vk_core::Buffer chunk_table_;
    vk_core::Buffer level_table_;
    std::array<std::uint32_t, MONOPLANE_CLASSES> alpha_classes_;
    passes::ShadowMap shadow_;
    // What casts shadows: the opaque chunks, and the masked ones through the alpha test.
    passes::DrawList shadow_opaque_;
    passes::DrawList shadow_masked_;
    std::optional<glm::dmat4> shadow_light_view_proj_;
    graph::ResourceState shadow_map_state_;
};

}  // namespace monoplane::modes
