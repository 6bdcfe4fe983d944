#include "renderer/passes/forward/forward_pass.h"

#include <array>
#include <cstddef>
#include <vector>

#include "common/programming_error.h"
#include "common/result.h"
#include "renderer/executor/image_layouts.h"
#include "renderer/passes/forward/forward_shaders.h"

namespace monoplane::passes {
namespace {

void require_stereo_support(const vk_core::Context& ctx, plan::StereoPass stereo) {
    if (stereo == plan::StereoPass::kGeometryShader && !ctx.capabilities().geometry_shader) {
        throw UserError("device '" + ctx.device_info().name +
                        "' has no geometry shaders: single-pass stereo by primitive duplication "
                        "(stereo-gs, --stereo-pass gs) is not available; try multiview");
    }
    if (stereo == plan::StereoPass::kMultiview && !ctx.capabilities().multiview) {
        throw UserError("device '" + ctx.device_info().name +
                        "' has no VK_KHR_multiview: stereo-multiview (--stereo-pass multiview) is "
                        "not available; try gs");
    }
    const vk_core::DeviceCapabilities& caps = ctx.capabilities();
    if (stereo == plan::StereoPass::kInstanced &&
        !(caps.vertex_shader_layer && caps.shader_draw_parameters)) {
        throw UserError("device '" + ctx.device_info().name + "' " +
                        (caps.vertex_shader_layer ? "has no shaderDrawParameters"
                                                  : "cannot write gl_Layer from a vertex shader "
                                                    "(VK_EXT_shader_viewport_index_layer)") +
                        ": stereo-instanced (--stereo-pass instanced) is not available; try gs or "
                        "multiview");
    }
}

// Set 0: the view constants (read by the geometry shader too in the GS form) and the shadow map.
vk::raii::DescriptorSetLayout make_view_set_layout(const vk_core::Context& ctx,
                                                   plan::StereoPass stereo) {
    using Stage = vk::ShaderStageFlagBits;
    const vk::ShaderStageFlags constant_stages =
        Stage::eVertex | Stage::eFragment |
        (stereo == plan::StereoPass::kGeometryShader ? Stage::eGeometry : vk::ShaderStageFlags());
    const std::array bindings = {
        vk::DescriptorSetLayoutBinding(0, vk::DescriptorType::eUniformBuffer, 1, constant_stages),
        vk::DescriptorSetLayoutBinding(1, vk::DescriptorType::eCombinedImageSampler, 1,
                                       Stage::eFragment),
    };
    return vk::raii::DescriptorSetLayout(ctx.device(),
                                         vk::DescriptorSetLayoutCreateInfo({}, bindings));
}

// Set 1: the merged depth pyramid and the per-chunk routing words.
vk::raii::DescriptorSetLayout make_merged_depth_layout(const vk_core::Context& ctx) {
    using Stage = vk::ShaderStageFlagBits;
    const std::array bindings = {
        vk::DescriptorSetLayoutBinding(0, vk::DescriptorType::eCombinedImageSampler, 1,
                                       Stage::eFragment),
        vk::DescriptorSetLayoutBinding(1, vk::DescriptorType::eStorageBuffer, 1, Stage::eFragment),
    };
    return vk::raii::DescriptorSetLayout(ctx.device(),
                                         vk::DescriptorSetLayoutCreateInfo({}, bindings));
}

// The shader modules of one pipeline; an empty SPIR-V span (the geometry stage outside the GS
// form) leaves its stage out.
struct PipelineShaders {
    vk::raii::ShaderModule vertex, geometry, fragment;

    PipelineShaders(const vk_core::Context& ctx, std::span<const std::uint32_t> vertex_spirv,
                    std::span<const std::uint32_t> geometry_spirv,
                    std::span<const std::uint32_t> fragment_spirv)
        : vertex(module(ctx, vertex_spirv)),
          geometry(module(ctx, geometry_spirv)),
          fragment(module(ctx, fragment_spirv)) {}

    vk_core::GraphicsPipelineDesc in(vk_core::GraphicsPipelineDesc desc) const {
        desc.vertex = *vertex;
        desc.geometry = *geometry;
        desc.fragment = *fragment;
        return desc;
    }

