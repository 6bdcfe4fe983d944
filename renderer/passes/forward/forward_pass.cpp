#include "renderer/passes/forward/forward_pass.h"

#include <array>
#include <cassert>
#include <vector>

#include "common/result.h"

namespace monoplane::passes {
namespace {
const std::uint32_t kForwardVert[] = {
#include "forward.vert.spv.inc"
};
const std::uint32_t kForwardFrag[] = {
#include "forward.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingVert[] = {
#include "forward_show_routing.vert.spv.inc"
};
const std::uint32_t kForwardShowRoutingFrag[] = {
#include "forward_show_routing.frag.spv.inc"
};
const std::uint32_t kFullscreenVert[] = {
#include "fullscreen.vert.spv.inc"
};
const std::uint32_t kSkyFrag[] = {
#include "sky.frag.spv.inc"
};
const std::uint32_t kForwardVelocityFrag[] = {
#include "forward_velocity.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingVelocityFrag[] = {
#include "forward_show_routing_velocity.frag.spv.inc"
};
const std::uint32_t kSkyVelocityFrag[] = {
#include "sky_velocity.frag.spv.inc"
};
const std::uint32_t kMaskHiddenFrag[] = {
#include "mask_hidden.frag.spv.inc"
};

const std::uint32_t kForwardMultiviewVert[] = {
#include "forward_multiview.vert.spv.inc"
};
const std::uint32_t kForwardShowRoutingMultiviewVert[] = {
#include "forward_show_routing_multiview.vert.spv.inc"
};
const std::uint32_t kForwardMultiviewFrag[] = {
#include "forward_multiview.frag.spv.inc"
};
const std::uint32_t kForwardVelocityMultiviewFrag[] = {
#include "forward_velocity_multiview.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingMultiviewFrag[] = {
#include "forward_show_routing_multiview.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingVelocityMultiviewFrag[] = {
#include "forward_show_routing_velocity_multiview.frag.spv.inc"
};
const std::uint32_t kSkyMultiviewFrag[] = {
#include "sky_multiview.frag.spv.inc"
};
const std::uint32_t kSkyVelocityMultiviewFrag[] = {
#include "sky_velocity_multiview.frag.spv.inc"
};
const std::uint32_t kForwardGsVert[] = {
#include "forward_gs.vert.spv.inc"
};
const std::uint32_t kForwardShowRoutingGsVert[] = {
#include "forward_show_routing_gs.vert.spv.inc"
};
const std::uint32_t kForwardGsFrag[] = {
#include "forward_gs.frag.spv.inc"
};
const std::uint32_t kForwardVelocityGsFrag[] = {
#include "forward_velocity_gs.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingGsFrag[] = {
#include "forward_show_routing_gs.frag.spv.inc"
};
const std::uint32_t kForwardShowRoutingVelocityGsFrag[] = {
#include "forward_show_routing_velocity_gs.frag.spv.inc"
};
const std::uint32_t kSkyGsFrag[] = {
#include "sky_gs.frag.spv.inc"
};
const std::uint32_t kSkyVelocityGsFrag[] = {
#include "sky_velocity_gs.frag.spv.inc"
};
const std::uint32_t kStereoDuplicateGeom[] = {
#include "stereo_duplicate.geom.spv.inc"
};
const std::uint32_t kStereoDuplicateShowRoutingGeom[] = {
#include "stereo_duplicate_show_routing.geom.spv.inc"
};
const std::uint32_t kStereoDuplicateSkyGeom[] = {
#include "stereo_duplicate_sky.geom.spv.inc"
};

// The shaders of one configuration.
struct ShaderSet {
    std::span<const std::uint32_t> vertex, show_routing_vertex;
    std::span<const std::uint32_t> geometry, show_routing_geometry, sky_geometry;  // GS form only
    std::span<const std::uint32_t> forward, show_routing, sky;
};

ShaderSet shader_set(const ForwardConfig& config) {
    const bool v = config.velocity;
    switch (config.stereo) {
        case StereoDuplication::kMultiview:
            return {
                kForwardMultiviewVert,
                kForwardShowRoutingMultiviewVert,
                {},
                {},
                {},
                v ? std::span<const std::uint32_t>(kForwardVelocityMultiviewFrag)
                  : kForwardMultiviewFrag,
                v ? std::span<const std::uint32_t>(kForwardShowRoutingVelocityMultiviewFrag)
                  : kForwardShowRoutingMultiviewFrag,
                v ? std::span<const std::uint32_t>(kSkyVelocityMultiviewFrag) : kSkyMultiviewFrag};
        case StereoDuplication::kGeometryShader:
            return {kForwardGsVert,
                    kForwardShowRoutingGsVert,
                    kStereoDuplicateGeom,
                    kStereoDuplicateShowRoutingGeom,
                    kStereoDuplicateSkyGeom,
                    v ? std::span<const std::uint32_t>(kForwardVelocityGsFrag) : kForwardGsFrag,
                    v ? std::span<const std::uint32_t>(kForwardShowRoutingVelocityGsFrag)
                      : kForwardShowRoutingGsFrag,
                    v ? std::span<const std::uint32_t>(kSkyVelocityGsFrag) : kSkyGsFrag};
        case StereoDuplication::kNone:
            break;
    }
    if (v) {
        return {kForwardVert,
                kForwardShowRoutingVert,
                {},
                {},
                {},
                kForwardVelocityFrag,
                kForwardShowRoutingVelocityFrag,
                kSkyVelocityFrag};
    }
    return {kForwardVert, kForwardShowRoutingVert, {},      {}, {},
            kForwardFrag, kForwardShowRoutingFrag, kSkyFrag};
}
}  // namespace

ForwardPass::ForwardPass(const vk_core::Context& ctx, vk::DescriptorSetLayout scene_textures_layout,
                         const ForwardConfig& config)
    : ctx_(ctx), config_(config) {
    using Stage = vk::ShaderStageFlagBits;
    const bool gs = config.stereo == StereoDuplication::kGeometryShader;
    if (gs && !ctx.capabilities().geometry_shader) {
        throw UserError("device '" + ctx.device_info().name +
                        "' has no geometry shaders: single-pass stereo by primitive duplication "
                        "(stereo-gs, --stereo-pass gs) is not available; try multiview");
    }
    if (config.stereo == StereoDuplication::kMultiview && !ctx.capabilities().multiview) {
        throw UserError("device '" + ctx.device_info().name +
                        "' has no VK_KHR_multiview: stereo-multiview (--stereo-pass multiview) is "
                        "not available; try gs");
    }
    const vk::ShaderStageFlags constant_stages =
        Stage::eVertex | Stage::eFragment | (gs ? Stage::eGeometry : vk::ShaderStageFlags());
    const std::array bindings = {
        vk::DescriptorSetLayoutBinding(0, vk::DescriptorType::eUniformBuffer, 1, constant_stages),
        vk::DescriptorSetLayoutBinding(1, vk::DescriptorType::eCombinedImageSampler, 1,
                                       Stage::eFragment),
    };
    set_layout_ = vk::raii::DescriptorSetLayout(ctx.device(),
                                                vk::DescriptorSetLayoutCreateInfo({}, bindings));
    const std::array set1_bindings = {
        vk::DescriptorSetLayoutBinding(0, vk::DescriptorType::eCombinedImageSampler, 1,
                                       Stage::eFragment),
        vk::DescriptorSetLayoutBinding(1, vk::DescriptorType::eStorageBuffer, 1, Stage::eFragment),
    };
    merged_depth_layout_ = vk::raii::DescriptorSetLayout(
        ctx.device(), vk::DescriptorSetLayoutCreateInfo({}, set1_bindings));
    // One layout for all pipelines; set 1 is bound only for the steps that read it.
    const std::array set_layouts = {*set_layout_, *merged_depth_layout_, scene_textures_layout};
    layout_ = vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, set_layouts));

    const ShaderSet shaders = shader_set(config);
    auto module = [&](std::span<const std::uint32_t> spirv) {
        return spirv.empty() ? vk::raii::ShaderModule(nullptr) : vk_core::make_shader(ctx, spirv);
    };
    std::vector<vk::Format> color_formats = {kHdrFormat, kLinearDepthFormat};
    if (config.velocity) color_formats.push_back(kVelocityFormat);
    const std::uint32_t view_mask = config.stereo == StereoDuplication::kMultiview ? 0b11u : 0u;
    // forward_vertex.glsl's kVertexWork (constant_id 0).
    const auto vertex_work = static_cast<std::int32_t>(config.vertex_work);
    const vk::SpecializationMapEntry work_entry(0, 0, sizeof(vertex_work));
    const vk::SpecializationInfo vertex_specialization(1, &work_entry, sizeof(vertex_work),
                                                       &vertex_work);
    const vk::raii::ShaderModule forward_vert = module(shaders.vertex);
    const vk::raii::ShaderModule forward_geom = module(shaders.geometry);
    const vk::raii::ShaderModule forward_frag = module(shaders.forward);
    vk_core::GraphicsPipelineDesc geometry;
    geometry.layout = *layout_;
    geometry.vertex = *forward_vert;
    geometry.vertex_specialization = &vertex_specialization;
    geometry.geometry = *forward_geom;
    geometry.fragment = *forward_frag;
    geometry.vertex_bindings = SceneGeometry::vertex_bindings();
    geometry.vertex_attributes = SceneGeometry::vertex_attributes();
    geometry.color_formats = color_formats;
    geometry.depth_format = kDepthFormat;
    geometry.samples = config.samples;
    geometry.view_mask = view_mask;
    // Each chunk pipeline twice: testing and writing depth, and after a depth pre-pass, testing
    // for the depth the pre-pass left (the same vertex shader, whose `precise` product rounds
    // alike in both pipelines).
    auto make_chunk_pipelines = [&](vk::raii::Pipeline& first, vk::raii::Pipeline& after_prepass) {
        geometry.depth_write = true;
        geometry.depth_compare = vk::CompareOp::eGreaterOrEqual;
        first = vk_core::make_graphics_pipeline(ctx, geometry);
        geometry.depth_write = false;
        geometry.depth_compare = vk::CompareOp::eEqual;
        after_prepass = vk_core::make_graphics_pipeline(ctx, geometry);
        geometry.depth_write = true;
        geometry.depth_compare = vk::CompareOp::eGreaterOrEqual;
    };
    make_chunk_pipelines(geometry_pipeline_, geometry_after_prepass_pipeline_);
    // Depth only: no fragment shader and no colour written; nearer is greater, as always.
    vk_core::GraphicsPipelineDesc prepass = geometry;
    prepass.fragment = nullptr;
    prepass.blend = vk::PipelineColorBlendAttachmentState().setColorWriteMask({});
    depth_prepass_pipeline_ = vk_core::make_graphics_pipeline(ctx, prepass);
    const vk::raii::ShaderModule routing_vert = module(shaders.show_routing_vertex);
    const vk::raii::ShaderModule routing_geom = module(shaders.show_routing_geometry);
    const vk::raii::ShaderModule routing_frag = module(shaders.show_routing);
    geometry.vertex = *routing_vert;
    geometry.geometry = *routing_geom;
    geometry.fragment = *routing_frag;
    make_chunk_pipelines(show_routing_pipeline_, show_routing_after_prepass_pipeline_);

    // The sky covers only pixels still at the cleared far depth (0 with reversed Z).
    const vk::raii::ShaderModule fullscreen_vert = vk_core::make_shader(ctx, kFullscreenVert);
    const vk::raii::ShaderModule sky_geom = module(shaders.sky_geometry);
    const vk::raii::ShaderModule sky_frag = module(shaders.sky);
    vk_core::GraphicsPipelineDesc sky;
    sky.layout = *layout_;
    sky.vertex = *fullscreen_vert;
    sky.geometry = *sky_geom;
    sky.fragment = *sky_frag;
    sky.color_formats = color_formats;
    sky.depth_format = kDepthFormat;
    sky.samples = config.samples;
    sky.view_mask = view_mask;
    sky.cull = vk::CullModeFlagBits::eNone;
    sky.depth_write = false;
    sky.depth_compare = vk::CompareOp::eEqual;
    sky_pipeline_ = vk_core::make_graphics_pipeline(ctx, sky);
    if (config.stereo == StereoDuplication::kNone) {
        // Every pixel at once, whatever the depth; only the hidden ones survive the discard.
        const vk::raii::ShaderModule mask_frag = vk_core::make_shader(ctx, kMaskHiddenFrag);
        vk_core::GraphicsPipelineDesc mask = sky;
        mask.geometry = nullptr;
        mask.fragment = *mask_frag;
        mask.depth_write = true;
        mask.depth_compare = vk::CompareOp::eAlways;
        mask.blend = vk::PipelineColorBlendAttachmentState().setColorWriteMask({});
        mask_hidden_pipeline_ = vk_core::make_graphics_pipeline(ctx, mask);
    }
}

