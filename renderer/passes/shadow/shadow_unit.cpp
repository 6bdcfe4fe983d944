// The sun's shadow map drawn, a pass kind written as one unit: once per frame after the culling
// and before the eyes' forward passes (which sample it), depth only, orthographic
// (fit_light_view_proj), from every opaque chunk whole and every alpha-masked chunk through the
// alpha test (ShadowCasters). The map belongs to the scene, which every renderer of it shares
// (ShadowMap): a frame whose light region is the one the map already holds skips the pass
// (PlanFrame::shadow_needed), and the renderer notes what the map holds once the pass is recorded.
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include <array>

#include "common/programming_error.h"
#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shadow/shadow_map.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/vk/pipeline.h"
#endif

namespace monoplane::passes::shadow {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

void place(plan::UnitPlacement& placement) {
    plan::PlannedPass& pass = placement.add_pass();
    graph::Step& step = pass.steps.emplace_back();
    step.name = "draw";
    graph::StepBuilder(step).use(placement.resources().shared(plan::ImageRole::kShadowMap),
                                 graph::Use::kDepthWrite);
    if (!placement.frame().shadow_needed) {
        pass.skipped = "light region unchanged: the shadow map is reused";
    }
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(plan::PassKind::kShadow, plan::UnitSlot::kAfterCulling,
                               "the sun's shadow map, when the light region changes", &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

const std::uint32_t kShadowVert[] = {
#include "shadow.vert.spv.inc"
};
const std::uint32_t kShadowMaskedVert[] = {
#include "shadow_masked.vert.spv.inc"
};
const std::uint32_t kShadowAlphaTestFrag[] = {
#include "alpha_test.frag.spv.inc"
};

class ShadowRecorder final : public UnitRecorder {
  public:
    ShadowRecorder(const vk_core::Context& ctx, const UnitScene& scene) : params_(scene.shadow) {
        const vk::PushConstantRange push(vk::ShaderStageFlagBits::eVertex, 0, sizeof(glm::mat4));
        // The scene's textures sit at set 2, where the forward pass's shaders (which the masked
        // draws share) expect them.
        no_bindings_ =
            vk::raii::DescriptorSetLayout(ctx.device(), vk::DescriptorSetLayoutCreateInfo());
        const std::array sets = {*no_bindings_, *no_bindings_, scene.textures->layout()};
        layout_ =
            vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, sets, push));
        const vk::raii::ShaderModule vert = vk_core::make_shader(ctx, kShadowVert);
        vk_core::GraphicsPipelineDesc desc;
        desc.layout = *layout_;
        desc.vertex = *vert;
        desc.vertex_bindings = SceneGeometry::vertex_bindings();
        desc.vertex_attributes = SceneGeometry::position_attribute();
        desc.depth_format = ShadowMap::kFormat;
        desc.cull = vk::CullModeFlagBits::eNone;  // thin and open geometry must cast shadows too
        desc.depth_compare = vk::CompareOp::eLessOrEqual;  // standard depth: nearest the sun is 0
        desc.depth_bias = true;
        pipeline_ = vk_core::make_graphics_pipeline(ctx, desc);
        if (scene.masked_chunks) make_masked_pipeline(ctx, desc);
    }

    void record(UnitRecording& r) override {
        const vk_core::Image& map = r.image(plan::ViewId::kNone, plan::ImageRole::kShadowMap);
        const vk::raii::CommandBuffer& cmd = r.cmd();
        const vk::RenderingAttachmentInfo depth(
            map.view(), executor::layout_for(graph::Use::kDepthWrite), {}, {}, {},
            vk::AttachmentLoadOp::eClear, vk::AttachmentStoreOp::eStore,
            vk::ClearValue(vk::ClearDepthStencilValue(1.0f, 0)));
        const vk::Extent2D extent = map.desc().extent;
        // Named setters: with positional arguments, `{}` for the colour attachments selects the
        // count-and-pointer constructor and &depth silently becomes pColorAttachments.
        cmd.beginRendering(vk::RenderingInfo()
                               .setRenderArea(vk::Rect2D({0, 0}, extent))
                               .setLayerCount(1)
                               .setPDepthAttachment(&depth));
        cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *pipeline_);
        vk_core::set_viewport_and_scissor(cmd, extent);
        cmd.setDepthBias(params_.depth_bias_constant, 0.0f, params_.depth_bias_slope);
        cmd.pushConstants<glm::mat4>(*layout_, vk::ShaderStageFlagBits::eVertex, 0,
                                     r.values().light_view_proj);
        const UnitScene& scene = r.scene();
        scene.geometry->bind(cmd);
        scene.shadow_casters.opaque.record(cmd);
        if (scene.shadow_casters.masked.max_draws > 0) {
            MONOPLANE_EXPECTS(*masked_pipeline_);
            cmd.bindDescriptorSets(vk::PipelineBindPoint::eGraphics, *layout_, 2,
                                   scene.shadow_casters.textures, {});
            cmd.bindPipeline(vk::PipelineBindPoint::eGraphics, *masked_pipeline_);
            scene.shadow_casters.masked.record(cmd);
        }
        cmd.endRendering();
    }

  private:
    // alphaMode MASK: the alpha test, with the albedo's alpha (location 2) beside the position.
    void make_masked_pipeline(const vk_core::Context& ctx, vk_core::GraphicsPipelineDesc desc) {
        const vk::raii::ShaderModule vert = vk_core::make_shader(ctx, kShadowMaskedVert);
        const vk::raii::ShaderModule frag = vk_core::make_shader(ctx, kShadowAlphaTestFrag);
        desc.vertex = *vert;
        desc.fragment = *frag;
        desc.vertex_attributes = SceneGeometry::position_attribute();
        desc.vertex_attributes.push_back(SceneGeometry::vertex_attributes()[2]);
        masked_pipeline_ = vk_core::make_graphics_pipeline(ctx, desc);
    }

    ShadowParams params_;
    vk::raii::DescriptorSetLayout no_bindings_{nullptr};  // sets 0 and 1: the forward pass's
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
    vk::raii::Pipeline masked_pipeline_{nullptr};
};

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene& scene,
                                            const UnitPasses&, const UnitSettings&) {
    return std::make_unique<ShadowRecorder>(ctx, scene);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::shadow
