// The mono-to-stereo composite of one eye (Fink et al. 2019, Sect. 4.2; papers/003 for the
// engine-style copy). Reads: C's HDR and linear depth (set 0). Writes: the eye's HDR and linear
// depth where its depth buffer still holds the cleared far value (no near content), or
// everywhere for the debug view "mono only"; with velocity (TAA) also C's velocity through eq. 9
// (set 0, binding 2, read texel-exact).
// record_display is the same composite fused with the eye's tone mapping, for frames in which
// nothing else reads the eye's HDR image (renderer/plan/frame_plan.h, PlannedPass::
// writes_display): one full-screen pass writes the eye's display image whole, C's colour tone
// mapped where the eye drew nothing and the eye's own HDR colour (set 1) tone mapped elsewhere,
// and C's linear depth where the eye drew nothing.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include <optional>

#include "renderer/passes/shared/display_format.h"
#include "renderer/passes/shared/indirect_draws.h"
#include "renderer/passes/shared/unit_settings.h"
#include "renderer/vk/descriptor_set.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {

enum class CompositeMapping {
    kProjective = 0,  // through M_{E->C} at the mono plane, bilinear: monoplane's hybrid
    kOffsetCopy = 1,  // a constant integer pixel offset, nearest: the engine-style far field
    kNothing = 2,     // leave the far region black (debug view "stereo only")
};

struct CompositeParams {
    glm::mat4 eye_to_mono{1.0f};      // M_{E->C}, float32 as the GPU uses it
    glm::vec2 uv_scale{1.0f};         // C's viewport / allocation (eq. 8)
    glm::vec2 mono_allocation{1.0f};  // C's image size in pixels
    glm::ivec2 pixel_offset{0};       // for kOffsetCopy
    // C's NDC velocity -> the eye's (diagonal): 1/2 S of eq. 9 for kProjective, C's size over
    // the eye's for kOffsetCopy. Used with CompositePass's velocity output (TAA).
    glm::vec2 velocity_scale{1.0f};
    CompositeMapping mapping = CompositeMapping::kProjective;
    float tint = 0.0f;              // debug view "mono region tinted": 0 off, 1 full
    bool cover_all_pixels = false;  // debug view "mono only": ignore the near content
    // Skips the draw (the pass records no work) when C had nothing to draw: the eyes drew the
    // sky themselves.
    std::optional<Predicate> when;
};

struct CompositeTargets {
    const vk_core::Image& hdr;                 // eye HDR, eColorAttachmentOptimal
    const vk_core::Image& linear_depth;        // eye linear depth, eColorAttachmentOptimal
    const vk_core::Image& depth;               // eye depth, eDepthAttachmentOptimal (read only)
    const vk_core::Image* velocity = nullptr;  // eye velocity; required with `velocity`
};

// The targets of record_display (the eye's HDR image is read through make_eye_input's set).
struct CompositeDisplayTargets {
    const vk_core::Image& display;       // kDisplayFormat, written whole
    const vk_core::Image& linear_depth;  // eye linear depth, eColorAttachmentOptimal
    const vk_core::Image& depth;         // eye depth, eDepthAttachmentOptimal (read only)
};

class CompositePass {
  public:
    // display: also make the pipelines of record_display (never with velocity: TAA reads the
    // eye's HDR image after the composite, so its tone mapping stays a pass of its own).
    CompositePass(const vk_core::Context& ctx, bool velocity = false, bool display = false);

    bool writes_display() const { return static_cast<bool>(*display_layout_); }

    // The set record() reads C through: its HDR (bilinear), linear depth (texel-exact) and, in a
    // pass made with velocity, its velocity (required then), all sampled.
    vk_core::DescriptorSet make_source(const vk_core::Image& mono_hdr,
                                       const vk_core::Image& mono_linear_depth,
                                       const vk_core::Image* mono_velocity = nullptr) const;

    // Appends to the eye's targets (their contents are kept).
    void record(const vk::raii::CommandBuffer& cmd, const CompositeTargets& targets,
                vk::DescriptorSet mono_set, const CompositeParams& params) const;

    // The set record_display reads the eye's HDR image (sampled, texel-exact) through. Needs
    // writes_display().
    vk_core::DescriptorSet make_eye_input(const vk_core::Image& eye_hdr) const;

    // The composite and the eye's tone mapping in one pass: writes every pixel of the display
    // image once (tone mapped with `tonemap`, as the tone mapping does) and C's linear depth where
    // the eye drew nothing; the eye's HDR image is only read. With params.when the GPU may skip
    // both draws: the display image is then undefined, and the eye's tone mapping must write it.
    // Needs writes_display().
    void record_display(const vk::raii::CommandBuffer& cmd, const CompositeDisplayTargets& targets,
                        vk::DescriptorSet mono_set, vk::DescriptorSet eye_set,
                        const CompositeParams& params, const TonemapParams& tonemap) const;

  private:
    void make_display_pipelines(const vk_core::GraphicsPipelineDesc& composite_desc);
    // The push constants of both record functions.
    void push(const vk::raii::CommandBuffer& cmd, vk::PipelineLayout layout, vk::Extent2D extent,
              const CompositeParams& params, float exposure) const;

    const vk_core::Context& ctx_;
    bool velocity_;
    vk::raii::DescriptorSetLayout set_layout_{nullptr};
    vk::raii::Sampler bilinear_{nullptr};
    vk::raii::Sampler nearest_{nullptr};
    vk::raii::PipelineLayout layout_{nullptr};
    vk::raii::Pipeline behind_near_content_{nullptr};  // depth test: equal to the cleared far
    vk::raii::Pipeline everywhere_{nullptr};
    // record_display: set 0 C's images as above, set 1 the eye's HDR image.
    vk::raii::DescriptorSetLayout eye_set_layout_{nullptr};
    vk::raii::PipelineLayout display_layout_{nullptr};
    vk::raii::Pipeline display_behind_near_content_{nullptr};
    vk::raii::Pipeline display_everywhere_{nullptr};
    vk::raii::Pipeline near_display_{nullptr};  // depth not equal to the cleared far value
};

}  // namespace monoplane::passes