  private:
    static vk::raii::ShaderModule module(const vk_core::Context& ctx,
                                         std::span<const std::uint32_t> spirv) {
        return spirv.empty() ? vk::raii::ShaderModule(nullptr) : vk_core::make_shader(ctx, spirv);
    }
};

// What every pipeline of a pass shares: its layout, and the attachments and views it draws into.
vk_core::GraphicsPipelineDesc shared_pipeline_desc(vk::PipelineLayout layout,
                                                   const ForwardConfig& config) {
    vk_core::GraphicsPipelineDesc desc;
    desc.layout = layout;
    desc.color_formats = {ForwardPass::kHdrFormat, ForwardPass::kLinearDepthFormat};
    if (config.velocity) desc.color_formats.push_back(ForwardPass::kVelocityFormat);
    desc.depth_format = ForwardPass::kDepthFormat;
    desc.samples = config.samples;
    desc.view_mask = config.stereo == plan::StereoPass::kMultiview ? 0b11u : 0u;
    return desc;
}

// The attachments of one forward pass; the vk::RenderingInfo recorded points into them.
struct Attachments {
    std::vector<vk::RenderingAttachmentInfo> colors;
    vk::RenderingAttachmentInfo depth;
};

vk::RenderingAttachmentInfo color_attachment(const vk_core::Image& image,
                                             const vk_core::Image* multisampled,
                                             vk::AttachmentLoadOp load,
                                             const vk::ClearColorValue& clear) {
    vk::RenderingAttachmentInfo info(image.view(), executor::layout_for(graph::Use::kColorWrite),
                                     {}, {}, {}, load, vk::AttachmentStoreOp::eStore,
                                     vk::ClearValue(clear));
    if (multisampled) {
        // Draw into the samples, keep only their average: the samples are never read again.
        info.setImageView(multisampled->view())
            .setResolveMode(vk::ResolveModeFlagBits::eAverage)
            .setResolveImageView(image.view())
            .setResolveImageLayout(executor::layout_for(graph::Use::kColorWrite))
            .setStoreOp(vk::AttachmentStoreOp::eDontCare);
    }
    return info;
}

Attachments make_attachments(const ForwardTargets& targets, bool velocity) {
    const MultisampleTargets* ms = targets.multisample;
    const vk::AttachmentLoadOp color_load =
        targets.clear_color ? vk::AttachmentLoadOp::eClear : vk::AttachmentLoadOp::eDontCare;
    Attachments attachments;
    attachments.colors = {
        color_attachment(targets.hdr, ms ? &ms->hdr : nullptr, color_load,
                         vk::ClearColorValue(0.0f, 0.0f, 0.0f, 1.0f)),
        color_attachment(
            targets.linear_depth, ms ? &ms->linear_depth : nullptr, color_load,
            vk::ClearColorValue(static_cast<float>(MONOPLANE_SKY_LINEAR_DEPTH), 0.0f, 0.0f, 0.0f)),
    };
    if (velocity) {
        attachments.colors.push_back(color_attachment(*targets.velocity, nullptr, color_load,
                                                      vk::ClearColorValue(0.0f, 0.0f, 0.0f, 0.0f)));
    }
    MONOPLANE_EXPECTS(ms != nullptr || targets.depth != nullptr);
    const vk_core::Image& depth_image = ms ? ms->depth : *targets.depth;
    attachments.depth = vk::RenderingAttachmentInfo(
        depth_image.view(), executor::layout_for(graph::Use::kDepthWrite), {}, {}, {},
        vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore,
        vk::ClearValue(vk::ClearDepthStencilValue(0.0f, 0)));  // reversed Z: far is 0
    return attachments;
}

// forward_shading.glsl's alpha constants: kAlphaMode (constant_id 1), kAlphaToCoverage (2).
struct AlphaSpecialization {
    std::int32_t mode = 0;  // scenes::AlphaMode
    vk::Bool32 to_coverage = VK_FALSE;
    std::array<vk::SpecializationMapEntry, 2> entries = {
        vk::SpecializationMapEntry(1, 0, sizeof(std::int32_t)),
        vk::SpecializationMapEntry(2, sizeof(std::int32_t), sizeof(vk::Bool32))};
    vk::SpecializationInfo info;

