#include "renderer/passes/taa/taa_pass.h"

#include <array>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shared/fullscreen_pass.h"

namespace monoplane::passes {
namespace {
const std::uint32_t kTaaResolveFrag[] = {
#include "taa_resolve.frag.spv.inc"
};

struct TaaPush {
    glm::vec4 params;
    glm::vec4 extent;
};
static_assert(sizeof(TaaPush) == 32, "must match taa_resolve.frag");

}  // namespace

TaaPass::TaaPass(const vk_core::Context& ctx)
    : ctx_(ctx),
      nearest_(vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest)),
      bilinear_(vk_core::make_clamped_sampler(ctx, vk::Filter::eLinear)) {
    std::array<vk::DescriptorSetLayoutBinding, 4> bindings;
    for (std::uint32_t i = 0; i < bindings.size(); ++i) {
        bindings[i] = vk::DescriptorSetLayoutBinding(i, vk::DescriptorType::eCombinedImageSampler,
                                                     1, vk::ShaderStageFlagBits::eFragment);
    }
    set_layout_ = vk::raii::DescriptorSetLayout(ctx.device(),
                                                vk::DescriptorSetLayoutCreateInfo({}, bindings));
    const vk::DescriptorSetLayout set_layout = *set_layout_;
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0, sizeof(TaaPush));
    layout_ =
        vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, set_layout, push));
    pipeline_ = make_fullscreen_pipeline(ctx, *layout_, kTaaResolveFrag, kOutputFormat);
}

void TaaPass::record(const vk::raii::CommandBuffer& cmd, const vk_core::Image& output,
                     vk::DescriptorSet inputs, const TaaParams& params, bool reset) const {
    const vk::Extent2D extent = output.desc().extent;
    const glm::vec2 size(static_cast<float>(extent.width), static_cast<float>(extent.height));
    const TaaPush push{
        glm::vec4(params.history_weight, params.velocity_box_widening, reset ? 1.0f : 0.0f, 0.0f),
        glm::vec4(size, 1.0f / size),
    };
    record_fullscreen(cmd, output, *pipeline_, *layout_, inputs,
                      std::as_bytes(std::span(&push, 1)));
}

vk_core::DescriptorSet TaaPass::make_inputs(const vk_core::Image& hdr,
                                            const vk_core::Image& velocity,
                                            const vk_core::Image& linear_depth,
                                            const vk_core::Image& history) const {
    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 4)};
    vk_core::DescriptorSet set(ctx_, *set_layout_, sizes);
    const auto read_only = executor::layout_for(graph::Use::kSampledFragment);
    const std::array images = {
        vk::DescriptorImageInfo(*nearest_, hdr.view(), read_only),
        vk::DescriptorImageInfo(*nearest_, velocity.view(), read_only),
        vk::DescriptorImageInfo(*nearest_, linear_depth.view(), read_only),
        vk::DescriptorImageInfo(*bilinear_, history.view(), read_only),
    };
    vk_core::write_sampled_images(ctx_, *set, images);
    return set;
}

}  // namespace monoplane::passes
