#include "renderer/passes/shared/fullscreen_pass.h"

#include "renderer/executor/image_layouts.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {
namespace {
const std::uint32_t kFullscreenVert[] = {
#include "fullscreen.vert.spv.inc"
};
}  // namespace

vk::raii::ShaderModule make_fullscreen_vertex_shader(const vk_core::Context& ctx) {
    return vk_core::make_shader(ctx, kFullscreenVert);
}

vk::raii::Pipeline make_fullscreen_pipeline(const vk_core::Context& ctx, vk::PipelineLayout layout,
                                            std::span<const std::uint32_t> fragment,
                                            vk::Format format) {
    const vk::raii::ShaderModule vert = make_fullscreen_vertex_shader(ctx);
    const vk::raii::ShaderModule frag = vk_core::make_shader(ctx, fragment);
    vk_core::GraphicsPipelineDesc desc;
    desc.layout = layout;
    desc.vertex = *vert;
    desc.fragment = *frag;
    desc.color_formats = {format};
    desc.cull = vk::CullModeFlagBits::eNone;
    desc.depth_test = false;
    desc.depth_write = false;
    return vk_core::make_graphics_pipeline(ctx, desc);
}

void record_fullscreen(const vk::raii::CommandBuffer& cmd, const vk_core::Image& target,
                       vk::Pipeline pipeline, vk::PipelineLayout layout, vk::DescriptorSet inputs,
                       std::span<const std::byte> push, const std::optional<Predicate>& when) {
    const vk::RenderingAttachmentInfo color(
        target.view(), executor::layout_for(graph::Use::kColorWrite), {}, {}, {},
        when ? vk::AttachmentLoadOp::eLoad : vk::AttachmentLoadOp::eDontCare,
        vk::AttachmentStoreOp::eStore);
    const vk::Extent2D extent = target.desc().extent;
    cmd.beginRendering(vk::RenderingInfo({}, vk::Rect2D({0, 0}, extent), 1, 0, color));
    vk_core::set_viewport_and_scissor(cmd, extent);
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, pipeline);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, layout, 0, inputs, {});
    if (!push.empty()) {
        cmd.pushConstants<std::byte>(layout, vk::ShaderStageFlagBits::eFragment, 0, push);
    }
    with_predicate(cmd, when, [&] { cmd.draw(3, 1, 0, 0); });
    cmd.endRendering();
}

}  // namespace monoplane::passes