    AlphaSpecialization(scenes::AlphaMode alpha_mode, bool alpha_to_coverage)
        : mode(static_cast<std::int32_t>(alpha_mode)),
          to_coverage(alpha_to_coverage ? VK_TRUE : VK_FALSE),
          info(static_cast<std::uint32_t>(entries.size()), entries.data(),
               sizeof(std::int32_t) + sizeof(vk::Bool32), &mode) {}
    AlphaSpecialization(const AlphaSpecialization&) = delete;
    AlphaSpecialization& operator=(const AlphaSpecialization&) = delete;
};
static_assert(offsetof(AlphaSpecialization, to_coverage) == sizeof(std::int32_t));

// glTF's "over" with straight alpha into the HDR colour (attachment 0); the linear depth and the
// velocity (TAA) keep what lies behind, whose depth they describe.
vk::PipelineColorBlendAttachmentState over_blend() {
    using Factor = vk::BlendFactor;
    return vk::PipelineColorBlendAttachmentState(
        VK_TRUE, Factor::eSrcAlpha, Factor::eOneMinusSrcAlpha, vk::BlendOp::eAdd, Factor::eOne,
        Factor::eOneMinusSrcAlpha, vk::BlendOp::eAdd,
        vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
            vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA);
}

// Blended chunks: after everything opaque, depth tested and not written; the HDR colour blended,
// the other attachments left as they are (independentBlend). The description points into the
// specialization it holds: neither may move.
struct BlendedDesc {
    AlphaSpecialization blend{scenes::AlphaMode::kBlend, false};
    vk_core::GraphicsPipelineDesc desc;

    explicit BlendedDesc(const vk_core::GraphicsPipelineDesc& chunks) : desc(chunks) {
        desc.fragment_specialization = &blend.info;
        desc.depth_write = false;
        desc.depth_compare = vk::CompareOp::eGreater;
        desc.blend = over_blend();
        desc.color_write_masks = {over_blend().colorWriteMask, {}, {}};
    }
    BlendedDesc(const BlendedDesc&) = delete;
    BlendedDesc& operator=(const BlendedDesc&) = delete;
};

// Single-pass stereo draws both layers of the targets: every draw covers both views with
// multiview; otherwise the geometry shader picks the layer of each triangle it emits, or the
// vertex shader that of each instance.
vk::RenderingInfo rendering_info(vk::Extent2D area, plan::StereoPass stereo,
                                 const Attachments& attachments) {
    const bool layered =
        stereo == plan::StereoPass::kGeometryShader || stereo == plan::StereoPass::kInstanced;
    return vk::RenderingInfo()
        .setRenderArea(vk::Rect2D({0, 0}, area))
        .setLayerCount(layered ? 2 : 1)
        .setViewMask(stereo == plan::StereoPass::kMultiview ? 0b11u : 0u)
        .setColorAttachments(attachments.colors)
        .setPDepthAttachment(&attachments.depth);
}
}  // namespace

ForwardPass::ForwardPass(const vk_core::Context& ctx, vk::DescriptorSetLayout scene_textures_layout,
                         const ForwardConfig& config)
    : ctx_(ctx), config_(config) {
    require_stereo_support(ctx, config.stereo);
    set_layout_ = make_view_set_layout(ctx, config.stereo);
    merged_depth_layout_ = make_merged_depth_layout(ctx);
    // One layout for all pipelines; set 1 is bound only for the steps that read it.
    const std::array set_layouts = {*set_layout_, *merged_depth_layout_, scene_textures_layout};
    layout_ = vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, set_layouts));
    make_chunk_pipelines();
    if (config.programs == ForwardPrograms::kForward) make_fullscreen_pipelines();
}

// The same vertex shader in both pipelines, whose `precise` product rounds alike in both, so the
// pipeline after a pre-pass finds exactly the depth the pre-pass left.
ForwardPass::ChunkPipelines ForwardPass::ChunkPipelines::make(const vk_core::Context& ctx,
                                                              vk_core::GraphicsPipelineDesc desc) {
    ChunkPipelines pipelines;
    desc.depth_write = true;
    desc.depth_compare = vk::CompareOp::eGreaterOrEqual;
    pipelines.first = vk_core::make_graphics_pipeline(ctx, desc);
    desc.depth_write = false;
    desc.depth_compare = vk::CompareOp::eEqual;
    pipelines.after_prepass = vk_core::make_graphics_pipeline(ctx, desc);
    return pipelines;
}