void ForwardPass::record(const vk::raii::CommandBuffer& cmd, const ForwardTargets& targets,
                         vk::DescriptorSet view_set, vk::DescriptorSet merged_depth_set,
                         const SceneGeometry& geometry, const SceneTextures& textures,
                         const IndirectDraws& chunks, std::span<const ForwardDraw> steps) const {
    using Stage = vk::PipelineStageFlagBits2;
    using Access = vk::AccessFlagBits2;
    const MultisampleTargets* ms = targets.multisample;
    assert((config_.samples != vk::SampleCountFlagBits::e1) == (ms != nullptr));
    assert(!config_.velocity || targets.velocity != nullptr);
    std::vector<const vk_core::Image*> colors_written = {&targets.hdr, &targets.linear_depth};
    if (config_.velocity) colors_written.push_back(targets.velocity);
    if (ms) {
        colors_written.push_back(&ms->hdr);
        colors_written.push_back(&ms->linear_depth);
    }
    for (const vk_core::Image* color : colors_written) {
        vk_core::transition(cmd, *color, vk::ImageLayout::eUndefined,
                            vk::ImageLayout::eColorAttachmentOptimal, Stage::eFragmentShader,
                            Access::eShaderSampledRead, Stage::eColorAttachmentOutput,
                            Access::eColorAttachmentWrite);
    }
    const vk_core::Image& depth_image = ms ? ms->depth : targets.depth;
    vk_core::transition(cmd, depth_image, vk::ImageLayout::eUndefined,
                        vk::ImageLayout::eDepthAttachmentOptimal,
                        Stage::eLateFragmentTests | Stage::eFragmentShader | Stage::eComputeShader,
                        Access::eDepthStencilAttachmentWrite | Access::eShaderSampledRead,
                        Stage::eEarlyFragmentTests | Stage::eLateFragmentTests,
                        Access::eDepthStencilAttachmentWrite | Access::eDepthStencilAttachmentRead);
    const vk::AttachmentLoadOp color_load =
        targets.clear_color ? vk::AttachmentLoadOp::eClear : vk::AttachmentLoadOp::eDontCare;
    auto attachment = [&](const vk_core::Image& image, const vk_core::Image* multisampled,
                          const vk::ClearColorValue& clear) {
        vk::RenderingAttachmentInfo info(image.view(), vk::ImageLayout::eColorAttachmentOptimal, {},
                                         {}, {}, color_load, vk::AttachmentStoreOp::eStore,
                                         vk::ClearValue(clear));
        if (multisampled) {
            // Draw into the samples, keep only their average: the samples are never read again.
            info.setImageView(multisampled->view())
                .setResolveMode(vk::ResolveModeFlagBits::eAverage)
                .setResolveImageView(image.view())
                .setResolveImageLayout(vk::ImageLayout::eColorAttachmentOptimal)
                .setStoreOp(vk::AttachmentStoreOp::eDontCare);
        }
        return info;
    };
    std::vector<vk::RenderingAttachmentInfo> colors = {
        attachment(targets.hdr, ms ? &ms->hdr : nullptr,
                   vk::ClearColorValue(0.0f, 0.0f, 0.0f, 1.0f)),
        attachment(
            targets.linear_depth, ms ? &ms->linear_depth : nullptr,
            vk::ClearColorValue(static_cast<float>(MONOPLANE_SKY_LINEAR_DEPTH), 0.0f, 0.0f, 0.0f)),
    };
    if (config_.velocity) {
        colors.push_back(
            attachment(*targets.velocity, nullptr, vk::ClearColorValue(0.0f, 0.0f, 0.0f, 0.0f)));
    }
    const vk::RenderingAttachmentInfo depth(
        depth_image.view(), vk::ImageLayout::eDepthAttachmentOptimal, {}, {}, {},
        vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore,
        vk::ClearValue(vk::ClearDepthStencilValue(0.0f, 0)));  // reversed Z: far is 0
    // Single-pass stereo draws both layers of the targets: every draw covers both views with
    // multiview; the geometry shader picks the layer of each triangle it emits otherwise.
    const bool gs = config_.stereo == StereoDuplication::kGeometryShader;
    const bool multiview = config_.stereo == StereoDuplication::kMultiview;
    assert(targets.hdr.desc().layers == (config_.stereo == StereoDuplication::kNone ? 1u : 2u));
    cmd.beginRendering(vk::RenderingInfo()
                           .setRenderArea(vk::Rect2D({0, 0}, targets.area))
                           .setLayerCount(gs ? 2 : 1)
                           .setViewMask(multiview ? 0b11u : 0u)
                           .setColorAttachments(colors)
                           .setPDepthAttachment(&depth));
    vk_core::set_viewport_and_scissor(cmd, targets.area);
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 0, view_set, {});
    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 2, textures.set(), {});
    geometry.bind(cmd);
    // Whether a depth pre-pass precedes the chunk steps: they then test for its depths.
    bool prepassed = false;
    auto chunk_pipeline = [&](const vk::raii::Pipeline& first,
                              const vk::raii::Pipeline& after_prepass) {
        return prepassed ? *after_prepass : *first;
    };
    for (const ForwardDraw& draw : steps) {
        with_predicate(cmd, draw.when, [&] {
            switch (draw.step) {
                case ForwardStep::kMaskHidden:
                    assert(*mask_hidden_pipeline_);
                    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 1,
                                           merged_depth_set, {});
                    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *mask_hidden_pipeline_);
                    cmd.draw(3, 1, 0, 0);
                    break;
                case ForwardStep::kDepthPrepass:
                    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *depth_prepass_pipeline_);
                    chunks.record(cmd);
                    break;
                case ForwardStep::kChunks:
                    cmd.bindPipeline(
                        vk::PipelineBindPoint::eGraphics,
                        chunk_pipeline(geometry_pipeline_, geometry_after_prepass_pipeline_));
                    chunks.record(cmd);
                    break;
                case ForwardStep::kChunksShowRouting:
                    cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 1,
                                           merged_depth_set, {});
                    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics,
                                     chunk_pipeline(show_routing_pipeline_,
                                                    show_routing_after_prepass_pipeline_));
                    chunks.record(cmd);
                    break;
                case ForwardStep::kSky:
                    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *sky_pipeline_);
                    cmd.draw(3, 1, 0, 0);
                    break;
            }
        });
        // A predicated pre-pass runs under the same predicate as the chunk steps after it.
        if (draw.step == ForwardStep::kDepthPrepass) prepassed = true;
    }
    cmd.endRendering();
}

