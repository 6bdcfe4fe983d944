#include "renderer/passes/composite/composite_pass.h"

#include <array>
#include <vector>

#include "common/programming_error.h"
#include "renderer/executor/image_layouts.h"
#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shared/fullscreen_pass.h"

namespace monoplane::passes {
namespace {
const std::uint32_t kCompositeFrag[] = {
#include "composite.frag.spv.inc"
};
const std::uint32_t kCompositeVelocityFrag[] = {
#include "composite_velocity.frag.spv.inc"
};
const std::uint32_t kCompositeDisplayFrag[] = {
#include "composite_display.frag.spv.inc"
};
const std::uint32_t kCompositeNearFrag[] = {
#include "composite_near.frag.spv.inc"
};

// The shader's push-constant block, std430.
struct CompositePush {
    glm::mat4 eye_to_mono;
    glm::vec4 uv_limits;
    glm::vec4 eye_extent_mode;
    glm::vec4 offset_exposure;
    glm::vec4 velocity_scale;
};
static_assert(sizeof(CompositePush) == 128, "must match composite_push.glsl");

constexpr vk::ColorComponentFlags kAllChannels =
    vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
    vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA;

// Begins rendering into `colors` over the eye's depth, read only (the composite's depth test
// against the cleared far value), and sets the viewport to the whole extent.
void begin_over_eye_depth(const vk::raii::CommandBuffer& cmd,
                          vk::ArrayProxy<const vk::RenderingAttachmentInfo> colors,
                          const vk_core::Image& eye_depth, vk::Extent2D extent) {
    const vk::RenderingAttachmentInfo depth(
        eye_depth.view(), executor::layout_for(graph::Use::kDepthTest), {}, {}, {},
        vk::AttachmentLoadOp::eLoad, vk::AttachmentStoreOp::eStore);
    cmd.beginRendering(vk::RenderingInfo()
                           .setRenderArea(vk::Rect2D({0, 0}, extent))
                           .setLayerCount(1)
                           .setColorAttachments(colors)
                           .setPDepthAttachment(&depth));
    vk_core::set_viewport_and_scissor(cmd, extent);
}

}  // namespace

CompositePass::CompositePass(const vk_core::Context& ctx, bool velocity, bool display)
    : ctx_(ctx),
      velocity_(velocity),
      bilinear_(vk_core::make_clamped_sampler(ctx, vk::Filter::eLinear)),
      nearest_(vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest)) {
    // Binding 2 (C's velocity) exists only with velocity: every binding of a set must be written
    // before it is bound, and lavapipe reads every one.
    std::vector<vk::DescriptorSetLayoutBinding> bindings;
    for (std::uint32_t binding = 0; binding < (velocity ? 3u : 2u); ++binding) {
        bindings.emplace_back(binding, vk::DescriptorType::eCombinedImageSampler, 1,
                              vk::ShaderStageFlagBits::eFragment);
    }
    set_layout_ = vk::raii::DescriptorSetLayout(ctx.device(),
                                                vk::DescriptorSetLayoutCreateInfo({}, bindings));
    const vk::DescriptorSetLayout set_layout = *set_layout_;
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0, sizeof(CompositePush));
    layout_ =
        vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, set_layout, push));
    const vk::raii::ShaderModule vert = make_fullscreen_vertex_shader(ctx);
    const vk::raii::ShaderModule frag = velocity ? vk_core::make_shader(ctx, kCompositeVelocityFrag)
                                                 : vk_core::make_shader(ctx, kCompositeFrag);
    vk_core::GraphicsPipelineDesc desc;
    desc.layout = *layout_;
    desc.vertex = *vert;
    desc.fragment = *frag;
    desc.color_formats = {ForwardPass::kHdrFormat, ForwardPass::kLinearDepthFormat};
    if (velocity) desc.color_formats.push_back(ForwardPass::kVelocityFormat);
    desc.depth_format = ForwardPass::kDepthFormat;
    desc.cull = vk::CullModeFlagBits::eNone;
    desc.depth_write = false;
    // The full-screen triangle lies at depth 0, the eye's far plane (m): equal only where the
    // eye drew nothing.
    desc.depth_compare = vk::CompareOp::eEqual;
    behind_near_content_ = vk_core::make_graphics_pipeline(ctx, desc);
    desc.depth_test = false;
    everywhere_ = vk_core::make_graphics_pipeline(ctx, desc);
    MONOPLANE_EXPECTS(!(velocity && display));
    if (display) make_display_pipelines(desc);
}

