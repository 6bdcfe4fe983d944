#include "app/headset/eye_depth_writer.h"

#include <array>

#include "app/headset/eye_depth_constants.h"
#include "common/programming_error.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::headset {
namespace {

const std::uint32_t kFullscreenVert[] = {
#include "fullscreen.vert.spv.inc"
};
const std::uint32_t kEyeDepthFrag[] = {
#include "eye_depth.frag.spv.inc"
};

using Stage = vk::PipelineStageFlagBits2;
using Access = vk::AccessFlagBits2;

void barrier(const vk::raii::CommandBuffer& cmd, const vk::ImageMemoryBarrier2& b) {
    cmd.pipelineBarrier2(vk::DependencyInfo().setImageMemoryBarriers(b));
}

}  // namespace

const std::vector<vk::Format>& eye_depth_formats() {
    // D24 before D16: more steps of near / distance. Formats with stencil last: the stencil is
    // carried along unused.
    static const std::vector<vk::Format> formats = {
        vk::Format::eD32Sfloat, vk::Format::eX8D24UnormPack32, vk::Format::eD24UnormS8Uint,
        vk::Format::eD16Unorm,  vk::Format::eD32SfloatS8Uint,
    };
    return formats;
}

vk::ImageAspectFlags depth_aspects(vk::Format format) {
    if (format == vk::Format::eD24UnormS8Uint || format == vk::Format::eD32SfloatS8Uint) {
        return vk::ImageAspectFlagBits::eDepth | vk::ImageAspectFlagBits::eStencil;
    }
    return vk::ImageAspectFlagBits::eDepth;
}

EyeDepthWriter::EyeDepthWriter(const vk_core::Context& ctx, vk::Format format)
    : ctx_(ctx), format_(format) {
    const vk::DescriptorSetLayoutBinding binding(0, vk::DescriptorType::eCombinedImageSampler, 1,
                                                 vk::ShaderStageFlagBits::eFragment);
    set_layout_ =
        vk::raii::DescriptorSetLayout(ctx.device(), vk::DescriptorSetLayoutCreateInfo({}, binding));
    sampler_ = vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest);
    const vk::DescriptorSetLayout set_layout = *set_layout_;
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0,
                                     sizeof(EyeDepthConstants));
    layout_ =
        vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, set_layout, push));
    const vk::raii::ShaderModule vert = vk_core::make_shader(ctx, kFullscreenVert);
    const vk::raii::ShaderModule frag = vk_core::make_shader(ctx, kEyeDepthFrag);
    vk_core::GraphicsPipelineDesc desc;
    desc.layout = *layout_;
    desc.vertex = *vert;
    desc.fragment = *frag;
    desc.depth_format = format;
    desc.cull = vk::CullModeFlagBits::eNone;
    // Every pixel takes the shader's depth: Vulkan writes depth only with the test enabled.
    desc.depth_test = true;
    desc.depth_write = true;
    desc.depth_compare = vk::CompareOp::eAlways;
    pipeline_ = vk_core::make_graphics_pipeline(ctx, desc);
}

vk::ImageView EyeDepthWriter::target_view(vk::Image target) {
    auto it = targets_.find(target);
    if (it == targets_.end()) {
        const vk::ImageViewCreateInfo info(
            {}, target, vk::ImageViewType::e2D, format_, {},
            vk::ImageSubresourceRange(depth_aspects(format_), 0, 1, 0, 1));
        it = targets_.emplace(target, vk::raii::ImageView(ctx_.device(), info)).first;
    }
    return *it->second;
}

vk::DescriptorSet EyeDepthWriter::source_set(const vk_core::Image& linear_depth) {
    auto it = sources_.find(linear_depth.view());
    if (it == sources_.end()) {
        const std::array sizes = {
            vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1)};
        vk_core::DescriptorSet set(ctx_, *set_layout_, sizes);
        const std::array images = {vk::DescriptorImageInfo(
            *sampler_, linear_depth.view(), vk::ImageLayout::eShaderReadOnlyOptimal)};
        vk_core::write_sampled_images(ctx_, *set, images);
        it = sources_.emplace(linear_depth.view(), std::move(set)).first;
    }
    return *it->second;
}

