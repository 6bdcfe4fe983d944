#include "app/headset/eye_compositor.h"

#include <algorithm>
#include <cmath>

#include "renderer/vk/buffer.h"

namespace monoplane::headset {
namespace {

using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;

void barrier(const vk::raii::CommandBuffer& cmd, vk::Image image, vk::ImageLayout from,
             vk::ImageLayout to, vk::PipelineStageFlags2 src_stage, vk::AccessFlags2 src_access,
             vk::PipelineStageFlags2 dst_stage, vk::AccessFlags2 dst_access) {
    const vk::ImageMemoryBarrier2 b(
        src_stage, src_access, dst_stage, dst_access, from, to, VK_QUEUE_FAMILY_IGNORED,
        VK_QUEUE_FAMILY_IGNORED, image,
        vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1));
    cmd.pipelineBarrier2(vk::DependencyInfo().setImageMemoryBarriers(b));
}

vk::ImageBlit full_blit(vk::Extent2D from, const PixelRect& to) {
    const vk::ImageSubresourceLayers layers(vk::ImageAspectFlagBits::eColor, 0, 0, 1);
    return vk::ImageBlit(layers,
                         {vk::Offset3D(0, 0, 0), vk::Offset3D(static_cast<int>(from.width),
                                                              static_cast<int>(from.height), 1)},
                         layers, {vk::Offset3D(to.x0, to.y0, 0), vk::Offset3D(to.x1, to.y1, 1)});
}

}  // namespace

struct EyeCompositor::Texture {
    vk_core::Image image;
    vk::Extent2D extent;
};

PixelRect overlay_rect(const OverlayPlacement& p, std::uint32_t image_width,
                       std::uint32_t image_height, const rig::Tangents& eye,
                       vk::Extent2D eye_extent) {
    // Pixels per tangent unit, horizontally and vertically (the eye's image spans its tangents).
    const double px_x = eye_extent.width / (eye.right - eye.left);
    const double px_y = eye_extent.height / (eye.up - eye.down);
    const double height = p.tan_height * px_y;
    const double width = height * image_width / std::max<std::uint32_t>(image_height, 1);
    const double cx = (p.tan_x - eye.left) * px_x;
    const double cy = (eye.up - p.tan_y) * px_y;
    PixelRect r;
    r.x0 = static_cast<int>(std::lround(cx - width / 2));
    r.x1 = static_cast<int>(std::lround(cx + width / 2));
    r.y0 = static_cast<int>(std::lround(cy - height / 2));
    r.y1 = static_cast<int>(std::lround(cy + height / 2));
    // Kept inside the image: a blit may not write outside it.
    const int w = static_cast<int>(eye_extent.width);
    const int h = static_cast<int>(eye_extent.height);
    r.x0 = std::clamp(r.x0, 0, w);
    r.x1 = std::clamp(r.x1, r.x0, w);
    r.y0 = std::clamp(r.y0, 0, h);
    r.y1 = std::clamp(r.y1, r.y0, h);
    return r;
}

EyeCompositor::EyeCompositor(const vk_core::Context& ctx) : ctx_(ctx) {}
EyeCompositor::~EyeCompositor() = default;

bool EyeCompositor::has_overlay(const std::string& key) const {
    return textures_.count(key) != 0;
}

void EyeCompositor::set_overlay(const std::string& key, const modes::RgbaImage& image) {
    auto texture = std::make_unique<Texture>();
    texture->extent = vk::Extent2D(image.width, image.height);
    // sRGB like the eyes: the text's bytes reach the display unchanged.
    texture->image = vk_core::Image(
        ctx_, {texture->extent, vk::Format::eR8G8B8A8Srgb,
               vk::ImageUsageFlagBits::eTransferSrc | vk::ImageUsageFlagBits::eTransferDst |
                   vk::ImageUsageFlagBits::eSampled});
    const vk_core::Buffer staging(ctx_, image.pixels.size(), vk::BufferUsageFlagBits::eTransferSrc,
                                  vk_core::MemoryUse::kHostVisible);
    staging.write(image.pixels.data(), image.pixels.size());
    ctx_.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        vk_core::transition(cmd, texture->image, vk::ImageLayout::eUndefined,
                            vk::ImageLayout::eTransferDstOptimal, Stage::eNone, Access::eNone,
                            Stage::eTransfer, Access::eTransferWrite);
        cmd.copyBufferToImage(
            staging.handle(), texture->image.handle(), vk::ImageLayout::eTransferDstOptimal,
            vk::BufferImageCopy(
                0, 0, 0, vk::ImageSubresourceLayers(vk::ImageAspectFlagBits::eColor, 0, 0, 1),
                {0, 0, 0}, vk::Extent3D(texture->extent, 1)));
        // From here on it is only ever read by blits.
        vk_core::transition(cmd, texture->image, vk::ImageLayout::eTransferDstOptimal,
                            vk::ImageLayout::eTransferSrcOptimal, Stage::eTransfer,
                            Access::eTransferWrite, Stage::eTransfer, Access::eTransferRead);
    });
    textures_[key] = std::move(texture);
}

