#include "renderer/passes/depth_pyramid/depth_pyramid_pass.h"

#include <algorithm>
#include <bit>

#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shared/dispatch_groups.h"
#include "renderer/vk/memory.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {
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

constexpr vk::Format kFormat = vk::Format::eR32Sfloat;
constexpr std::uint32_t kPyramidGroup = 8;  // the shaders' local size in x and y

}  // namespace

DepthPyramidPass::DepthPyramidPass(const vk_core::Context& ctx) : ctx_(ctx) {
    nearest_ = vk::raii::Sampler(
        ctx.device(),
        vk::SamplerCreateInfo({}, vk::Filter::eNearest, vk::Filter::eNearest,
                              vk::SamplerMipmapMode::eNearest, vk::SamplerAddressMode::eClampToEdge,
                              vk::SamplerAddressMode::eClampToEdge,
                              vk::SamplerAddressMode::eClampToEdge, 0.0f, VK_FALSE, 1.0f, VK_FALSE,
                              vk::CompareOp::eNever, 0.0f, VK_LOD_CLAMP_NONE));
    using Type = vk::DescriptorType;
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
    const vk::PushConstantRange push(compute, 0, 6 * sizeof(glm::vec4));
    const vk::DescriptorSetLayout merge_layout = *merge_layout_;
    const vk::DescriptorSetLayout reduce_layout = *reduce_layout_;
    merge_pipeline_layout_ = vk::raii::PipelineLayout(
        ctx.device(), vk::PipelineLayoutCreateInfo({}, merge_layout, push));
    reduce_pipeline_layout_ =
        vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, reduce_layout));
    const vk::raii::ShaderModule blocks = vk_core::make_shader(ctx, kEyeDepthBlocks);
    const vk::raii::ShaderModule merge = vk_core::make_shader(ctx, kMergeEyeDepths);
    blocks_ = vk_core::make_compute_pipeline(ctx, *merge_pipeline_layout_, *blocks);
    const vk::raii::ShaderModule reduce = vk_core::make_shader(ctx, kReduceDepth);
    merge_ = vk_core::make_compute_pipeline(ctx, *merge_pipeline_layout_, *merge);
    reduce_ = vk_core::make_compute_pipeline(ctx, *reduce_pipeline_layout_, *reduce);
    // A 1 x 1 pyramid until C exists: the culling pass's descriptor must name a valid image.
    create_image({1, 1});
}

DepthPyramidPass::~DepthPyramidPass() = default;

namespace {

// One pyramid texel per 4 x 4 block of C's pixels.
vk::Extent2D pyramid_extent(vk::Extent2D mono_allocation) {
    return {(mono_allocation.width + 3) / 4, (mono_allocation.height + 3) / 4};
}

}  // namespace

bool DepthPyramidPass::fits(vk::Extent2D mono_allocation) const {
    const vk::Extent2D needed = pyramid_extent(mono_allocation);
    return needed.width <= extent_.width && needed.height <= extent_.height;
}

bool DepthPyramidPass::resize(vk::Extent2D mono_allocation) {
    if (fits(mono_allocation)) return false;
    create_image(pyramid_extent(mono_allocation));
    return true;
}

