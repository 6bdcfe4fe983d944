// The merged depth pyramid of both eyes in C's image space (papers/000 Sect. 4.4), as images:
// built after the eyes' near passes by the depth pyramid unit (depth_pyramid_unit.cpp), it lets
// C discard fragments no eye will show (the forward pass's mask) and lets the occlusion culling
// drop C's chunks hidden in both eyes. Mip 0 of the pyramid is the paper's level 2 (4 x 4 pixels
// per texel); levels 0 and 1 are never written. Values are reversed-Z depths of the eyes (whose
// far plane is m): the farthest over the region, 0 where some eye pixel sees past the near
// content, 1 where no eye pixel reads C at all. Beside it, each eye's depth as 4 x 4 block
// minima (one layer per eye), the unit's intermediate. Both live in general layout, always.
//
// The renderer's, as the shadow map is the scene's: several passes read it (the occlusion
// culling, C's forward pass), and it grows with C's allocation.
//
// When may this be called: on the thread that owns the device; resize() between frames, none of
// which in flight uses the pyramid.
#pragma once

#include <cstdint>
#include <optional>

#include "renderer/vk/image.h"

namespace monoplane::passes {

class DepthPyramid {
  public:
    static constexpr vk::Format kFormat = vk::Format::eR32Sfloat;

    // eye_extent: each eye's depth image's size (the blocks' images are a quarter of it).
    DepthPyramid(const vk_core::Context& ctx, vk::Extent2D eye_extent);

    // Whether the pyramid already covers C's allocation (resize() would keep it).
    bool fits(vk::Extent2D mono_allocation) const;
    // (Re)creates the pyramid for C's allocation when it grows; returns true when it did (views
    // of it must be rebound).
    bool resize(vk::Extent2D mono_allocation);

    // Every mip (view(): all of them, for texelFetch; mip_view(level): one, to write).
    const vk_core::Image& pyramid() const { return *pyramid_; }
    const vk_core::Image& blocks() const { return blocks_; }
    // Nearest, every mip: how the pyramid's readers sample it.
    vk::Sampler sampler() const { return *nearest_; }
    std::uint32_t mips() const { return pyramid_->desc().mip_levels; }

  private:
    const vk_core::Context& ctx_;
    vk::raii::Sampler nearest_{nullptr};
    std::optional<vk_core::Image> pyramid_;
    vk_core::Image blocks_;
};

}  // namespace monoplane::passes
