// HDR -> 8-bit sRGB display image for one view (tone_mapping.glsl, which the composite that
// writes the display image itself shares).
// Reads: the HDR image (set 0, binding 0, texel-exact). Writes: the display image.
#pragma once

#include <optional>

#include "renderer/passes/shared/indirect_draws.h"
#include "renderer/vk/descriptor_set.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {

struct TonemapParams {
    float exposure = 1.0f;
};

class TonemapPass {
  public:
    static constexpr vk::Format kDisplayFormat = vk::Format::eR8G8B8A8Srgb;

    explicit TonemapPass(const vk_core::Context& ctx);

    // The set record() reads `source` (kHdrFormat: an HDR image or the TAA unit's resolve, sampled) through.
    vk_core::DescriptorSet make_input(const vk_core::Image& source) const;

    // Expects the HDR image bound in hdr_set to be in eShaderReadOnlyOptimal and `display` in
    // eColorAttachmentOptimal; overwrites all of it. With `when` the GPU may skip the draw: the
    // display image is then loaded and kept as an earlier pass wrote it (the composite that
    // writes the display image itself, in a frame whose C had something to draw).
    void record(const vk::raii::CommandBuffer& cmd, const vk_core::Image& display,
                vk::DescriptorSet hdr_set, const TonemapParams& params,
                const std::optional<Predicate>& when = std::nullopt) const;

  private:
    const vk_core::Context& ctx_;
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::Sampler sampler_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline pipeline_{nullptr};
};

}  // namespace monoplane::passes