void DepthPyramidPass::create_image(vk::Extent2D extent) {
    extent_ = extent;
    mips_ = static_cast<std::uint32_t>(std::bit_width(std::max(extent.width, extent.height)));
    reduce_sets_.clear();
    merge_set_ = nullptr;
    pool_ = nullptr;
    mip_views_.clear();
    all_mips_ = nullptr;
    image_ = nullptr;
    memory_ = nullptr;

    image_ = vk::raii::Image(
        ctx_.device(),
        vk::ImageCreateInfo({}, vk::ImageType::e2D, kFormat, vk::Extent3D(extent, 1), mips_, 1,
                            vk::SampleCountFlagBits::e1, vk::ImageTiling::eOptimal,
                            vk::ImageUsageFlagBits::eStorage | vk::ImageUsageFlagBits::eSampled |
                                vk::ImageUsageFlagBits::eTransferDst,
                            vk::SharingMode::eExclusive));
    memory_ = vk_core::allocate_memory(ctx_, image_.getMemoryRequirements(),
                                       vk::MemoryPropertyFlagBits::eDeviceLocal);
    image_.bindMemory(*memory_, 0);
    const auto color = vk::ImageAspectFlagBits::eColor;
    all_mips_ = vk::raii::ImageView(
        ctx_.device(), vk::ImageViewCreateInfo({}, *image_, vk::ImageViewType::e2D, kFormat, {},
                                               vk::ImageSubresourceRange(color, 0, mips_, 0, 1)));
    for (std::uint32_t mip = 0; mip < mips_; ++mip) {
        mip_views_.emplace_back(
            ctx_.device(), vk::ImageViewCreateInfo({}, *image_, vk::ImageViewType::e2D, kFormat, {},
                                                   vk::ImageSubresourceRange(color, mip, 1, 0, 1)));
    }
    // The pyramid lives in eGeneral: written as storage, read by texelFetch, never moved. Its
    // first contents are "nothing needs C" (1), never read before a build.
    vk_core::initialise_image(ctx_, pyramid_image(),
                              vk::ClearColorValue(std::array{1.0f, 1.0f, 1.0f, 1.0f}));

    using Type = vk::DescriptorType;
    const std::array pool_sizes = {vk::DescriptorPoolSize(Type::eCombinedImageSampler, 2),
                                   vk::DescriptorPoolSize(Type::eStorageImage, 2 * mips_ + 3)};
    pool_ = vk::raii::DescriptorPool(
        ctx_.device(),
        vk::DescriptorPoolCreateInfo(vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet, mips_,
                                     pool_sizes));
    const vk::DescriptorSetLayout merge_layout = *merge_layout_;
    merge_set_ = std::move(vk::raii::DescriptorSets(
        ctx_.device(), vk::DescriptorSetAllocateInfo(*pool_, merge_layout))[0]);
    const vk::DescriptorImageInfo level2(nullptr, *mip_views_[0],
                                         executor::layout_for(graph::Use::kStorageWrite));
    ctx_.device().updateDescriptorSets(
        vk::WriteDescriptorSet(*merge_set_, 1, 0, Type::eStorageImage, level2), {});
    for (std::uint32_t mip = 1; mip < mips_; ++mip) {
        const vk::DescriptorSetLayout reduce_layout = *reduce_layout_;
        reduce_sets_.push_back(std::move(vk::raii::DescriptorSets(
            ctx_.device(), vk::DescriptorSetAllocateInfo(*pool_, reduce_layout))[0]));
        const vk::DescriptorImageInfo finer(nullptr, *mip_views_[mip - 1],
                                            executor::layout_for(graph::Use::kStorageWrite));
        const vk::DescriptorImageInfo coarser(nullptr, *mip_views_[mip],
                                              executor::layout_for(graph::Use::kStorageWrite));
        const std::array writes = {
            vk::WriteDescriptorSet(*reduce_sets_.back(), 0, 0, Type::eStorageImage, finer),
            vk::WriteDescriptorSet(*reduce_sets_.back(), 1, 0, Type::eStorageImage, coarser),
        };
        ctx_.device().updateDescriptorSets(writes, {});
    }
}

