// The merged depth pyramid of both eyes in C's image space (papers/000 Sect. 4.4; the images in
// depth_pyramid.h), a pass kind written as one unit: in monoplane's hybrid, after the eyes'
// forward passes and before C's, each eye's depth is reduced to 4 x 4 block minima
// (eye_depth_blocks.comp), the blocks merged through the homography from C's pixels to each
// eye's into the pyramid's level 0 (merge_eye_depths.comp), and each further level reduced from
// the one before (reduce_depth.comp). The GPU skips it when no eye drew anything nearer than m.
//
// The declaration (compiled Vulkan-free with MONOPLANE_UNIT_DECLARATION) and the recorder
// (MONOPLANE_UNIT_RECORDER) of renderer/plan/pass_unit.h and renderer/passes/shared/pass_unit.h,
// side by side.
#include "renderer/plan/pass_unit.h"

#ifdef MONOPLANE_UNIT_RECORDER
#include <algorithm>
#include <array>
#include <map>
#include <vector>

#include <glm/vec4.hpp>

#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shared/dispatch_groups.h"
#include "renderer/passes/shared/pass_unit.h"
#include "renderer/vk/descriptor_set.h"
#include "renderer/vk/pipeline.h"
#endif

namespace monoplane::passes::depth_pyramid {

#ifdef MONOPLANE_UNIT_DECLARATION
namespace {

using graph::Use;
using plan::ImageRole;

// Once per hybrid frame whose C is depth-tested (plan::depth_test_skip_reason says why not):
// "blocks" (both eyes' depth to block minima), "merge" (level 0), "reduce" (once per further
// level: the step repeats).
void place(plan::UnitPlacement& placement) {
    if (placement.options().mode == plan::Mode::kStereo) return;
    plan::PlannedPass& pass = placement.add_pass();
    plan::PlanResources& r = placement.resources();
    graph::Step& blocks = pass.steps.emplace_back();
    blocks.name = "blocks";
    graph::StepBuilder blocks_uses(blocks);
    for (plan::ViewId eye : plan::kEyeViews) {
        blocks_uses.use(r.image(eye, ImageRole::kDepth), Use::kDepthSampledCompute);
    }
    blocks_uses.use(r.shared(ImageRole::kPyramidBlocks), Use::kStorageWrite);
    graph::Step& merge = pass.steps.emplace_back();
    merge.name = "merge";
    graph::StepBuilder(merge)
        .use(r.shared(ImageRole::kPyramidBlocks), Use::kStorageRead)
        .use(r.shared(ImageRole::kMergedDepth), Use::kStorageWrite);
    graph::Step& reduce = pass.steps.emplace_back();
    reduce.name = "reduce";
    reduce.repeats = true;
    graph::StepBuilder(reduce).use(r.shared(ImageRole::kMergedDepth), Use::kStorageWrite);
    // No pyramid where no eye drew anything: C has nothing to save.
    pass.when = placement.when(plan::GpuPredicate::kMonoDepthTested);
    pass.skipped = plan::depth_test_skip_reason(placement.options(), placement.frame());
}

}  // namespace

plan::PassUnitDeclaration declaration() {
    return plan::built_in_unit(plan::PassKind::kDepthPyramid, plan::UnitSlot::kAfterEyesForward,
                               "both eyes' near depth merged into a pyramid in C's image space",
                               &place);
}
#endif  // MONOPLANE_UNIT_DECLARATION

#ifdef MONOPLANE_UNIT_RECORDER
namespace {

const std::uint32_t kMergeEyeDepths[] = {
#include "merge_eye_depths.comp.spv.inc"
};
const std::uint32_t kEyeDepthBlocks[] = {
#include "eye_depth_blocks.comp.spv.inc"
};
const std::uint32_t kReduceDepth[] = {
#include "reduce_depth.comp.spv.inc"
};

using Type = vk::DescriptorType;

constexpr std::uint32_t kPyramidGroup = 8;  // the shaders' local size in x and y

// The merge's push constant: each eye's homography from C's pixels, row by row.
using MergePush = std::array<glm::vec4, 6>;

class PyramidRecorder final : public UnitRecorder {
  public:
    explicit PyramidRecorder(const vk_core::Context& ctx) : ctx_(ctx) {
        nearest_ = vk_core::make_texel_sampler(ctx);
        const auto compute = vk::ShaderStageFlagBits::eCompute;
        // Shared by the blocks step (bindings 0, 2) and the merge step (0, 1, 3).
        const std::array merge_bindings = {
            vk::DescriptorSetLayoutBinding(0, Type::eCombinedImageSampler, 2, compute),
            vk::DescriptorSetLayoutBinding(1, Type::eStorageImage, 1, compute),
            vk::DescriptorSetLayoutBinding(2, Type::eStorageImage, 1, compute),
            vk::DescriptorSetLayoutBinding(3, Type::eStorageImage, 1, compute),
        };
        merge_layout_ = vk::raii::DescriptorSetLayout(
            ctx.device(), vk::DescriptorSetLayoutCreateInfo({}, merge_bindings));
        const std::array reduce_bindings = {
            vk::DescriptorSetLayoutBinding(0, Type::eStorageImage, 1, compute),
            vk::DescriptorSetLayoutBinding(1, Type::eStorageImage, 1, compute),
        };
        reduce_layout_ = vk::raii::DescriptorSetLayout(
            ctx.device(), vk::DescriptorSetLayoutCreateInfo({}, reduce_bindings));
        const vk::PushConstantRange push(compute, 0, sizeof(MergePush));
        const vk::DescriptorSetLayout merge_layout = *merge_layout_;
        const vk::DescriptorSetLayout reduce_layout = *reduce_layout_;
        merge_pipeline_layout_ = vk::raii::PipelineLayout(
            ctx.device(), vk::PipelineLayoutCreateInfo({}, merge_layout, push));
        reduce_pipeline_layout_ =
            vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, reduce_layout));
        const vk::raii::ShaderModule blocks = vk_core::make_shader(ctx, kEyeDepthBlocks);
        const vk::raii::ShaderModule merge = vk_core::make_shader(ctx, kMergeEyeDepths);
        const vk::raii::ShaderModule reduce = vk_core::make_shader(ctx, kReduceDepth);
        blocks_ = vk_core::make_compute_pipeline(ctx, *merge_pipeline_layout_, *blocks);
        merge_ = vk_core::make_compute_pipeline(ctx, *merge_pipeline_layout_, *merge);
        reduce_ = vk_core::make_compute_pipeline(ctx, *reduce_pipeline_layout_, *reduce);
    }

