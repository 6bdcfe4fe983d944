#include "renderer/passes/tonemap/tonemap_pass.h"

#include <array>

#include "renderer/executor/image_layouts.h"

namespace monoplane::passes {
namespace {
const std::uint32_t kFullscreenVert[] = {
#include "fullscreen.vert.spv.inc"
};
const std::uint32_t kTonemapFrag[] = {
#include "tonemap.frag.spv.inc"
};
}  // namespace

TonemapPass::TonemapPass(const vk_core::Context& ctx) : ctx_(ctx) {
    const vk::DescriptorSetLayoutBinding binding(0, vk::DescriptorType::eCombinedImageSampler, 1,
                                                 vk::ShaderStageFlagBits::eFragment);
    set_layout_ =
        vk::raii::DescriptorSetLayout(ctx.device(), vk::DescriptorSetLayoutCreateInfo({}, binding));
    sampler_ = vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest);
    const vk::DescriptorSetLayout set_layout = *set_layout_;
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0, sizeof(TonemapParams));
    layout_ =
        vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, set_layout, push));
    const vk::raii::ShaderModule vert = vk_core::make_shader(ctx, kFullscreenVert);
    const vk::raii::ShaderModule frag = vk_core::make_shader(ctx, kTonemapFrag);
    vk_core::GraphicsPipelineDesc desc;
    desc.layout = *layout_;
    desc.vertex = *vert;
    desc.fragment = *frag;
    desc.color_formats = {kDisplayFormat};
    desc.cull = vk::CullModeFlagBits::eNone;
    desc.depth_test = false;
    desc.depth_write = false;
    pipeline_ = vk_core::make_graphics_pipeline(ctx, desc);
}

void TonemapPass::record(const vk::raii::CommandBuffer& cmd, const vk_core::Image& display,
                         vk::DescriptorSet hdr_set, const TonemapParams& params,
                         const std::optional<Predicate>& when) const {
    const vk::RenderingAttachmentInfo color(
        display.view(), executor::layout_for(graph::Use::kColorWrite), {}, {}, {},
        when ? vk::AttachmentLoadOp::eLoad : vk::AttachmentLoadOp::eDontCare,
        vk::AttachmentStoreOp::eStore);
    const vk::Extent2D extent = display.desc().extent;
    cmd.beginRendering(vk::RenderingInfo({}, vk::Rect2D({0, 0}, extent), 1, 0, color));
    vk_core::set_viewport_and_scissor(cmd, extent);
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline_);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 0, hdr_set, {});
    cmd.pushConstants<TonemapParams>(*layout_, vk::ShaderStageFlagBits::eFragment, 0, params);
    with_predicate(cmd, when, [&] { cmd.draw(3, 1, 0, 0); });
    cmd.endRendering();
}

vk_core::DescriptorSet TonemapPass::make_input(const vk_core::Image& source) const {
    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1)};
    vk_core::DescriptorSet set(ctx_, *set_layout_, sizes);
    const std::array images = {vk::DescriptorImageInfo(
        *sampler_, source.view(), executor::layout_for(graph::Use::kSampledFragment))};
    vk_core::write_sampled_images(ctx_, *set, images);
    return set;
}

}  // namespace monoplane::passes