void DepthPyramidPass::set_eye_depths(vk::ImageView left, vk::ImageView right,
                                      vk::Extent2D eye_extent) {
    const vk::Extent2D blocks((eye_extent.width + 3) / 4, (eye_extent.height + 3) / 4);
    if (blocks != blocks_extent_) {
        blocks_view_ = nullptr;
        blocks_image_ = nullptr;
        blocks_memory_ = nullptr;
        blocks_extent_ = blocks;
        blocks_image_ = vk::raii::Image(
            ctx_.device(),
            vk::ImageCreateInfo({}, vk::ImageType::e2D, kFormat, vk::Extent3D(blocks, 1), 1, 2,
                                vk::SampleCountFlagBits::e1, vk::ImageTiling::eOptimal,
                                vk::ImageUsageFlagBits::eStorage, vk::SharingMode::eExclusive));
        blocks_memory_ = vk_core::allocate_memory(ctx_, blocks_image_.getMemoryRequirements(),
                                                  vk::MemoryPropertyFlagBits::eDeviceLocal);
        blocks_image_.bindMemory(*blocks_memory_, 0);
        const vk::ImageSubresourceRange layers(vk::ImageAspectFlagBits::eColor, 0, 1, 0, 2);
        blocks_view_ = vk::raii::ImageView(
            ctx_.device(), vk::ImageViewCreateInfo({}, *blocks_image_, vk::ImageViewType::e2DArray,
                                                   kFormat, {}, layers));
        vk_core::initialise_image(ctx_, blocks_image());
    }
    const std::array depths = {
        vk::DescriptorImageInfo(*nearest_, left,
                                executor::layout_for(graph::Use::kDepthSampledCompute)),
        vk::DescriptorImageInfo(*nearest_, right,
                                executor::layout_for(graph::Use::kDepthSampledCompute)),
    };
    const vk::DescriptorImageInfo blocks_info(nullptr, *blocks_view_,
                                              executor::layout_for(graph::Use::kStorageWrite));
    const std::array writes = {
        vk::WriteDescriptorSet(*merge_set_, 0, 0, vk::DescriptorType::eCombinedImageSampler,
                               depths),
        vk::WriteDescriptorSet(*merge_set_, 2, 0, vk::DescriptorType::eStorageImage, blocks_info),
        vk::WriteDescriptorSet(*merge_set_, 3, 0, vk::DescriptorType::eStorageImage, blocks_info),
    };
    ctx_.device().updateDescriptorSets(writes, {});
}

void DepthPyramidPass::record(const vk::raii::CommandBuffer& cmd, StepSync& sync,
                              const std::array<glm::dmat3, 2>& mono_to_eye,
                              const std::optional<Predicate>& when) const {
    std::array<glm::vec4, 6> rows{};
    for (int e = 0; e < 2; ++e) {
        for (int r = 0; r < 3; ++r) {
            // glm is column-major: element (row r, column c) is m[c][r].
            rows[3 * e + r] =
                glm::vec4(mono_to_eye[e][0][r], mono_to_eye[e][1][r], mono_to_eye[e][2][r], 0.0f);
        }
    }
    with_predicate(cmd, when, [&] {
        sync.next(cmd, "blocks");
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *merge_pipeline_layout_, 0,
                               *merge_set_, {});
        cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *blocks_);
        cmd.dispatch(groups_covering(blocks_extent_.width, kPyramidGroup),
                     groups_covering(blocks_extent_.height, kPyramidGroup), 2);
        sync.next(cmd, "merge");
        cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *merge_);
        cmd.pushConstants<std::array<glm::vec4, 6>>(*merge_pipeline_layout_,
                                                    vk::ShaderStageFlagBits::eCompute, 0, rows);
        cmd.dispatch(groups_covering(extent_.width, kPyramidGroup),
                     groups_covering(extent_.height, kPyramidGroup), 1);
        cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *reduce_);
        for (std::uint32_t mip = 1; mip < mips_; ++mip) {
            sync.next(cmd, "reduce");  // again, per level
            cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *reduce_pipeline_layout_, 0,
                                   *reduce_sets_[mip - 1], {});
            cmd.dispatch(groups_covering(std::max(extent_.width >> mip, 1u), kPyramidGroup),
                         groups_covering(std::max(extent_.height >> mip, 1u), kPyramidGroup), 1);
        }
    });
}

vk_core::ImageRange DepthPyramidPass::pyramid_image() const {
    return {*image_, vk::ImageAspectFlagBits::eColor,
            0,       1,
            mips_,   executor::layout_for(graph::Use::kStorageWrite)};
}

vk_core::ImageRange DepthPyramidPass::blocks_image() const {
    return {*blocks_image_,
            vk::ImageAspectFlagBits::eColor,
            0,
            2,
            1,
            executor::layout_for(graph::Use::kStorageWrite)};
}

}  // namespace monoplane::passes