void EyeDepthWriter::record(const vk::raii::CommandBuffer& cmd, vk::Image target,
                            vk::Extent2D extent, const EyeDepthSource* source, double near,
                            const std::vector<PixelRect>& at_infinity) {
    const vk::ImageSubresourceRange target_range(depth_aspects(format_), 0, 1, 0, 1);
    constexpr vk::ImageLayout kAttachment = vk::ImageLayout::eDepthStencilAttachmentOptimal;
    // The layout the runtime hands the image out in and wants back; the barrier orders this
    // write after the last one into the same image (an earlier frame's).
    barrier(cmd, vk::ImageMemoryBarrier2(
                     Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
                     Access::eDepthStencilAttachmentWrite,
                     Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
                     Access::eDepthStencilAttachmentRead | Access::eDepthStencilAttachmentWrite,
                     kAttachment, kAttachment, VK_QUEUE_FAMILY_IGNORED, VK_QUEUE_FAMILY_IGNORED,
                     target, target_range));
    const vk_core::Image* linear = source ? source->linear_depth.image : nullptr;
    const vk::ImageLayout found =
        source ? source->linear_depth.layout : vk::ImageLayout::eUndefined;
    MONOPLANE_EXPECTS(linear == nullptr || found != vk::ImageLayout::eUndefined);
    if (linear) {
        // Written as a colour attachment, or already made readable (SSAO, TAA) or copied from
        // (read-back): readable now, and back to that layout after, as the renderer expects.
        vk_core::transition(
            cmd, *linear, found, vk::ImageLayout::eShaderReadOnlyOptimal,
            Stage::eColorAttachmentOutput | Stage::eFragmentShader | Stage::eTransfer,
            Access::eColorAttachmentWrite, Stage::eFragmentShader, Access::eShaderSampledRead);
    }
    // Cleared to infinity: what the neutral screen and the questionnaire keep.
    const vk::RenderingAttachmentInfo depth(
        target_view(target), kAttachment, {}, {}, {}, vk::AttachmentLoadOp::eClear,
        vk::AttachmentStoreOp::eStore, vk::ClearValue(vk::ClearDepthStencilValue(0.0f, 0)));
    cmd.beginRendering(vk::RenderingInfo()
                           .setRenderArea(vk::Rect2D({0, 0}, extent))
                           .setLayerCount(1)
                           .setPDepthAttachment(&depth));
    if (linear) {
        vk_core::set_viewport_and_scissor(cmd, extent);
        cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline_);
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 0, source_set(*linear),
                               {});
        const rig::Tangents& t = source->tangents;
        EyeDepthConstants constants;
        // A rotation's inverse is its transpose.
        constants.eye_to_head = glm::mat4(glm::mat3(glm::transpose(source->head_to_eye)));
        constants.tangents = glm::vec4(static_cast<float>(t.left), static_cast<float>(t.right),
                                       static_cast<float>(t.up), static_cast<float>(t.down));
        constants.encoding = glm::vec4(static_cast<float>(near),
                                       static_cast<float>(source->eye_in_front), 0.0f, 0.0f);
        cmd.pushConstants<EyeDepthConstants>(*layout_, vk::ShaderStageFlagBits::eFragment, 0,
                                             constants);
        cmd.draw(3, 1, 0, 0);
    }
    std::vector<vk::ClearRect> rects;
    for (const PixelRect& r : at_infinity) {
        if (r.x1 <= r.x0 || r.y1 <= r.y0) continue;
        rects.emplace_back(
            vk::Rect2D({r.x0, r.y0}, vk::Extent2D(static_cast<std::uint32_t>(r.x1 - r.x0),
                                                  static_cast<std::uint32_t>(r.y1 - r.y0))),
            0, 1);
    }
    if (!rects.empty()) {
        // After the draw: vkCmdClearAttachments runs in rasterization order with it.
        const vk::ClearAttachment clear(vk::ImageAspectFlagBits::eDepth, 0,
                                        vk::ClearValue(vk::ClearDepthStencilValue(0.0f, 0)));
        cmd.clearAttachments(clear, rects);
    }
    cmd.endRendering();
    if (linear) {
        vk_core::transition(
            cmd, *linear, vk::ImageLayout::eShaderReadOnlyOptimal, found, Stage::eFragmentShader,
            Access::eShaderSampledRead,
            Stage::eFragmentShader | Stage::eColorAttachmentOutput | Stage::eTransfer,
            Access::eNone);
    }
}

}  // namespace monoplane::headset
