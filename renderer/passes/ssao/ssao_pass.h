// Screen-space ambient occlusion in the style of HBAO+ (NVIDIA 2016, as summarised in papers/002
// Sect. 2), per view, and the stereo-consistent variant of Shi, Billeter and Eisemann
// (papers/002 Sect. 3): obscuration estimated over both views with the visibility test (3.1),
// the left estimate reprojected to the right eye with a back-check (3.2), and the stereo-aware
// bilateral filter (3.3).
// Reads: each view's ViewConstants (view_proj as rasterised, camera, head position and forward)
// and linear depth (metres in front of the eyes' plane, MONOPLANE_SKY_LINEAR_DEPTH for the sky).
// Writes: each view's AO image (1 = unoccluded); record_apply multiplies a view's HDR by it.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/passes/shared/step_sync.h"
#include "renderer/vk/buffer.h"
#include "renderer/vk/image.h"
#include "renderer/vk/pipeline.h"

namespace monoplane::passes {

enum class SsaoVariant {
    kPerView,           // HBAO+ estimate and a depth-aware bilateral filter in each view alone
    kStereoConsistent,  // papers/002: stereo estimate, reprojection with back-check, stereo filter
};
std::optional<SsaoVariant> parse_ssao_variant(const std::string& name);  // "per-eye", "stereo"
std::string ssao_variant_name(SsaoVariant variant);

struct SsaoParams {
    float radius = 0.75f;        // metres: radius R of the sample disk around P
    int directions = 8;          // HBAO+ directions per pixel
    int steps = 4;               // samples per direction
    float angle_bias = 0.1f;     // HBAO+ bias subtracted from the cosine term
    float strength = 1.5f;       // AO = clamp(1 - strength * mean obscuration, 0, 1)
    int filter_taps = 13;        // N of the separable bilateral filter (papers/002 Sect. 3.3)
    float sigma_min = 0.02f;     // metres: clamp of sigma = r / 3
    float sigma_max = 0.5f;      // metres
    float eta = 0.05f;           // w = smoothstep(0.5 - eta, 0.5, alpha), GLSL order
    float back_check_px = 1.0f;  // reverse reprojection accepts a round trip within this distance
};

// One view's AO state: its AO image, scratch images, descriptor sets and read-back buffer. Made by
// SsaoPass::make_view; the constants buffer and linear-depth image it reads must outlive it.
class SsaoView;

class SsaoPass {
  public:
    static constexpr vk::Format kAoFormat = vk::Format::eR32Sfloat;

    SsaoPass(const vk_core::Context& ctx, const SsaoParams& params = {});
    ~SsaoPass();
    SsaoPass(const SsaoPass&) = delete;
    SsaoPass& operator=(const SsaoPass&) = delete;

    const SsaoParams& params() const { return params_; }

    // extent: the images' size (C: its allocation). The view reads `constants` (ViewConstants)
    // and `linear_depth` (ForwardPass::kLinearDepthFormat, sampled usage).
    std::unique_ptr<SsaoView> make_view(const vk_core::Buffer& constants,
                                        const vk_core::Image& linear_depth,
                                        vk::Extent2D extent) const;

    // HBAO+ and the bilateral filter on one view alone (C in hybrid mode, or one eye). area: the
    // region drawn from the top-left corner (C: its eq. 8 viewport); pixel centres map to NDC
    // over the area. Three steps (estimate, filter-x, filter-y), each begun with sync.next(): the
    // render graph puts linear_depth in shader-read-only and the AO and scratch images in general
    // (renderer/plan/pass_steps.h, ssao_steps). step_view: "" for C's pass, whose steps are named
    // as above, or the eye ("left") whose steps the plan names "left.estimate", ...
    // skip_beyond: the estimate leaves AO 1 at pixels whose linear depth is beyond it (hybrid:
    // m + skip_margin(), where the eyes' AO is never applied and no nearer pixel's filter weighs
    // the value); the default computes every pixel.
    void record_view(const vk::raii::CommandBuffer& cmd, StepSync& sync, SsaoView& view,
                     vk::Extent2D area, float skip_beyond = kEveryPixel,
                     std::string_view step_view = "") const;
    static constexpr float kEveryPixel = 3.0e38f;
    // Metres beyond a depth at which a pixel's AO no longer reaches nearer pixels' filtered AO.
    float skip_margin() const;

    // Both eyes: kPerView is record_view on each (six steps); kStereoConsistent is papers/002
    // Sect. 3 in eight steps, one per dispatch, each over both eyes' images (visibility,
    // estimate, filter-x, filter-y, each for the left eye, then the right). Both views have the
    // same extent and area.
    void record_pair(const vk::raii::CommandBuffer& cmd, StepSync& sync, SsaoView& left,
                     SsaoView& right, vk::Extent2D area, SsaoVariant variant,
                     float skip_beyond = kEveryPixel) const;

    // hdr *= AO over the area, one step (begun with sync.next(), "apply" or, with step_view,
    // "left.apply"): hdr a colour attachment, the AO sampled. With `near_only_depth` (the eye's
    // reversed-Z depth buffer, depth-tested, read only) only where it holds near content (depth !=
    // the cleared 0): in hybrid mode the far region's AO was applied to C's image before the
    // composite.
    void record_apply(const vk::raii::CommandBuffer& cmd, StepSync& sync, const SsaoView& view,
                      const vk_core::Image& hdr, vk::Extent2D area,
                      const vk_core::Image* near_only_depth = nullptr,
                      std::string_view step_view = "") const;

    // Copies the AO image (a transfer source by then) to the view's host-visible buffer, inside
    // the read-back pass's step. ao_values() reads it after the submission completed.
    void record_readback(const vk::raii::CommandBuffer& cmd, SsaoView& view) const;

  private:
    struct Impl;
    const vk_core::Context& ctx_;
    SsaoParams params_;
    std::unique_ptr<Impl> impl_;
};

class SsaoView {
  public:
    ~SsaoView();
    const vk_core::Image& ao() const;
    // The images the estimate and filters write between them (the render graph's ao_scratch).
    std::vector<const vk_core::Image*> scratch() const;
    vk::Extent2D extent() const;
    // The host-visible buffer the read-back copies the AO image into (record_readback, or the
    // renderer's read-back pass).
    const vk_core::Buffer& readback() const;
    // The last read-back AO, row-major, extent().width * extent().height values (pixels outside
    // the area are unspecified), once a frame that copied it has completed.
    std::vector<float> ao_values() const;

  private:
    friend class SsaoPass;
    struct State;
    explicit SsaoView(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

}  // namespace monoplane::passes