vk_core::DescriptorSet ForwardPass::make_view_set(const vk_core::Buffer& constants,
                                                  vk::ImageView shadow,
                                                  vk::Sampler shadow_sampler) const {
    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eUniformBuffer, 1),
                              vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1)};
    vk_core::DescriptorSet set(ctx_, *set_layout_, sizes);
    const vk::DescriptorBufferInfo constants_info(constants.handle(), 0, VK_WHOLE_SIZE);
    const vk::DescriptorImageInfo shadow_info(shadow_sampler, shadow,
                                              vk::ImageLayout::eShaderReadOnlyOptimal);
    const std::array writes = {
        vk::WriteDescriptorSet(*set, 0, 0, vk::DescriptorType::eUniformBuffer, {}, constants_info),
        vk::WriteDescriptorSet(*set, 1, 0, vk::DescriptorType::eCombinedImageSampler, shadow_info),
    };
    ctx_.device().updateDescriptorSets(writes, {});
    return set;
}

vk_core::DescriptorSet ForwardPass::make_merged_depth_set() const {
    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1),
                              vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 1)};
    return vk_core::DescriptorSet(ctx_, *merged_depth_layout_, sizes);
}

void ForwardPass::write_merged_depth(const vk_core::DescriptorSet& set, vk::ImageView pyramid,
                                     vk::Sampler nearest, vk::Buffer routing) const {
    const vk::DescriptorImageInfo merged(nearest, pyramid, vk::ImageLayout::eGeneral);
    const vk::DescriptorBufferInfo routing_info(routing, 0, VK_WHOLE_SIZE);
    const std::array writes = {
        vk::WriteDescriptorSet(*set, 0, 0, vk::DescriptorType::eCombinedImageSampler, merged),
        vk::WriteDescriptorSet(*set, 1, 0, vk::DescriptorType::eStorageBuffer, {}, routing_info),
    };
    ctx_.device().updateDescriptorSets(writes, {});
}

}  // namespace monoplane::passes