void ForwardPass::make_chunk_pipelines() {
    const ForwardShaders shaders = forward_shaders(config_);
    // forward_vertex.glsl's kVertexWork (constant_id 0).
    const auto vertex_work = static_cast<std::int32_t>(config_.vertex_work);
    const vk::SpecializationMapEntry work_entry(0, 0, sizeof(vertex_work));
    const vk::SpecializationInfo vertex_specialization(1, &work_entry, sizeof(vertex_work),
                                                       &vertex_work);
    vk_core::GraphicsPipelineDesc chunks = shared_pipeline_desc(*layout_, config_);
    chunks.vertex_specialization = &vertex_specialization;
    chunks.vertex_bindings = SceneGeometry::vertex_bindings();
    chunks.vertex_attributes = SceneGeometry::vertex_attributes();

    const PipelineShaders shading(ctx_, shaders.vertex, shaders.geometry, shaders.forward);
    if (config_.programs == ForwardPrograms::kBlendedAfterComposite) {
        make_after_composite_pipeline(shaders, shading.in(chunks));
        return;
    }
    shading_pipelines_ = ChunkPipelines::make(ctx_, shading.in(chunks));
    // Depth only: no fragment shader and no colour written; nearer is greater, as always.
    vk_core::GraphicsPipelineDesc prepass = shading.in(chunks);
    prepass.fragment = nullptr;
    prepass.blend = vk::PipelineColorBlendAttachmentState().setColorWriteMask({});
    depth_prepass_pipeline_ = vk_core::make_graphics_pipeline(ctx_, prepass);

    const PipelineShaders routing(ctx_, shaders.show_routing_vertex, shaders.show_routing_geometry,
                                  shaders.show_routing);
    show_routing_pipelines_ = ChunkPipelines::make(ctx_, routing.in(chunks));
    make_alpha_pipelines(shaders, shading.in(chunks), prepass);
}

// Masked: the alpha test in the pre-pass and in the shading (alpha to coverage with MSAA).
void ForwardPass::make_masked_pipelines(const vk_core::GraphicsPipelineDesc& chunks,
                                        const vk_core::GraphicsPipelineDesc& prepass,
                                        std::span<const std::uint32_t> masked_depth_spirv) {
    const bool multisampled = config_.samples != vk::SampleCountFlagBits::e1;
    const vk::raii::ShaderModule masked_depth = vk_core::make_shader(ctx_, masked_depth_spirv);
    vk_core::GraphicsPipelineDesc masked_prepass = prepass;
    masked_prepass.fragment = *masked_depth;
    masked_prepass.alpha_to_coverage = multisampled;
    masked_prepass_pipeline_ = vk_core::make_graphics_pipeline(ctx_, masked_prepass);
    const AlphaSpecialization mask(scenes::AlphaMode::kMask, multisampled);
    vk_core::GraphicsPipelineDesc masked = chunks;
    masked.fragment_specialization = &mask.info;
    masked.alpha_to_coverage = multisampled;
    masked_pipelines_ = ChunkPipelines::make(ctx_, masked);
}

void ForwardPass::make_alpha_pipelines(const ForwardShaders& shaders,
                                       const vk_core::GraphicsPipelineDesc& chunks,
                                       const vk_core::GraphicsPipelineDesc& prepass) {
    if (config_.masked_chunks) make_masked_pipelines(chunks, prepass, shaders.masked_depth);
    if (!config_.blended_chunks) return;
    // The blended chunks leave the other attachments as they are (BlendedDesc).
    if (!ctx_.capabilities().independent_blend) {
        throw UserError("device '" + ctx_.device_info().name +
                        "' has no independentBlend: it cannot draw alphaMode BLEND materials, "
                        "which blend the colour and leave the linear depth behind them");
    }
    const BlendedDesc blended(chunks);
    blended_pipeline_ = vk_core::make_graphics_pipeline(ctx_, blended.desc);
}

void ForwardPass::make_after_composite_pipeline(const ForwardShaders& shaders,
                                                const vk_core::GraphicsPipelineDesc& chunks) {
    // Hybrid's after the composite, one eye per pass (hybrid has no MSAA): HDR colour only, no
    // depth buffer (the shader tests the composite's linear depth), clamped rather than clipped
    // at the eyes' far plane m.
    MONOPLANE_EXPECTS(config_.blended_chunks && config_.samples == vk::SampleCountFlagBits::e1 &&
                      config_.stereo == plan::StereoPass::kTwoPasses);
    if (!ctx_.capabilities().depth_clamp) {
        throw UserError("device '" + ctx_.device_info().name +
                        "' cannot clamp depth (depthClamp): hybrid cannot draw the blended "
                        "surfaces nearer than the mono plane after the composite; use --mode "
                        "stereo for scenes with alphaMode BLEND materials");
    }
    const BlendedDesc blended(chunks);
    const vk::raii::ShaderModule after = vk_core::make_shader(ctx_, shaders.after_composite);
    vk_core::GraphicsPipelineDesc after_composite = blended.desc;
    after_composite.fragment = *after;
    after_composite.color_formats = {kHdrFormat};
    after_composite.color_write_masks.clear();
    after_composite.depth_format = vk::Format::eUndefined;
    after_composite.depth_test = false;
    after_composite.depth_write = false;
    after_composite.depth_clamp = true;
    after_composite_pipeline_ = vk_core::make_graphics_pipeline(ctx_, after_composite);
}

