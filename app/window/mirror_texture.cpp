#include "app/window/mirror_texture.h"

#include <algorithm>
#include <cmath>

#include "common/programming_error.h"
#include "renderer/vk/memory.h"

namespace monoplane::window {
namespace {

using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;
using Layout = vk::ImageLayout;

const vk::ImageSubresourceRange kColor(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 1);

vk::ImageMemoryBarrier2 barrier(vk::Image image, Layout from, Layout to,
                                vk::PipelineStageFlags2 src_stage, vk::AccessFlags2 src_access,
                                vk::PipelineStageFlags2 dst_stage, vk::AccessFlags2 dst_access) {
    return vk::ImageMemoryBarrier2(src_stage, src_access, dst_stage, dst_access, from, to,
                                   VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED, image, kColor);
}

}  // namespace

FitRect fit_aspect(float outer_width, float outer_height, float inner_width, float inner_height) {
    if (outer_width <= 0 || outer_height <= 0 || inner_width <= 0 || inner_height <= 0) return {};
    const float scale = std::min(outer_width / inner_width, outer_height / inner_height);
    FitRect rect;
    rect.width = inner_width * scale;
    rect.height = inner_height * scale;
    rect.x = (outer_width - rect.width) * 0.5f;
    rect.y = (outer_height - rect.height) * 0.5f;
    return rect;
}

MirrorTexture::MirrorTexture(const vk_core::Context& ctx, vk::Extent2D extent,
                             vk::DescriptorPool pool, vk::DescriptorSetLayout set_layout)
    : extent_(extent) {
    // Stored as sRGB, so that a blit from an sRGB or a linear source keeps its colours; sampled
    // through a UNORM view, so that the encoded bytes reach the window's UNORM swapchain (where
    // Dear ImGui draws) unchanged, i.e. look as in the headset.
    const std::array view_formats{vk::Format::eR8G8B8A8Srgb, vk::Format::eR8G8B8A8Unorm};
    const vk::ImageFormatListCreateInfo format_list(view_formats);
    const vk::ImageCreateInfo info(
        vk::ImageCreateFlagBits::eMutableFormat, vk::ImageType::e2D, vk::Format::eR8G8B8A8Srgb,
        vk::Extent3D(extent, 1), 1, 1, vk::SampleCountFlagBits::e1, vk::ImageTiling::eOptimal,
        vk::ImageUsageFlagBits::eTransferDst | vk::ImageUsageFlagBits::eSampled,
        vk::SharingMode::eExclusive, {}, Layout::eUndefined, &format_list);
    image_ = vk::raii::Image(ctx.device(), info);
    memory_ = vk_core::allocate_memory(ctx, image_.getMemoryRequirements(),
                                       vk::MemoryPropertyFlagBits::eDeviceLocal);
    image_.bindMemory(*memory_, 0);
    view_ = vk::raii::ImageView(ctx.device(),
                                vk::ImageViewCreateInfo({}, *image_, vk::ImageViewType::e2D,
                                                        vk::Format::eR8G8B8A8Unorm, {}, kColor));

    vk::raii::DescriptorSets sets(ctx.device(), vk::DescriptorSetAllocateInfo(pool, set_layout));
    set_ = std::move(sets.front());
    // The layout's immutable sampler samples it; only the view and layout are written.
    const vk::DescriptorImageInfo image_info({}, *view_, Layout::eShaderReadOnlyOptimal);
    ctx.device().updateDescriptorSets(
        vk::WriteDescriptorSet(*set_, 0, 0, vk::DescriptorType::eCombinedImageSampler, image_info),
        {});

    ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        const auto to_dst = barrier(*image_, Layout::eUndefined, Layout::eTransferDstOptimal,
                                    Stage::eNone, {}, Stage::eClear, Access::eTransferWrite);
        cmd.pipelineBarrier2(vk::DependencyInfo({}, {}, {}, to_dst));
        cmd.clearColorImage(*image_, Layout::eTransferDstOptimal,
                            vk::ClearColorValue(std::array{0.05f, 0.05f, 0.05f, 1.0f}), kColor);
        const auto to_read = barrier(
            *image_, Layout::eTransferDstOptimal, Layout::eShaderReadOnlyOptimal, Stage::eClear,
            Access::eTransferWrite, Stage::eFragmentShader, Access::eShaderSampledRead);
        cmd.pipelineBarrier2(vk::DependencyInfo({}, {}, {}, to_read));
    });
}

