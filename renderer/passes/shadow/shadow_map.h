// The sun's shadow map: depth-only, orthographic, fitted to the region around the viewer.
#pragma once

#include <glm/mat4x4.hpp>

#include "renderer/passes/shared/scene_geometry.h"
#include "renderer/vk/image.h"

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

// The shadow map itself, which every renderer of a scene shares (modes::SceneResources): the
// depth image, the comparison sampler the forward passes read it through, and its parameters.
// The shadow unit (shadow_unit.cpp) draws it.
class ShadowMap {
  public:
    ShadowMap(const vk_core::Context& ctx, const ShadowParams& params);

    vk::ImageView view() const { return map_.view(); }
    const vk_core::Image& map() const { return map_; }
    vk::Sampler sampler() const { return *sampler_; }
    float texel_size() const { return 1.0f / static_cast<float>(params_.resolution); }
    const ShadowParams& params() const { return params_; }

    // The map's depth format.
    static constexpr vk::Format kFormat = vk::Format::eD32Sfloat;

  private:
    ShadowParams params_;
    vk_core::Image map_;
    vk::raii::Sampler sampler_{nullptr};
};

}  // namespace monoplane::passes
