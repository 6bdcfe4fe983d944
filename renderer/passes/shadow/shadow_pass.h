// The sun's shadow map: depth-only, orthographic, fitted to the region around the viewer.
#pragma once

#include <glm/mat4x4.hpp>

#include "renderer/passes/shared/scene_geometry.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {

struct ShadowParams {
    std::uint32_t resolution = 4096;
    float region_radius_m = 160.0f;  // shadows are computed within this distance of the viewer
    float depth_bias_constant = 1.25f;
    float depth_bias_slope = 1.75f;
    bool operator==(const ShadowParams&) const = default;
};

// Orthographic world -> shadow clip transform (depth 0 nearest the sun) that encloses `region`.
glm::dmat4 fit_light_view_proj(const glm::dvec3& towards_sun, const scenes::Aabb& region);

// What casts a shadow: the opaque chunks whole, the alpha-masked ones (alphaMode MASK) where
// their alpha reaches the cut-off. Blended chunks cast none (a pane of glass would otherwise
// throw a solid shadow: the map holds one depth per texel, not a transmittance).
struct ShadowCasters {
    IndirectDraws opaque;
    IndirectDraws masked;
    vk::DescriptorSet textures;  // set 2 (SceneTextures::set()), read by the masked draws
};

class ShadowPass {
  public:
    // scene_textures: the layout of set 2 (SceneTextures::layout()); masked: the scene has
    // alpha-masked chunks, whose pipeline (the alpha test) is then made.
    ShadowPass(const vk_core::Context& ctx, const ShadowParams& params,
               vk::DescriptorSetLayout scene_textures, bool masked);

    // Leaves the shadow map in eShaderReadOnlyOptimal for the forward pass.
    void record(const vk::raii::CommandBuffer& cmd, const SceneGeometry& geometry,
                const ShadowCasters& casters, const glm::mat4& light_view_proj) const;

    vk::ImageView view() const { return map_.view(); }
    const vk_core::Image& map() const { return map_; }
    vk::Sampler sampler() const { return *sampler_; }
    float texel_size() const { return 1.0f / static_cast<float>(params_.resolution); }
    const ShadowParams& params() const { return params_; }

  private:
    ShadowParams params_;
    vk_core::Image map_;
    vk::raii::Sampler sampler_{nullptr};
    void make_masked_pipeline(const vk_core::Context& ctx, vk_core::GraphicsPipelineDesc desc);

    vk::raii::DescriptorSetLayout no_bindings_{nullptr};  // sets 0 and 1: the forward pass's
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
    vk::raii::Pipeline masked_pipeline_{nullptr};  // alphaMode MASK: the alpha test
};

}  // namespace monoplane::passes
