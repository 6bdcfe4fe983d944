// The tone mapping, HDR to the 8-bit sRGB display image of each eye and of C (tone_mapping.glsl,
// which the composite that tone maps shares), a pass kind written as one unit: per eye after TAA
// (whose resolve it then reads instead of the HDR image), and C's own in the hybrid modes. Where
// the plan had the composite write an eye's display image itself (PlannedPass::writes_display),
// the eye's tone mapping runs only for frames whose C had nothing to draw (the GPU skips the
// composite then), keeping what the composite wrote otherwise; without GPU predicates it does not
// run at all.
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include <array>
#include <optional>

#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shared/display_format.h"
#include "renderer/passes/shared/fullscreen_pass.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/passes/shared/slot_sets.h"
#include "renderer/vk/descriptor_set.h"
#endif

namespace monoplane::passes::tonemap {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

// One step: `source` of `view` read texel-exact, its display image written (kColorWrite) or
// kept where the draw is skipped (kColorBlend: loaded).
void declare_tonemap(plan::PlannedPass& pass, plan::PlanResources& r, plan::ViewId view,
                     plan::ImageRole source, graph::Use display) {
    graph::Step& step = pass.steps.emplace_back();
    step.name = "tonemap";
    graph::StepBuilder(step)
        .use(r.image(view, source), graph::Use::kSampledFragment)
        .use(r.image(view, plan::ImageRole::kDisplay), display);
}

void place_eye(plan::UnitPlacement& placement, plan::ViewId eye) {
    plan::PlannedPass& pass = placement.add_pass(eye);
    plan::PlanResources& r = placement.resources();
    const plan::PlannedPass* composite = placement.plan().find(plan::PassKind::kComposite, eye);
    if (composite == nullptr || !composite->writes_display) {
        const bool taa = placement.options().anti_aliasing == plan::AntiAliasing::kTaa;
        declare_tonemap(pass, r, eye, taa ? plan::ImageRole::kHistory : plan::ImageRole::kHdr,
                        graph::Use::kColorWrite);
        return;
    }
    if (placement.predicated()) {
        pass.when = plan::GpuPredicate::kMonoNone;
        declare_tonemap(pass, r, eye, plan::ImageRole::kHdr, graph::Use::kColorBlend);
        return;
    }
    declare_tonemap(pass, r, eye, plan::ImageRole::kHdr, graph::Use::kColorWrite);
    pass.skipped =
        "fused into " + composite->name + ": nothing else reads " + plan::view_name(eye) + ".hdr";
}

void place(plan::UnitPlacement& placement) {
    for (plan::ViewId eye : plan::kEyeViews) place_eye(placement, eye);
    if (placement.options().mode == plan::Mode::kStereo) return;
    // C's own tone-mapped image exists only to be looked at (mono.png): without a read-back
    // nothing reads it, and the culling drops the pass.
    plan::PlannedPass& pass = placement.add_pass(plan::ViewId::kMono);
    declare_tonemap(pass, placement.resources(), plan::ViewId::kMono, plan::ImageRole::kHdr,
                    graph::Use::kColorWrite);
    pass.skipped = placement.no_mono_reason();
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(plan::PassKind::kTonemap, plan::UnitSlot::kToneMapping,
                               "each eye's (and C's) HDR colour tone mapped into its display image",
                               &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

const std::uint32_t kTonemapFrag[] = {
#include "tonemap.frag.spv.inc"
};

class TonemapRecorder final : public UnitRecorder {
  public:
    explicit TonemapRecorder(const vk_core::Context& ctx)
        : ctx_(ctx), sampler_(vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest)) {
        const vk::DescriptorSetLayoutBinding binding(0, vk::DescriptorType::eCombinedImageSampler,
                                                     1, vk::ShaderStageFlagBits::eFragment);
        set_layout_ = vk::raii::DescriptorSetLayout(ctx.device(),
                                                    vk::DescriptorSetLayoutCreateInfo({}, binding));
        const vk::DescriptorSetLayout set_layout = *set_layout_;
        const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0,
                                         sizeof(TonemapParams));
        layout_ = vk::raii::PipelineLayout(ctx.device(),
                                           vk::PipelineLayoutCreateInfo({}, set_layout, push));
        pipeline_ = make_fullscreen_pipeline(ctx, *layout_, kTonemapFrag, kDisplayFormat);
        sets_.emplace(
            ctx, set_layout,
            std::vector{vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1)});
    }

    void record(UnitRecording& r) override {
        const plan::ViewId view = r.pass().view;
        // Under TAA an eye's colour is its resolve; its HDR image otherwise.
        const plan::ImageRole source = r.declares(view, plan::ImageRole::kHistory)
                                           ? plan::ImageRole::kHistory
                                           : plan::ImageRole::kHdr;
        const vk::DescriptorSet input = sets_->at(r.values().slot, view);
        const std::array images = {
            vk::DescriptorImageInfo(*sampler_, r.image(view, source).view(),
                                    executor::layout_for(graph::Use::kSampledFragment))};
        vk_core::write_sampled_images(ctx_, input, images);
        const TonemapParams& params = r.values().settings.tonemap;
        // Predicated (if mono-none) where the composite writes the display image otherwise.
        record_fullscreen(r.cmd(), r.image(view, plan::ImageRole::kDisplay), *pipeline_, *layout_,
                          input, std::as_bytes(std::span(&params, 1)), r.predicate(r.pass().when));
    }

  private:
    const vk_core::Context& ctx_;
    vk::raii::Sampler sampler_{nullptr};
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
    std::optional<SlotSets> sets_;  // the view's colour, per frame slot
};

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene&,
                                            const UnitPasses&, const UnitSettings&) {
    return std::make_unique<TonemapRecorder>(ctx);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::tonemap