void CompositePass::make_display_pipelines(const vk_core::GraphicsPipelineDesc& composite_desc) {
    const vk::DescriptorSetLayoutBinding binding(0, vk::DescriptorType::eCombinedImageSampler, 1,
                                                 vk::ShaderStageFlagBits::eFragment);
    eye_set_layout_ = vk::raii::DescriptorSetLayout(ctx_.device(),
                                                    vk::DescriptorSetLayoutCreateInfo({}, binding));
    const std::array set_layouts = {*set_layout_, *eye_set_layout_};
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0, sizeof(CompositePush));
    display_layout_ = vk::raii::PipelineLayout(ctx_.device(),
                                               vk::PipelineLayoutCreateInfo({}, set_layouts, push));
    const vk::raii::ShaderModule composite = vk_core::make_shader(ctx_, kCompositeDisplayFrag);
    const vk::raii::ShaderModule near = vk_core::make_shader(ctx_, kCompositeNearFrag);
    vk_core::GraphicsPipelineDesc desc = composite_desc;
    desc.layout = *display_layout_;
    desc.fragment = *composite;
    desc.color_formats = {kDisplayFormat, ForwardPass::kLinearDepthFormat};
    desc.depth_test = true;
    display_behind_near_content_ = vk_core::make_graphics_pipeline(ctx_, desc);
    desc.depth_test = false;
    display_everywhere_ = vk_core::make_graphics_pipeline(ctx_, desc);
    // The complement of the composite's test: every pixel the eye drew. Its linear depth is the
    // eye's own and stays; only the display image is written.
    desc.fragment = *near;
    desc.depth_test = true;
    desc.depth_compare = vk::CompareOp::eNotEqual;
    desc.color_write_masks = {kAllChannels, vk::ColorComponentFlags()};
    near_display_ = vk_core::make_graphics_pipeline(ctx_, desc);
}

void CompositePass::push(const vk::raii::CommandBuffer& cmd, vk::PipelineLayout layout,
                         vk::Extent2D extent, const CompositeParams& params, float exposure) const {
    const glm::vec2 half_texel = 0.5f / params.mono_allocation;
    const CompositePush block{
        params.eye_to_mono,
        glm::vec4(params.uv_scale, half_texel),
        glm::vec4(static_cast<float>(extent.width), static_cast<float>(extent.height),
                  static_cast<float>(params.mapping), params.tint),
        glm::vec4(static_cast<float>(params.pixel_offset.x),
                  static_cast<float>(params.pixel_offset.y), exposure, 0.0f),
        glm::vec4(params.velocity_scale, 0.0f, 0.0f),
    };
    cmd.pushConstants<CompositePush>(layout, vk::ShaderStageFlagBits::eFragment, 0, block);
}

