// The depth debug view (`--debug-view depth`), a pass kind written as one unit: after the tone
// mapping, each eye's display image is replaced by its linear depth, warm nearer than the mono
// plane and cool beyond it (depth_view.frag), so that one image shows what hybrid rendering sends
// through C. The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the
// recorder (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and
// renderer/passes/shared/pass_unit.h, side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include <optional>

#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shared/display_format.h"
#include "renderer/passes/shared/fullscreen_pass.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/passes/shared/slot_sets.h"
#include "renderer/passes/shared/view_constants.h"
#include "renderer/vk/descriptor_set.h"
#endif

namespace monoplane::passes::depth_view {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

// Per eye, when the frame shows this view: the eye's linear depth in, its display image out.
void place(plan::UnitPlacement& placement) {
    if (!placement.debug_view_shown()) return;
    for (plan::ViewId eye : plan::kEyeViews) {
        plan::PlannedPass& pass = placement.add_pass(eye);
        plan::PlanResources& r = placement.resources();
        graph::Step& step = pass.steps.emplace_back();
        step.name = "draw";
        graph::StepBuilder(step)
            .use(r.image(eye, plan::ImageRole::kLinearDepth), graph::Use::kSampledFragment)
            .use(r.image(eye, plan::ImageRole::kDisplay), graph::Use::kColorWrite);
    }
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    plan::PassUnitDeclaration unit;
    unit.name = "depth_view";
    unit.slots = {plan::UnitSlot::kAfterToneMapping};
    unit.debug_view = "depth";
    unit.help =
        "each eye's linear depth, brighter nearer, warm before the mono plane and cool at or "
        "beyond it, black sky; every mode";
    unit.place = &place;
    return unit;
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

const std::uint32_t kDepthViewFrag[] = {
#include "depth_view.frag.spv.inc"
};

// Stereo and frames without C: nothing lies beyond the plane, not even the sky (depth_view.frag).
constexpr float kNoMonoPlane = static_cast<float>(MONOPLANE_SKY_LINEAR_DEPTH);

class DepthViewRecorder final : public UnitRecorder {
  public:
    explicit DepthViewRecorder(const vk_core::Context& ctx) : ctx_(ctx) {
        const vk::DescriptorSetLayoutBinding binding(0, vk::DescriptorType::eCombinedImageSampler,
                                                     1, vk::ShaderStageFlagBits::eFragment);
        set_layout_ = vk::raii::DescriptorSetLayout(ctx.device(),
                                                    vk::DescriptorSetLayoutCreateInfo({}, binding));
        sampler_ = vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest);
        const vk::DescriptorSetLayout set_layout = *set_layout_;
        const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0, sizeof(float));
        layout_ = vk::raii::PipelineLayout(ctx.device(),
                                           vk::PipelineLayoutCreateInfo({}, set_layout, push));
        pipeline_ = make_fullscreen_pipeline(ctx, *layout_, kDepthViewFrag, kDisplayFormat);
        sets_.emplace(
            ctx, set_layout,
            std::vector{vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1)});
    }

    void record(UnitRecording& r) override {
        const plan::ViewId eye = r.pass().view;
        const vk_core::Image& depth = r.image(eye, plan::ImageRole::kLinearDepth);
        const vk_core::Image& display = r.image(eye, plan::ImageRole::kDisplay);
        const vk::DescriptorSet input = sets_->at(r.values().slot, eye);
        const std::array images = {vk::DescriptorImageInfo(
            *sampler_, depth.view(), executor::layout_for(graph::Use::kSampledFragment))};
        vk_core::write_sampled_images(ctx_, input, images);
        const float mono_plane =
            r.values().use_mono ? static_cast<float>(r.values().mono_plane) : kNoMonoPlane;

        record_fullscreen(r.cmd(), display, *pipeline_, *layout_, input,
                          std::as_bytes(std::span(&mono_plane, 1)));
    }

  private:
    const vk_core::Context& ctx_;
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::Sampler sampler_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
    std::optional<SlotSets> sets_;  // the eye's linear depth, per frame slot
};

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene&,
                                            const UnitPasses&, const UnitSettings&) {
    return std::make_unique<DepthViewRecorder>(ctx);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::depth_view
