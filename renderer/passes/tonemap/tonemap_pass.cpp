#include "renderer/passes/tonemap/tonemap_pass.h"

#include <array>

#include "renderer/executor/image_layouts.h"
#include "renderer/passes/shared/fullscreen_pass.h"

namespace monoplane::passes {
namespace {
const std::uint32_t kTonemapFrag[] = {
#include "tonemap.frag.spv.inc"
};
}  // namespace

TonemapPass::TonemapPass(const vk_core::Context& ctx) : ctx_(ctx) {
    const vk::DescriptorSetLayoutBinding binding(0, vk::DescriptorType::eCombinedImageSampler, 1,
                                                 vk::ShaderStageFlagBits::eFragment);
    set_layout_ =
        vk::raii::DescriptorSetLayout(ctx.device(), vk::DescriptorSetLayoutCreateInfo({}, binding));
    sampler_ = vk_core::make_clamped_sampler(ctx, vk::Filter::eNearest);
    const vk::DescriptorSetLayout set_layout = *set_layout_;
    const vk::PushConstantRange push(vk::ShaderStageFlagBits::eFragment, 0, sizeof(TonemapParams));
    layout_ =
        vk::raii::PipelineLayout(ctx.device(), vk::PipelineLayoutCreateInfo({}, set_layout, push));
    pipeline_ = make_fullscreen_pipeline(ctx, *layout_, kTonemapFrag, kDisplayFormat);
}

void TonemapPass::record(const vk::raii::CommandBuffer& cmd, const vk_core::Image& display,
                         vk::DescriptorSet hdr_set, const TonemapParams& params,
                         const std::optional<Predicate>& when) const {
    record_fullscreen(cmd, display, *pipeline_, *layout_, hdr_set,
                      std::as_bytes(std::span(&params, 1)), when);
}

vk_core::DescriptorSet TonemapPass::make_input(const vk_core::Image& source) const {
    const std::array sizes = {vk::DescriptorPoolSize(vk::DescriptorType::eCombinedImageSampler, 1)};
    vk_core::DescriptorSet set(ctx_, *set_layout_, sizes);
    const std::array images = {vk::DescriptorImageInfo(
        *sampler_, source.view(), executor::layout_for(graph::Use::kSampledFragment))};
    vk_core::write_sampled_images(ctx_, *set, images);
    return set;
}

}  // namespace monoplane::passes