void EyeCompositor::record_eye(const vk::raii::CommandBuffer& cmd, vk::Image target,
                               vk::Extent2D extent, const rig::Tangents& tangents,
                               const vk_core::Image* source, const std::vector<Overlay>& overlays,
                               const MirrorRecorder& mirror) const {
    barrier(cmd, target, vk::ImageLayout::eColorAttachmentOptimal,
            vk::ImageLayout::eTransferDstOptimal, Stage::eColorAttachmentOutput | Stage::eTransfer,
            Access::eColorAttachmentWrite | Access::eTransferWrite | Access::eTransferRead,
            Stage::eTransfer, Access::eTransferWrite);
    if (source) {
        // The renderer's frame left it a transfer source, visible to transfers that follow.
        const PixelRect all{0, 0, static_cast<int>(extent.width), static_cast<int>(extent.height)};
        const vk::Extent2D from = source->desc().extent;
        // Same size: an exact copy; a blit also converts RGBA to a BGRA swapchain.
        cmd.blitImage(source->handle(), vk::ImageLayout::eTransferSrcOptimal, target,
                      vk::ImageLayout::eTransferDstOptimal, full_blit(from, all),
                      from == extent ? vk::Filter::eNearest : vk::Filter::eLinear);
    } else {
        const vk::ClearColorValue grey(
            std::array<float, 4>{kNeutralGrey, kNeutralGrey, kNeutralGrey, 1.0f});
        cmd.clearColorImage(target, vk::ImageLayout::eTransferDstOptimal, grey,
                            vk::ImageSubresourceRange(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1));
    }
    if (!overlays.empty()) {
        barrier(cmd, target, vk::ImageLayout::eTransferDstOptimal,
                vk::ImageLayout::eTransferDstOptimal, Stage::eTransfer, Access::eTransferWrite,
                Stage::eTransfer, Access::eTransferWrite);
    }
    for (const Overlay& overlay : overlays) {
        const auto it = textures_.find(overlay.key);
        if (it == textures_.end()) continue;
        const Texture& texture = *it->second;
        const PixelRect rect = overlay_rect(overlay.placement, texture.extent.width,
                                            texture.extent.height, tangents, extent);
        if (rect.x1 <= rect.x0 || rect.y1 <= rect.y0) continue;
        cmd.blitImage(texture.image.handle(), vk::ImageLayout::eTransferSrcOptimal, target,
                      vk::ImageLayout::eTransferDstOptimal, full_blit(texture.extent, rect),
                      vk::Filter::eNearest);
    }
    if (mirror) {
        barrier(cmd, target, vk::ImageLayout::eTransferDstOptimal,
                vk::ImageLayout::eTransferSrcOptimal, Stage::eTransfer, Access::eTransferWrite,
                Stage::eTransfer, Access::eTransferRead);
        mirror(cmd, target, vk::ImageLayout::eTransferSrcOptimal, extent);
        barrier(cmd, target, vk::ImageLayout::eTransferSrcOptimal,
                vk::ImageLayout::eColorAttachmentOptimal, Stage::eTransfer, Access::eTransferRead,
                Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite);
    } else {
        barrier(cmd, target, vk::ImageLayout::eTransferDstOptimal,
                vk::ImageLayout::eColorAttachmentOptimal, Stage::eTransfer, Access::eTransferWrite,
                Stage::eColorAttachmentOutput, Access::eColorAttachmentWrite);
    }
}

std::vector<PixelRect> EyeCompositor::overlay_rects(const std::vector<Overlay>& overlays,
                                                    const rig::Tangents& tangents,
                                                    vk::Extent2D extent) const {
    std::vector<PixelRect> rects;
    for (const Overlay& overlay : overlays) {
        const auto it = textures_.find(overlay.key);
        if (it == textures_.end()) continue;
        const vk::Extent2D size = it->second->extent;
        rects.push_back(overlay_rect(overlay.placement, size.width, size.height, tangents, extent));
    }
    return rects;
}

}  // namespace monoplane::headset
