#include "renderer/passes/depth_pyramid/depth_pyramid.h"

#include <algorithm>
#include <array>
#include <bit>

#include "renderer/executor/image_layouts.h"

namespace monoplane::passes {
namespace {

// One pyramid texel per 4 x 4 block of C's pixels.
vk::Extent2D pyramid_extent(vk::Extent2D mono_allocation) {
    return {(mono_allocation.width + 3) / 4, (mono_allocation.height + 3) / 4};
}

// The pyramid of `extent` (mip 0), every level down to 1 x 1. Its first contents are "nothing
// needs C" (1), never read before a build.
vk_core::Image make_pyramid(const vk_core::Context& ctx, vk::Extent2D extent) {
    vk_core::ImageDesc desc;
    desc.extent = extent;
    desc.format = DepthPyramid::kFormat;
    desc.usage = vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled |
                 vk::ImageUsageFlagBits::eTransferDst;
    desc.mip_levels =
        static_cast<std::uint32_t>(std::bit_width(std::max(extent.width, extent.height)));
    vk_core::Image pyramid(ctx, desc);
    vk_core::initialise_image(ctx, pyramid, executor::layout_for(graph::Use::kStorageWrite),
                              vk::ClearColorValue(std::array{1.0f, 1.0f, 1.0f, 1.0f}));
    return pyramid;
}

vk_core::Image make_blocks(const vk_core::Context& ctx, vk::Extent2D eye_extent) {
    vk_core::ImageDesc desc;
    desc.extent = vk::Extent2D((eye_extent.width + 3) / 4, (eye_extent.height + 3) / 4);
    desc.format = DepthPyramid::kFormat;
    desc.usage = vk::ImageUsageFlagBits::eStorage;
    desc.layers = 2;
    vk_core::Image blocks(ctx, desc);
    vk_core::initialise_image(ctx, blocks, executor::layout_for(graph::Use::kStorageWrite));
    return blocks;
}

}  // namespace

DepthPyramid::DepthPyramid(const vk_core::Context& ctx, vk::Extent2D eye_extent)
    : ctx_(ctx), blocks_(make_blocks(ctx, eye_extent)) {
    nearest_ = vk_core::make_texel_sampler(ctx);
    // A 1 x 1 pyramid until C exists: the culling pass's descriptor must name a valid image.
    pyramid_.emplace(make_pyramid(ctx, {1, 1}));
}

bool DepthPyramid::fits(vk::Extent2D mono_allocation) const {
    const vk::Extent2D needed = pyramid_extent(mono_allocation);
    const vk::Extent2D extent = pyramid_->desc().extent;
    return needed.width <= extent.width && needed.height <= extent.height;
}

bool DepthPyramid::resize(vk::Extent2D mono_allocation) {
    if (fits(mono_allocation)) return false;
    pyramid_.reset();
    pyramid_.emplace(make_pyramid(ctx_, pyramid_extent(mono_allocation)));
    return true;
}

}  // namespace monoplane::passes
