#include "renderer/passes/depth_histogram/depth_histogram_pass.h"

#include <bit>
#include <cmath>
#include <cstring>

#include "common/programming_error.h"
#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shared/dispatch_groups.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {
namespace {

const std::uint32_t kDepthHistogram[] = {
#include "depth_histogram.comp.spv.inc"
};

// The pixels one workgroup counts along x and y: the shader's local size (16) times the block each
// invocation counts (kBlock, 4).
constexpr std::uint32_t kHistogramGroup = 16 * 4;
constexpr vk::DeviceSize kBytes = MONOPLANE_DEPTH_HISTOGRAM_WORDS * sizeof(std::uint32_t);

struct Push {
    float log_near;
    float bins_per_log_unit;
    std::uint32_t width, height;
};

}  // namespace

DepthHistogramPass::DepthHistogramPass(const vk_core::Context& ctx, std::uint32_t slots,
                                       double near, double far)
    : ctx_(ctx), near_(near), far_(far) {
    MONOPLANE_EXPECTS(near > 0.0 && far > near && slots > 0);
    nearest_ = vk::raii::Sampler(
        ctx.device(),
        vk::SamplerCreateInfo({}, vk::Filter::eNearest, vk::Filter::eNearest,
                              vk::SamplerMipmapMode::eNearest, vk::SamplerAddressMode::eClampToEdge,
                              vk::SamplerAddressMode::eClampToEdge,
                              vk::SamplerAddressMode::eClampToEdge));
    const auto compute = vk::ShaderStageFlagBits::eCompute;
    const std::array bindings = {
        vk::DescriptorSetLayoutBinding(0, vk::DescriptorType::eCombinedImageSampler, 1, compute),
        vk::DescriptorSetLayoutBinding(1, vk::DescriptorType::eStorageBuffer, 1, compute),
    };
    set_layout_ = vk::raii::DescriptorSetLayout(ctx.device(),
                                                vk::DescriptorSetLayoutCreateInfo({}, bindings));
    const vk::PushConstantRange push(compute, 0, sizeof(Push));
    const vk::DescriptorSetLayout set_layout = *set_layout_;
    layout_ =
        vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, set_layout, push));
    const vk::raii::ShaderModule shader = vk_core::make_shader(ctx, kDepthHistogram);
    pipeline_ = vk_core::make_compute_pipeline(ctx, *layout_, *shader);
    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1),
                              vk::DescriptorPoolSize(vk::DescriptorType::eStorageBuffer, 1)};
    for (std::uint32_t s = 0; s < slots; ++s) {
        buffers_.emplace_back(
            ctx, kBytes,
            vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eTransferDst,
            vk_core::MemoryUse::kHostVisible);
        sets_.push_back({vk_core::DescriptorSet(ctx, *set_layout_, sizes),
                         vk_core::DescriptorSet(ctx, *set_layout_, sizes)});
    }
}

void DepthHistogramPass::set_eye_depths(std::array<vk::ImageView, 2> linear_depth,
                                        vk::Extent2D eye_extent) {
    extent_ = eye_extent;
    for (std::size_t s = 0; s < sets_.size(); ++s) {
        for (std::size_t e = 0; e < 2; ++e) {
            const vk::DescriptorImageInfo image(*nearest_, linear_depth[e],
                                                executor::layout_for(graph::Use::kSampledCompute));
            const vk::DescriptorBufferInfo buffer(buffers_[s].handle(), 0, kBytes);
            const std::array writes = {
                vk::WriteDescriptorSet(*sets_[s][e], 0, 0,
                                       vk::DescriptorType::eCombinedImageSampler, image),
                vk::WriteDescriptorSet(*sets_[s][e], 1, 0, vk::DescriptorType::eStorageBuffer, {},
                                       buffer)};
            ctx_.device().updateDescriptorSets(writes, {});
        }
    }
}

void DepthHistogramPass::record(const vk::raii::CommandBuffer& cmd, StepSync& sync,
                                std::uint32_t slot) const {
    MONOPLANE_EXPECTS(slot < buffers_.size() && extent_.width > 0);
    sync.next(cmd, "clear");
    cmd.fillBuffer(buffers_[slot].handle(), 0, kBytes, 0u);
    sync.next(cmd, "count");
    cmd.bindPipeline(vk::PipelineBindPoint::eCompute, *pipeline_);
    const Push push{static_cast<float>(std::log(near_)),
                    static_cast<float>(MONOPLANE_DEPTH_HISTOGRAM_BINS / std::log(far_ / near_)),
                    extent_.width, extent_.height};
    cmd.pushConstants<Push>(*layout_, vk::ShaderStageFlagBits::eCompute, 0, push);
    for (const vk_core::DescriptorSet& set : sets_[slot]) {
        cmd.bindDescriptorSets(vk::PipelineBindPoint::eCompute, *layout_, 0, *set, {});
        cmd.dispatch(groups_covering(extent_.width, kHistogramGroup),
                     groups_covering(extent_.height, kHistogramGroup), 1);
    }
}

plan::DepthHistogram DepthHistogramPass::result(std::uint32_t slot) const {
    MONOPLANE_EXPECTS(slot < buffers_.size());
    std::array<std::uint32_t, MONOPLANE_DEPTH_HISTOGRAM_WORDS> words{};
    std::memcpy(words.data(), buffers_[slot].mapped(), kBytes);
    plan::DepthHistogram histogram;
    histogram.near = near_;
    histogram.far = far_;
    for (int b = 0; b < plan::DepthHistogram::kBins; ++b) {
        histogram.counts[static_cast<std::size_t>(b)] = words[static_cast<std::size_t>(b)];
    }
    histogram.sky = words[MONOPLANE_DEPTH_HISTOGRAM_SKY_WORD];
    histogram.farthest = std::bit_cast<float>(words[MONOPLANE_DEPTH_HISTOGRAM_FARTHEST_WORD]);
    return histogram;
}

}  // namespace monoplane::passes