void ForwardPass::make_fullscreen_pipelines() {
    const ForwardShaders shaders = forward_shaders(config_);
    // The sky covers only pixels still at the cleared far depth (0 with reversed Z).
    const PipelineShaders sky_shaders(ctx_, shaders.sky_vertex, shaders.sky_geometry, shaders.sky);
    vk_core::GraphicsPipelineDesc sky = sky_shaders.in(shared_pipeline_desc(*layout_, config_));
    sky.cull = vk::CullModeFlagBits::eNone;
    sky.depth_write = false;
    sky.depth_compare = vk::CompareOp::eEqual;
    sky_pipeline_ = vk_core::make_graphics_pipeline(ctx_, sky);
    if (config_.stereo != plan::StereoPass::kTwoPasses) return;

    // Every pixel at once, whatever the depth; only the hidden ones survive the discard.
    const vk::raii::ShaderModule mask_frag = vk_core::make_shader(ctx_, shaders.mask_hidden);
    vk_core::GraphicsPipelineDesc mask = sky;
    mask.geometry = nullptr;
    mask.fragment = *mask_frag;
    mask.depth_write = true;
    mask.depth_compare = vk::CompareOp::eAlways;
    mask.blend = vk::PipelineColorBlendAttachmentState().setColorWriteMask({});
    mask_hidden_pipeline_ = vk_core::make_graphics_pipeline(ctx_, mask);
}

void ForwardPass::record(const vk::raii::CommandBuffer& cmd, const ForwardTargets& targets,
                         vk::DescriptorSet view_set, vk::DescriptorSet merged_depth_set,
                         const SceneGeometry& geometry, const SceneTextures& textures,
                         const ChunkDraws& chunks, std::span<const ForwardDraw> steps) const {
    MONOPLANE_EXPECTS((config_.samples != vk::SampleCountFlagBits::e1) ==
                      (targets.multisample != nullptr));
    MONOPLANE_EXPECTS(!config_.velocity || targets.velocity != nullptr);
    MONOPLANE_EXPECTS(targets.hdr.desc().layers ==
                      (config_.stereo == plan::StereoPass::kTwoPasses ? 1u : 2u));
    const Attachments attachments = make_attachments(targets, config_.velocity);
    cmd.beginRendering(rendering_info(targets.area, config_.stereo, attachments));
    vk_core::set_viewport_and_scissor(cmd, targets.area);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 0, view_set, {});
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 2, textures.set(), {});
    geometry.bind(cmd);
    // Whether a depth pre-pass precedes the chunk steps: they then test for its depths.
    bool prepassed = false;
    for (const ForwardDraw& draw : steps) {
        with_predicate(cmd, draw.when,
                       [&] { record_step(cmd, draw.step, prepassed, merged_depth_set, chunks); });
        // A predicated pre-pass runs under the same predicate as the chunk steps after it.
        if (draw.step == plan::DrawStep::kDepthPrepass) prepassed = true;
    }
    cmd.endRendering();
}

void ForwardPass::record_step(const vk::raii::CommandBuffer& cmd, plan::DrawStep step,
                              bool prepassed, vk::DescriptorSet merged_depth_set,
                              const ChunkDraws& chunks) const {
    switch (step) {
        case plan::DrawStep::kMaskHidden:
            MONOPLANE_EXPECTS(*mask_hidden_pipeline_);
            cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 1, merged_depth_set,
                                   {});
            cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *mask_hidden_pipeline_);
            cmd.draw(3, 1, 0, 0);
            break;
        case plan::DrawStep::kDepthPrepass:
            cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *depth_prepass_pipeline_);
            chunks.opaque.record(cmd);
            if (chunks.masked.max_draws == 0) break;
            cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *masked_prepass_pipeline_);
            chunks.masked.record(cmd);
            break;
        case plan::DrawStep::kChunks:
            cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, shading_pipelines_.pick(prepassed));
            chunks.opaque.record(cmd);
            if (chunks.masked.max_draws == 0) break;
            cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, masked_pipelines_.pick(prepassed));
            chunks.masked.record(cmd);
            break;
        case plan::DrawStep::kChunksShowRouting:
            // Masked chunks drawn whole: the debug view shows routing, not surfaces.
            cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 1, merged_depth_set,
                                   {});
            cmd.bindPipeline(vk::PipelineBindPoint::eGraphics,
                             show_routing_pipelines_.pick(prepassed));
            chunks.opaque.record(cmd);
            chunks.masked.record(cmd);
            break;
        case plan::DrawStep::kBlended:
            cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *blended_pipeline_);
            chunks.blended.record(cmd);
            break;
        case plan::DrawStep::kSky: {
            // Instanced stereo draws the full-screen triangle once per eye, as it does each chunk.
            const std::uint32_t instances = config_.stereo == plan::StereoPass::kInstanced ? 2 : 1;
            cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *sky_pipeline_);
            cmd.draw(3, instances, 0, 0);
            break;
        }
    }
}