    void record(UnitRecording& r) override {
        with_predicate(r.cmd(), r.predicate(r.pass().when), [&] { record_steps(r); });
    }

  private:
    // This frame slot's sets: the slot's last frame has completed, so they are free to rewrite,
    // and each is written before this recording binds it.
    struct FrameSets {
        vk_core::DescriptorSet blocks;
        vk_core::DescriptorSet merge;
        std::vector<vk_core::DescriptorSet> reduce;  // one per level after the first
    };

    void record_steps(UnitRecording& r) {
        const vk::raii::CommandBuffer& cmd = r.cmd();
        FrameSets& sets = sets_for(r.values().slot);
        // "blocks": each eye's depth (sampled) to its layer of the blocks image.
        const std::array depths = {
            vk::DescriptorImageInfo(*nearest_, r.image(plan::ViewId::kLeft, kDepth).view(),
                                    executor::layout_for(graph::Use::kDepthSampledCompute)),
            vk::DescriptorImageInfo(*nearest_, r.image(plan::ViewId::kRight, kDepth).view(),
                                    executor::layout_for(graph::Use::kDepthSampledCompute)),
        };
        const vk_core::Image& blocks =
            r.image(plan::ViewId::kNone, plan::ImageRole::kPyramidBlocks);
        write(*sets.blocks, depths, 2, blocks.view());
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *merge_pipeline_layout_, 0,
                               *sets.blocks, {});
        cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *blocks_);
        const vk::Extent2D blocks_extent = blocks.desc().extent;
        cmd.dispatch(groups_covering(blocks_extent.width, kPyramidGroup),
                     groups_covering(blocks_extent.height, kPyramidGroup), 2);

        // "merge": the blocks through each eye's homography into level 0. The shader takes the
        // eyes' depth sizes from their descriptors (textureSize), reading none of their texels.
        r.next_step("merge");
        const vk_core::Image& pyramid = r.image(plan::ViewId::kNone, plan::ImageRole::kMergedDepth);
        write(*sets.merge, depths, 3, blocks.view(), pyramid.mip_view(0));
        write_reduce_sets(sets, pyramid);
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *merge_pipeline_layout_, 0,
                               *sets.merge, {});
        cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *merge_);
        cmd.pushConstants<MergePush>(*merge_pipeline_layout_, vk::ShaderStageFlagBits::eCompute, 0,
                                     merge_push(r.values()));
        const vk::Extent2D extent = pyramid.desc().extent;
        cmd.dispatch(groups_covering(extent.width, kPyramidGroup),
                     groups_covering(extent.height, kPyramidGroup), 1);

        // "reduce", again per level.
        cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *reduce_);
        for (std::uint32_t mip = 1; mip < pyramid.desc().mip_levels; ++mip) {
            r.next_step("reduce");
            cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *reduce_pipeline_layout_, 0,
                                   *sets.reduce[mip - 1], {});
            cmd.dispatch(groups_covering(std::max(extent.width >> mip, 1u), kPyramidGroup),
                         groups_covering(std::max(extent.height >> mip, 1u), kPyramidGroup), 1);
        }
    }

    static MergePush merge_push(const UnitFrameValues& values) {
        MergePush rows{};
        for (int e = 0; e < 2; ++e) {
            const glm::dmat3& m = values.mono_pixel_to_eye[e];
            for (int row = 0; row < 3; ++row) {
                // glm is column-major: element (row, column c) is m[c][row].
                rows[3 * e + row] = glm::vec4(m[0][row], m[1][row], m[2][row], 0.0f);
            }
        }
        return rows;
    }

    FrameSets& sets_for(std::uint32_t slot) {
        auto [entry, added] = sets_.try_emplace(slot);
        if (added) {
            const std::array sizes = {vk::DescriptorPoolSize(Type::eCombinedImageSampler, 2),
                                      vk::DescriptorPoolSize(Type::eStorageImage, 3)};
            entry->second.blocks = vk_core::DescriptorSet(ctx_, *merge_layout_, sizes);
            entry->second.merge = vk_core::DescriptorSet(ctx_, *merge_layout_, sizes);
        }
        return entry->second;
    }

    // The eyes' depths at binding 0 and `storage` at `first_storage`, ... (the blocks set: the
    // blocks at 2; the merge set: the blocks at 3, level 0 at 1).
    void write(vk::DescriptorSet set, const std::array<vk::DescriptorImageInfo, 2>& depths,
               std::uint32_t blocks_binding, vk::ImageView blocks,
               vk::ImageView level0 = nullptr) const {
        const auto storage = [](vk::ImageView view) {
            return vk::DescriptorImageInfo(nullptr, view,
                                           executor::layout_for(graph::Use::kStorageWrite));
        };
        const vk::DescriptorImageInfo blocks_info = storage(blocks);
        const vk::DescriptorImageInfo level0_info = storage(level0);
        std::vector<vk::WriteDescriptorSet> writes = {
            vk::WriteDescriptorSet(set, 0, 0, Type::eCombinedImageSampler, depths),
            vk::WriteDescriptorSet(set, blocks_binding, 0, Type::eStorageImage, blocks_info),
        };
        if (level0) writes.emplace_back(set, 1, 0, Type::eStorageImage, level0_info);
        ctx_.device().updateDescriptorSets(writes, {});
    }

    // Each level after the first reads the level before it.
    void write_reduce_sets(FrameSets& sets, const vk_core::Image& pyramid) const {
        const std::uint32_t mips = pyramid.desc().mip_levels;
        const std::array sizes = {vk::DescriptorPoolSize(Type::eStorageImage, 2)};
        while (sets.reduce.size() + 1 < mips) {
            sets.reduce.emplace_back(ctx_, *reduce_layout_, sizes);
        }
        for (std::uint32_t mip = 1; mip < mips; ++mip) {
            const std::array levels = {
                vk::DescriptorImageInfo(nullptr, pyramid.mip_view(mip - 1),
                                        executor::layout_for(graph::Use::kStorageWrite)),
                vk::DescriptorImageInfo(nullptr, pyramid.mip_view(mip),
                                        executor::layout_for(graph::Use::kStorageWrite)),
            };
            const std::array writes = {
                vk::WriteDescriptorSet(*sets.reduce[mip - 1], 0, 0, Type::eStorageImage, levels[0]),
                vk::WriteDescriptorSet(*sets.reduce[mip - 1], 1, 0, Type::eStorageImage, levels[1]),
            };
            ctx_.device().updateDescriptorSets(writes, {});
        }
    }

    static constexpr plan::ImageRole kDepth = plan::ImageRole::kDepth;

    const vk_core::Context& ctx_;
    vk::raii::Sampler nearest_{nullptr};
    vk::raii::DescriptorSetLayout merge_layout_{nullptr};
    vk::raii::DescriptorSetLayout reduce_layout_{nullptr};
    vk::raii::PipelineLayout merge_pipeline_layout_{nullptr};
    vk::raii::PipelineLayout reduce_pipeline_layout_{nullptr};
    vk::raii::Pipeline blocks_{nullptr};
    vk::raii::Pipeline merge_{nullptr};
    vk::raii::Pipeline reduce_{nullptr};
    std::map<std::uint32_t, FrameSets> sets_;  // per frame slot
};

}  // namespace

std::unique_ptr<UnitRecorder> make_recorder(const vk_core::Context& ctx, const UnitScene&,
                                            const UnitPasses&, const UnitSettings&) {
    return std::make_unique<PyramidRecorder>(ctx);
}
#endif  // MONOPLANE_UNIT_RECORDER

}  // namespace monoplane::passes::depth_pyramid