void MirrorTexture::record_copy(const vk::raii::CommandBuffer& cmd, vk::Image source,
                                vk::ImageLayout source_layout, vk::Extent2D source_extent) const {
    MONOPLANE_EXPECTS(source_layout != Layout::eUndefined &&
                      source_layout != Layout::ePreinitialized);
    if (source_extent.width == 0 || source_extent.height == 0) return;
    const FitRect fit = fit_aspect(
        static_cast<float>(extent_.width), static_cast<float>(extent_.height),
        static_cast<float>(source_extent.width), static_cast<float>(source_extent.height));
    const auto x0 = static_cast<std::int32_t>(std::lround(fit.x));
    const auto y0 = static_cast<std::int32_t>(std::lround(fit.y));
    const auto x1 = std::clamp(static_cast<std::int32_t>(std::lround(fit.x + fit.width)), x0 + 1,
                               static_cast<std::int32_t>(extent_.width));
    const auto y1 = std::clamp(static_cast<std::int32_t>(std::lround(fit.y + fit.height)), y0 + 1,
                               static_cast<std::int32_t>(extent_.height));
    const bool letterboxed = x0 > 0 || y0 > 0 || x1 < static_cast<std::int32_t>(extent_.width) ||
                             y1 < static_cast<std::int32_t>(extent_.height);

    // The window's previous frame may still sample the mirror (earlier on the same queue), and
    // the source was last written by any stage of the app's frame.
    const std::array before{
        barrier(*image_, Layout::eShaderReadOnlyOptimal, Layout::eTransferDstOptimal,
                Stage::eFragmentShader, {}, Stage::eClear | Stage::eBlit, Access::eTransferWrite),
        barrier(source, source_layout, Layout::eTransferSrcOptimal, Stage::eAllCommands,
                Access::eMemoryWrite, Stage::eBlit, Access::eTransferRead),
    };
    cmd.pipelineBarrier2(vk::DependencyInfo({}, {}, {}, before));
    if (letterboxed) {
        cmd.clearColorImage(*image_, Layout::eTransferDstOptimal,
                            vk::ClearColorValue(std::array{0.0f, 0.0f, 0.0f, 1.0f}), kColor);
        const auto after_clear =
            barrier(*image_, Layout::eTransferDstOptimal, Layout::eTransferDstOptimal,
                    Stage::eClear, Access::eTransferWrite, Stage::eBlit, Access::eTransferWrite);
        cmd.pipelineBarrier2(vk::DependencyInfo({}, {}, {}, after_clear));
    }
    const vk::ImageSubresourceLayers layers(vk::ImageAspectFlagBits::eColor, 0, 0, 1);
    const vk::ImageBlit region(
        layers,
        {vk::Offset3D(0, 0, 0), vk::Offset3D(static_cast<std::int32_t>(source_extent.width),
                                             static_cast<std::int32_t>(source_extent.height), 1)},
        layers, {vk::Offset3D(x0, y0, 0), vk::Offset3D(x1, y1, 1)});
    cmd.blitImage(source, Layout::eTransferSrcOptimal, *image_, Layout::eTransferDstOptimal, region,
                  vk::Filter::eLinear);
    const std::array after{
        barrier(*image_, Layout::eTransferDstOptimal, Layout::eShaderReadOnlyOptimal, Stage::eBlit,
                Access::eTransferWrite, Stage::eFragmentShader, Access::eShaderSampledRead),
        barrier(source, Layout::eTransferSrcOptimal, source_layout, Stage::eBlit, {},
                Stage::eAllCommands, Access::eMemoryRead | Access::eMemoryWrite),
    };
    cmd.pipelineBarrier2(vk::DependencyInfo({}, {}, {}, after));
}

}  // namespace monoplane::window