vk_core::DescriptorSet ForwardPass::make_view_set() const {
    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, 1),
                              vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1)};
    return vk_core::DescriptorSet(ctx_, *set_layout_, sizes);
}

void ForwardPass::write_view_set(vk::DescriptorSet set, const vk_core::Buffer& constants,
                                 vk::ImageView shadow, vk::Sampler shadow_sampler) const {
    const vk::DescriptorBufferInfo constants_info(constants.handle(), 0, VK_WHOLE_SIZE);
    const vk::DescriptorImageInfo shadow_info(shadow_sampler, shadow,
                                              executor::layout_for(graph::Use::kSampledFragment));
    const std::array writes = {
        vk::WriteDescriptorSet(set, 0, 0, vk::DescriptorType::eUniformBuffer, {}, constants_info),
        vk::WriteDescriptorSet(set, 1, 0, vk::DescriptorType::eCombinedImageSampler, shadow_info),
    };
    ctx_.device().updateDescriptorSets(writes, {});
}

void ForwardPass::record_after_composite(const vk::raii::CommandBuffer& cmd,
                                         const AfterCompositeTargets& targets,
                                         vk::DescriptorSet view_set,
                                         vk::DescriptorSet composite_depth_set,
                                         const SceneGeometry& geometry,
                                         const SceneTextures& textures,
                                         const IndirectDraws& blended) const {
    MONOPLANE_EXPECTS(*after_composite_pipeline_);
    const vk::RenderingAttachmentInfo color(
        targets.hdr.view(), executor::layout_for(graph::Use::kColorBlend), {}, {}, {},
        vk::AttachmentLoadOp::eLoad, vk::AttachmentStoreOp::eStore, {});
    cmd.beginRendering(vk::RenderingInfo()
                           .setRenderArea(vk::Rect2D({0, 0}, targets.area))
                           .setLayerCount(1)
                           .setColorAttachments(color));
    vk_core::set_viewport_and_scissor(cmd, targets.area);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 0, view_set, {});
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 1, composite_depth_set, {});
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 2, textures.set(), {});
    geometry.bind(cmd);
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *after_composite_pipeline_);
    blended.record(cmd);
    cmd.endRendering();
}

void ForwardPass::write_composite_depth(vk::DescriptorSet set, vk::ImageView linear_depth,
                                        vk::Sampler nearest) const {
    const vk::DescriptorImageInfo depth(nearest, linear_depth,
                                        executor::layout_for(graph::Use::kSampledFragment));
    ctx_.device().updateDescriptorSets(
        vk::WriteDescriptorSet(set, 0, 0, vk::DescriptorType::eCombinedImageSampler, depth), {});
}

vk_core::DescriptorSet ForwardPass::make_merged_depth_set() const {
    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1),
                              vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 1)};
    return vk_core::DescriptorSet(ctx_, *merged_depth_layout_, sizes);
}

void ForwardPass::write_merged_depth(vk::DescriptorSet set, vk::ImageView pyramid,
                                     vk::Sampler nearest, vk::Buffer routing) const {
    const vk::DescriptorImageInfo merged(nearest, pyramid,
                                         executor::layout_for(graph::Use::kGeneralSampled));
    const vk::DescriptorBufferInfo routing_info(routing, 0, VK_WHOLE_SIZE);
    const std::array writes = {
        vk::WriteDescriptorSet(set, 0, 0, vk::DescriptorType::eCombinedImageSampler, merged),
        vk::WriteDescriptorSet(set, 1, 0, vk::DescriptorType::eStorageBuffer, {}, routing_info),
    };
    ctx_.device().updateDescriptorSets(writes, {});
}

}  // namespace monoplane::passes
