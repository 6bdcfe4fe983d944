// Temporal anti-aliasing of one eye (Karis 2014; Fink et al. 2019 Sect. 4.5): the frame's HDR
// image is blended with the reprojected, colour-box-clipped history of earlier frames.
// Reads (set 0): the eye's assembled HDR (binding 0), velocity (1), linear depth (2), all
// texel-exact and in eShaderReadOnlyOptimal, and the previous output (3, bilinear).
// Writes: the new output, which is the next frame's history and what tone mapping reads.
#pragma once

#include "renderer/vk/descriptor_set.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {

struct TaaParams {
    // Weight of the history in the exponential blend (Karis: 0.9, about ten frames' memory).
    float history_weight = 0.9f;
    // The colour box grows by this factor per pixel of screen-space motion, up to one pixel
    // (Sect. 4.5: "scale the color box according to the current screen space velocities").
    float velocity_box_widening = 1.0f;
};

class TaaPass {
  public:
    static constexpr vk::Format kOutputFormat = vk::Format::eR16G16B16A16Sfloat;

    explicit TaaPass(const vk_core::Context& ctx);

    // The inputs record() reads: this frame's HDR, velocity and linear depth (texel-exact) and
    // the history written last frame (bilinear), all sampled.
    vk_core::DescriptorSet make_inputs(const vk_core::Image& hdr, const vk_core::Image& velocity,
                                       const vk_core::Image& linear_depth,
                                       const vk_core::Image& history) const;

    // Writes `output` (expected in eUndefined, left in eColorAttachmentOptimal) over its whole
    // extent. reset: ignore the history (first frame, or the history belongs to another view).
    void record(const vk::raii::CommandBuffer& cmd, const vk_core::Image& output,
                vk::DescriptorSet inputs, const TaaParams& params, bool reset) const;

  private:
    const vk_core::Context& ctx_;
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::Sampler nearest_{nullptr};
    vk::raii::Sampler bilinear_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
};

}  // namespace monoplane::passes
