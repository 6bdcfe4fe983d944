#include "renderer/passes/shadow/shadow_pass.h"

#include <algorithm>
#include <array>
#include <limits>

#include <glm/geometric.hpp>

#include "common/programming_error.h"
#include "renderer/executor/image_layouts.h"

namespace monoplane::passes {
namespace {
const std::uint32_t kShadowVert[] = {
#include "shadow.vert.spv.inc"
};
const std::uint32_t kShadowMaskedVert[] = {
#include "shadow_masked.vert.spv.inc"
};
const std::uint32_t kAlphaTestFrag[] = {
#include "alpha_test.frag.spv.inc"
};
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;
}  // namespace

glm::dmat4 fit_light_view_proj(const glm::dvec3& towards_sun, const scenes::Aabb& region) {
    // Light frame: forward points away from the sun; pick any right/up perpendicular to it.
    const glm::dvec3 forward = -glm::normalize(towards_sun);
    const glm::dvec3 helper =
        std::abs(forward.y) > 0.99 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, helper));
    const glm::dvec3 up = glm::cross(right, forward);
    glm::dvec3 lo(std::numeric_limits<double>::max());
    glm::dvec3 hi(std::numeric_limits<double>::lowest());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? region.max.x : region.min.x,
                           (corner & 2) ? region.max.y : region.min.y,
                           (corner & 4) ? region.max.z : region.min.z);
        const glm::dvec3 q(glm::dot(p, right), glm::dot(p, up), glm::dot(p, forward));
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    const glm::dvec3 extent = glm::max(hi - lo, glm::dvec3(1e-3));
    // Rows map (right, up, forward) coordinates to [-1, 1] x [-1, 1] x [0, 1].
    glm::dmat4 m(0.0);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = 2.0 * right[c] / extent.x;
        m[c][1] = 2.0 * up[c] / extent.y;
        m[c][2] = forward[c] / extent.z;
    }
    m[3][0] = -2.0 * lo.x / extent.x - 1.0;
    m[3][1] = -2.0 * lo.y / extent.y - 1.0;
    m[3][2] = -lo.z / extent.z;
    m[3][3] = 1.0;
    return m;
}

ShadowPass::ShadowPass(const vk_core::Context& ctx, const ShadowParams& params,
                       vk::DescriptorSetLayout scene_textures, bool masked)
    : params_(params),
      map_(ctx, vk_core::ImageDesc{{params.resolution, params.resolution},
                                   kDepthFormat,
                                   vk::ImageUsageFlagBits::eDepthStencilAttachment |
                                       vk::ImageUsageFlagBits::eSampled}) {
    // Hardware comparison: each texture() tap is itself a 2x2 bilinear PCF.
    sampler_ = vk::raii::Sampler(
        ctx.device(),
        vk::SamplerCreateInfo(
            {}, vk::Filter::eLinear, vk::Filter::eLinear, vk::SamplerMipmapMode::eNearest,
            vk::SamplerAddressMode::eClampToEdge, vk::SamplerAddressMode::eClampToEdge,
            vk::SamplerAddressMode::eClampToEdge, 0.0f, VK_FALSE, 1.0f, VK_TRUE,
            vk::CompareOp::eLessOrEqual, 0.0f, 0.0f, vk::BorderColor::eFloatOpaqueWhite));
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eVertex, 0, sizeof(glm::mat4));
    // The scene's textures sit at set 2, where the forward pass's shaders (which the masked
    // draws share) expect them.
    no_bindings_ = vk::raii::DescriptorSetLayout(ctx.device(), vk::DescriptorSetLayoutCreateInfo());
    const std::array sets = {*no_bindings_, *no_bindings_, scene_textures};
    layout_ = vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, sets, push));
    const vk::raii::ShaderModule vert = vk_core::make_shader(ctx, kShadowVert);
    vk_core::GraphicsPipelineDesc desc;
    desc.layout = *layout_;
    desc.vertex = *vert;
    desc.vertex_bindings = SceneGeometry::vertex_bindings();
    desc.vertex_attributes = SceneGeometry::position_attribute();
    desc.depth_format = kDepthFormat;
    desc.cull = vk::CullModeFlagBits::eNone;  // thin and open geometry must cast shadows too
    desc.depth_compare = vk::CompareOp::eLessOrEqual;  // standard depth: nearest the sun is 0
    desc.depth_bias = true;
    pipeline_ = vk_core::make_graphics_pipeline(ctx, desc);
    if (masked) make_masked_pipeline(ctx, desc);
}

void ShadowPass::make_masked_pipeline(const vk_core::Context& ctx,
                                      vk_core::GraphicsPipelineDesc desc) {
    const vk::raii::ShaderModule vert = vk_core::make_shader(ctx, kShadowMaskedVert);
    const vk::raii::ShaderModule frag = vk_core::make_shader(ctx, kAlphaTestFrag);
    desc.vertex = *vert;
    desc.fragment = *frag;
    // The albedo's alpha (location 2) joins the position.
    desc.vertex_attributes = SceneGeometry::position_attribute();
    desc.vertex_attributes.push_back(SceneGeometry::vertex_attributes()[2]);
    masked_pipeline_ = vk_core::make_graphics_pipeline(ctx, desc);
}

void ShadowPass::record(const vk::raii::CommandBuffer& cmd, const SceneGeometry& geometry,
                        const ShadowCasters& casters, const glm::mat4& light_view_proj) const {
    const vk::RenderingAttachmentInfo depth(
        map_.view(), executor::layout_for(graph::Use::kDepthWrite), {}, {}, {},
        vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore,
        vk::ClearValue(vk::ClearDepthStencilValue(1.0f, 0)));
    const vk::Extent2D extent{params_.resolution, params_.resolution};
    // Named setters: with positional arguments, `{}` for the colour attachments selects the
    // count-and-pointer constructor and &depth silently becomes pColorAttachments.
    cmd.beginRendering(vk::RenderingInfo()
                           .setRenderArea(vk::Rect2D({0, 0}, extent))
                           .setLayerCount(1)
                           .setPDepthAttachment(&depth));
    cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline_);
    vk_core::set_viewport_and_scissor(cmd, extent);
    cmd.setDepthBias(params_.depth_bias_constant, 0.0f, params_.depth_bias_slope);
    cmd.pushConstants<glm::mat4>(*layout_, vk::ShaderStageFlagBits::eVertex, 0, light_view_proj);
    geometry.bind(cmd);
    casters.opaque.record(cmd);
    if (casters.masked.max_draws > 0) {
        MONOPLANE_EXPECTS(*masked_pipeline_);
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 2, casters.textures, {});
        cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *masked_pipeline_);
        casters.masked.record(cmd);
    }
    cmd.endRendering();
}

}  // namespace monoplane::passes