void CompositePass::record(const vk::raii::CommandBuffer& cmd, const CompositeTargets& targets,
                           vk::DescriptorSet mono_set, const CompositeParams& params) const {
    const vk::Extent2D extent = targets.hdr.desc().extent;
    std::vector<vk::RenderingAttachmentInfo> colors;
    std::vector<const vk_core::Image*> written = {&targets.hdr, &targets.linear_depth};
    MONOPLANE_EXPECTS(!velocity_ || targets.velocity != nullptr);
    if (velocity_) written.push_back(targets.velocity);
    for (const vk_core::Image* image : written) {
        colors.push_back(vk::RenderingAttachmentInfo()
                             .setImageView(image->view())
                             .setImageLayout(executor::layout_for(graph::Use::kColorBlend))
                             .setLoadOp(vk::AttachmentLoadOp::eLoad)
                             .setStoreOp(vk::AttachmentStoreOp::eStore));
    }
    begin_over_eye_depth(cmd, colors, targets.depth, extent);
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics,
                     params.cover_all_pixels ? *everywhere_ : *behind_near_content_);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 0, mono_set, {});
    push(cmd, *layout_, extent, params, 0.0f);
    with_predicate(cmd, params.when, [&] { cmd.draw(3, 1, 0, 0); });
    cmd.endRendering();
}

void CompositePass::record_display(const vk::raii::CommandBuffer& cmd,
                                   const CompositeDisplayTargets& targets,
                                   vk::DescriptorSet mono_set, vk::DescriptorSet eye_set,
                                   const CompositeParams& params,
                                   const TonemapParams& tonemap) const {
    MONOPLANE_EXPECTS(writes_display());
    const vk::Extent2D extent = targets.display.desc().extent;
    // Every pixel is written by one of the two draws: the display image's contents need no load.
    const std::array colors = {
        vk::RenderingAttachmentInfo(targets.display.view(),
                                    executor::layout_for(graph::Use::kColorWrite),
                                    vk::ResolveModeFlagBits::eNone, nullptr, {},
                                    vk::AttachmentLoadOp::eDontCare, vk::AttachmentStoreOp::eStore),
        vk::RenderingAttachmentInfo(targets.linear_depth.view(),
                                    executor::layout_for(graph::Use::kColorBlend),
                                    vk::ResolveModeFlagBits::eNone, nullptr, {},
                                    vk::AttachmentLoadOp::eLoad, vk::AttachmentStoreOp::eStore)};
    begin_over_eye_depth(cmd, colors, targets.depth, extent);
    const std::array sets = {mono_set, eye_set};
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *display_layout_, 0, sets, {});
    push(cmd, *display_layout_, extent, params, tonemap.exposure);
    with_predicate(cmd, params.when, [&] {
        cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, params.cover_all_pixels
                                                               ? *display_everywhere_
                                                               : *display_behind_near_content_);
        cmd.draw(3, 1, 0, 0);
        if (params.cover_all_pixels) return;
        cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *near_display_);
        cmd.draw(3, 1, 0, 0);
    });
    cmd.endRendering();
}

vk_core::DescriptorSet CompositePass::make_eye_input(const vk_core::Image& eye_hdr) const {
    MONOPLANE_EXPECTS(writes_display());
    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1)};
    vk_core::DescriptorSet set(ctx_, *eye_set_layout_, sizes);
    const std::array images = {vk::DescriptorImageInfo(
        *nearest_, eye_hdr.view(), executor::layout_for(graph::Use::kSampledFragment))};
    vk_core::write_sampled_images(ctx_, *set, images);
    return set;
}

vk_core::DescriptorSet CompositePass::make_source(const vk_core::Image& mono_hdr,
                                                  const vk_core::Image& mono_linear_depth,
                                                  const vk_core::Image* mono_velocity) const {
    MONOPLANE_EXPECTS(velocity_ == (mono_velocity != nullptr));
    const std::uint32_t count = velocity_ ? 3u : 2u;
    const std::array sizes = {
        vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, count)};
    vk_core::DescriptorSet set(ctx_, *set_layout_, sizes);
    const auto read_only = executor::layout_for(graph::Use::kSampledFragment);
    std::vector images = {
        vk::DescriptorImageInfo(*bilinear_, mono_hdr.view(), read_only),
        vk::DescriptorImageInfo(*nearest_, mono_linear_depth.view(), read_only),
    };
    if (mono_velocity) images.emplace_back(*nearest_, mono_velocity->view(), read_only);
    vk_core::write_sampled_images(ctx_, *set, images);
    return set;
}

}  // namespace monoplane::passes
