// Temporal anti-aliasing of each eye (Karis 2014; papers/000 Sect. 4.5), a pass kind written as
// one unit: the frame's HDR image is blended with the reprojected, colour-box-clipped history of
// earlier frames (taa_resolve.frag). Per eye, after the eyes' SSAO and before their tone mapping,
// which then reads the resolve (the eye's history image) instead of its HDR image.
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION, for the plan) and the
// recorder (MONOPLANE_UNIT_RECORDER, for the renderer) of renderer/plan/pass_unit.h and
// renderer/passes/shared/pass_unit.h, side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include <array>
#include <optional>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "renderer/executor/image_layouts.h"
#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shared/fullscreen_pass.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/passes/shared/slot_sets.h"
#include "renderer/vk/descriptor_set.h"
#endif

namespace monoplane::passes::taa {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

// Per eye when the renderer anti-aliases with TAA: this frame's colour, motion and depth and
// the last frame's resolve in, this frame's resolve (the next frame's history) out.
void place(plan::UnitPlacement& placement) {
    if (placement.options().anti_aliasing != plan::AntiAliasing::kTaa) return;
    for (plan::ViewId eye : plan::kEyeViews) {
        plan::PlannedPass& pass = placement.add_pass(eye);
        plan::PlanResources& r = placement.resources();
        graph::Step& step = pass.steps.emplace_back();
        step.name = "resolve";
        graph::StepBuilder(step)
            .use(r.image(eye, plan::ImageRole::kHdr), graph::Use::kSampledFragment)
            .use(r.image(eye, plan::ImageRole::kVelocity), graph::Use::kSampledFragment)
            .use(r.image(eye, plan::ImageRole::kLinearDepth), graph::Use::kSampledFragment)
            .use(r.image(eye, plan::ImageRole::kHistoryPrevious), graph::Use::kSampledFragment)
            .use(r.image(eye, plan::ImageRole::kHistory), graph::Use::kColorWrite);
    }
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(plan::PassKind::kTaa, plan::UnitSlot::kBeforeToneMapping,
                               "temporal anti-aliasing of each eye (--anti-aliasing taa)", &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

const std::uint32_t kTaaResolveFrag[] = {
#include "taa_resolve.frag.spv.inc"
};

struct TaaPush {
    glm::vec4 params;  // history weight, box widening per pixel of motion, 1 = reset, unused
    glm::vec4 extent;  // size in pixels, 1 / size
};
static_assert(sizeof(TaaPush) == 32, "must match taa_resolve.frag");

// The resolve's output is HDR colour (the tone mapping reads it), in the HDR images' format.
constexpr vk::Format kOutputFormat = ForwardPass::kHdrFormat;

class TaaRecorder final : public UnitRecorder {
  public:
    explicit TaaRecorder(const vk_core::Context& ctx)
        : ctx_(ctx),
          nearest_(vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest)),
          bilinear_(vk_core::make_clamped_sampler(ctx, vk::Filter::eLinear)) {
        std::array<vk::DescriptorSetLayoutBinding, 4> bindings;
        for (std::uint32_t i = 0; i < bindings.size(); ++i) {
            bindings[i] =
                vk::DescriptorSetLayoutBinding(i, vk::DescriptorType::eCombinedImageSampler, 1,
                                               vk::ShaderStageFlagBits::eFragment);
        }
        set_layout_ = vk::raii::DescriptorSetLayout(
            ctx.device(), vk::DescriptorSetLayoutCreateInfo({}, bindings));
        const vk::DescriptorSetLayout set_layout = *set_layout_;
        const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0, sizeof(TaaPush));
        layout_ = vk::raii::PipelineLayout(ctx.device(),
                                           vk::PipelineLayoutCreateInfo({}, set_layout, push));
        pipeline_ = make_fullscreen_pipeline(ctx, *layout_, kTaaResolveFrag, kOutputFormat);
        sets_.emplace(
            ctx, set_layout,
            std::vector{vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 4)});
    }

    void record(UnitRecording& r) override {
        const plan::ViewId eye = r.pass().view;
        const vk_core::Image& output = r.image(eye, plan::ImageRole::kHistory);
        const vk::DescriptorSet inputs = input_set(r, eye);
        const TaaParams& params = r.values().settings.taa;
        const vk::Extent2D extent = output.desc().extent;
        const glm::vec2 size(static_cast<float>(extent.width), static_cast<float>(extent.height));
        // A restarted history is bound for the shader's interface, not read.
        const TaaPush push{glm::vec4(params.history_weight, params.velocity_box_widening,
                                     r.values().history_restarted ? 1.0f : 0.0f, 0.0f),
                           glm::vec4(size, 1.0f / size)};
        record_fullscreen(r.cmd(), output, *pipeline_, *layout_, inputs,
                          std::as_bytes(std::span(&push, 1)));
    }

  private:
    // The slot's set for the eye, pointed at this frame's images (the history images swap roles
    // every frame).
    vk::DescriptorSet input_set(UnitRecording& r, plan::ViewId eye) {
        const vk::DescriptorSet set = sets_->at(r.values().slot, eye);
        const auto read_only = executor::layout_for(graph::Use::kSampledFragment);
        const auto input = [&](vk::Sampler sampler, plan::ImageRole role) {
            return vk::DescriptorImageInfo(sampler, r.image(eye, role).view(), read_only);
        };
        // Texel-exact: this frame's colour, motion and depth; bilinear: the last resolve.
        const std::array images = {input(*nearest_, plan::ImageRole::kHdr),
                                   input(*nearest_, plan::ImageRole::kVelocity),
                                   input(*nearest_, plan::ImageRole::kLinearDepth),
                                   input(*bilinear_, plan::ImageRole::kHistoryPrevious)};
        vk_core::write_sampled_images(ctx_, set, images);
        return set;
    }

    const vk_core::Context& ctx_;
    vk::raii::Sampler nearest_{nullptr};
    vk::raii::Sampler bilinear_{nullptr};
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
    std::optional<SlotSets> sets_;  // the eye's inputs, per frame slot
};

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene&,
                                            const UnitPasses&, const UnitSettings&) {
    return std::make_unique<TaaRecorder>(ctx);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::taa
