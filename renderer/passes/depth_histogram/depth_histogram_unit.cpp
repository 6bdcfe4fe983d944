// The depth histogram of both eyes' final linear depth (renderer/plan/depth_histogram.h), for
// `--mono-plane auto`, a pass kind written as one unit: after the tone mapping, the frame's
// histogram buffer is cleared and each eye counted into it by one compute dispatch
// (depth_histogram.comp); the host reads it when the frame completes (the renderer's chooser,
// renderer/modes/auto_mono_plane.h, which owns one buffer per frame slot).
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include <array>
#include <cmath>
#include <optional>

#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shared/dispatch_groups.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/passes/shared/slot_sets.h"
#include "renderer/plan/depth_histogram.h"
#include "renderer/vk/descriptor_set.h"
#include "renderer/vk/pipeline.h"
#endif

namespace monoplane::passes::depth_histogram {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

// Once per frame under `--mono-plane auto`: "clear" the buffer, then "count" both eyes' final
// depth (C's where it shows through) into it; the host reads it after the frame.
void place(plan::UnitPlacement& placement) {
    if (!placement.options().depth_histogram) return;
    plan::PlannedPass& pass = placement.add_pass();
    plan::PlanResources& r = placement.resources();
    const graph::BufferHandle bins = r.shared(plan::BufferRole::kDepthHistogram);
    graph::Step& clear = pass.steps.emplace_back();
    clear.name = "clear";
    graph::StepBuilder(clear).use(bins, graph::Use::kTransferDst);
    graph::Step& count = pass.steps.emplace_back();
    count.name = "count";
    graph::StepBuilder counting(count);
    for (plan::ViewId eye : plan::kEyeViews) {
        counting.use(r.image(eye, plan::ImageRole::kLinearDepth), graph::Use::kSampledCompute);
    }
    counting.use(bins, graph::Use::kStorageWrite);
    placement.read_by_host(bins);
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(plan::PassKind::kDepthHistogram, plan::UnitSlot::kAfterToneMapping,
                               "both eyes' final depth counted into bins for --mono-plane auto",
                               &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

const std::uint32_t kDepthHistogramComp[] = {
#include "depth_histogram.comp.spv.inc"
};

// The pixels one workgroup counts along x and y: the shader's local size (16) times the block
// each invocation counts (kBlock, 4).
constexpr std::uint32_t kHistogramGroup = 16 * 4;
constexpr vk::DeviceSize kBytes = MONOPLANE_DEPTH_HISTOGRAM_WORDS * sizeof(std::uint32_t);

struct HistogramPush {
    float log_near;
    float bins_per_log_unit;
    std::uint32_t width, height;
};

class DepthHistogramRecorder final : public UnitRecorder {
  public:
    explicit DepthHistogramRecorder(const vk_core::Context& ctx)
        : ctx_(ctx), nearest_(vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest)) {
        const auto compute = vk::ShaderStageFlagBits::eCompute;
        const std::array bindings = {
            vk::DescriptorSetLayoutBinding(0, vk::DescriptorType::eCombinedImageSampler, 1,
                                           compute),
            vk::DescriptorSetLayoutBinding(1, vk::DescriptorType::eStorageBuffer, 1, compute),
        };
        set_layout_ = vk::raii::DescriptorSetLayout(
            ctx.device(), vk::DescriptorSetLayoutCreateInfo({}, bindings));
        const vk::PushConstantRange push(compute, 0, sizeof(HistogramPush));
        const vk::DescriptorSetLayout set_layout = *set_layout_;
        layout_ = vk::raii::PipelineLayout(ctx.device(),
                                           vk::PipelineLayoutCreateInfo({}, set_layout, push));
        const vk::raii::ShaderModule shader = vk_core::make_shader(ctx, kDepthHistogramComp);
        pipeline_ = vk_core::make_compute_pipeline(ctx, *layout_, *shader);
        sets_.emplace(
            ctx, set_layout,
            std::vector{vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1),
                        vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 1)});
    }

    void record(UnitRecording& r) override {
        const vk_core::Buffer& bins =
            r.buffer(plan::ViewId::kNone, plan::BufferRole::kDepthHistogram);
        r.cmd().fillBuffer(bins.handle(), 0, kBytes, 0u);
        r.next_step("count");
        const DepthHistogramRange range = r.values().settings.depth_histogram;
        const vk::Extent2D extent =
            r.image(plan::ViewId::kLeft, plan::ImageRole::kLinearDepth).desc().extent;
        const HistogramPush push{
            static_cast<float>(std::log(range.near)),
            static_cast<float>(MONOPLANE_DEPTH_HISTOGRAM_BINS / std::log(range.far / range.near)),
            extent.width, extent.height};
        r.cmd().bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline_);
        r.cmd().pushConstants<HistogramPush>(*layout_, vk::ShaderStageFlagBits::eCompute, 0, push);
        for (plan::ViewId eye : plan::kEyeViews) {
            const vk::DescriptorSet set = input_set(r, eye, bins);
            r.cmd().bindDescriptorSets(vk::PipelineBindPoint::eCompute, *layout_, 0, set, {});
            r.cmd().dispatch(groups_covering(extent.width, kHistogramGroup),
                             groups_covering(extent.height, kHistogramGroup), 1);
        }
    }

  private:
    // The slot's set for the eye, pointed at this frame's depth image and buffer.
    vk::DescriptorSet input_set(UnitRecording& r, plan::ViewId eye, const vk_core::Buffer& bins) {
        const vk::DescriptorSet set = sets_->at(r.values().slot, eye);
        const vk::DescriptorImageInfo image(*nearest_,
                                            r.image(eye, plan::ImageRole::kLinearDepth).view(),
                                            executor::layout_for(graph::Use::kSampledCompute));
        const vk::DescriptorBufferInfo buffer(bins.handle(), 0, kBytes);
        const std::array writes = {
            vk::WriteDescriptorSet(set, 0, 0, vk::DescriptorType::eCombinedImageSampler, image),
            vk::WriteDescriptorSet(set, 1, 0, vk::DescriptorType::eStorageBuffer, {}, buffer)};
        ctx_.device().updateDescriptorSets(writes, {});
        return set;
    }

    const vk_core::Context& ctx_;
    vk::raii::Sampler nearest_{nullptr};
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
    std::optional<SlotSets> sets_;  // the eye's depth and the frame's buffer, per frame slot
};

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene&,
                                            const UnitPasses&, const UnitSettings&) {
    return std::make_unique<DepthHistogramRecorder>(ctx);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::depth_histogram
