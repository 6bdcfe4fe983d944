// Screen-space ambient occlusion in the style of HBAO+ (NVIDIA 2016, as summarised in papers/002
// Sect. 2), per view, and the stereo-consistent variant of Shi, Billeter and Eisemann
// (papers/002 Sect. 3): obscuration estimated over both views with the visibility test (3.1),
// the left estimate reprojected to the right eye with a back-check (3.2), and the stereo-aware
// bilateral filter (3.3).
// Reads: each view's ViewConstants (view_proj as rasterised, camera, head position and forward)
// and linear depth (metres in front of the eyes' plane, MONOPLANE_SKY_LINEAR_DEPTH for the sky).
// Writes: each view's AO image (1 = unoccluded); apply() multiplies a view's HDR by it.
//
// The pipelines and their dispatches, one step's commands each. Which steps a frame runs, in
// what order and over which images, is the SSAO unit's (ssao_unit.cpp, ssao_steps.h); no
// function here begins a step or records a barrier.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "renderer/passes/shared/unit_settings.h"
#include "renderer/passes/ssao/ssao_steps.h"
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

// One view's AO images: the AO itself, the scratch images the estimate and the filters write
// between them, and the host-visible buffer a read-back copies the AO into. A view's, as its
// colour and depth are (the renderer makes one per view with SSAO); initialised so that a frame
// may begin reading them: scratch in general, the AO 1 everywhere (outside the area it stays so),
// shader-readable as if a frame had computed it.
class SsaoImages {
  public:
    static constexpr vk::Format kAoFormat = vk::Format::eR32Sfloat;

    // extent: the view's images' size (C: its allocation).
    SsaoImages(const vk_core::Context& ctx, vk::Extent2D extent);

    const vk_core::Image& ao() const { return ao_; }
    // The render graph's ao_scratch, in the order SsaoBindings takes them: the raw estimate, the
    // horizontal filter's output, the visibility map L.
    std::vector<const vk_core::Image*> scratch() const {
        return {&raw_, &filtered_x_, &other_pixel_};
    }
    vk::Extent2D extent() const { return ao_.desc().extent; }
    const vk_core::Buffer& readback() const { return readback_; }
    // The last read-back AO, row-major, extent().width * extent().height values (pixels outside
    // the area are unspecified), once a frame that copied it has completed.
    std::vector<float> ao_values() const;

  private:
    vk_core::Image raw_;
    vk_core::Image filtered_x_;
    vk_core::Image other_pixel_;
    vk_core::Image ao_;
    vk_core::Buffer readback_;
};

// What one view's dispatches and apply read and write: its constants, its linear depth
// (ForwardPass::kLinearDepthFormat, sampled usage) and its SSAO images, each as the step that
// uses it declared it (the render graph puts linear_depth in shader-read-only and the AO and
// scratch images in general while computing; the AO in shader-read-only when applied).
struct SsaoViewImages {
    const vk_core::Buffer* constants = nullptr;  // ViewConstants
    const vk_core::Image* linear_depth = nullptr;
    const vk_core::Image* ao = nullptr;
    std::vector<const vk_core::Image*> scratch;  // as SsaoImages::scratch()
};

// One view's descriptor sets (the compute shaders' bindings and the apply's sampled AO), each
// with a pool of its own; SsaoPass::bind points them at a view's images. Rewrite only while no
// submitted frame that reads them is pending.
class SsaoBindings {
  private:
    friend class SsaoPass;
    vk::raii::DescriptorPool pool_{nullptr};
    vk::raii::DescriptorSet compute_set_{nullptr};  // ssao_common.glsl's bindings of one view
    vk::raii::DescriptorSet apply_set_{nullptr};    // the AO, sampled
};

class SsaoPass {
  public:
    explicit SsaoPass(const vk_core::Context& ctx);
    ~SsaoPass();
    SsaoPass(const SsaoPass&) = delete;
    SsaoPass& operator=(const SsaoPass&) = delete;

    std::unique_ptr<SsaoBindings> make_bindings() const;
    // Points `bindings` at `images` (all set, of one extent).
    void bind(SsaoBindings& bindings, const SsaoViewImages& images) const;

    // One compute step (ssao_steps.h's dispatches but kApply) over `area` of `self`, with `other`
    // the other eye's bindings in the stereo dispatches (`self` again in the per-view ones). area:
    // the region drawn from the top-left corner (C: its eq. 8 viewport); pixel centres map to NDC
    // over the area. skip_beyond: the estimate leaves AO 1 at pixels whose linear depth is beyond
    // it (hybrid: m + skip_margin(), where the eyes' AO is never applied and no nearer pixel's
    // filter weighs the value); kEveryPixel computes every pixel.
    void dispatch(const vk::raii::CommandBuffer& cmd, ssao::Dispatch dispatch,
                  const SsaoBindings& self, const SsaoBindings& other, vk::Extent2D area,
                  const SsaoParams& params, float skip_beyond = kEveryPixel) const;
    static constexpr float kEveryPixel = 3.0e38f;
    // Metres beyond a depth at which a pixel's AO no longer reaches nearer pixels' filtered AO.
    static float skip_margin(const SsaoParams& params);

    // hdr *= AO over the area (ssao::Dispatch::kApply): hdr a colour attachment, the AO sampled.
    // With `near_only_depth` (the eye's reversed-Z depth buffer, depth-tested, read only) only
    // where it holds near content (depth != the cleared 0): in hybrid mode the far region's AO
    // was applied to C's image before the composite.
    void apply(const vk::raii::CommandBuffer& cmd, const SsaoBindings& view,
               const vk_core::Image& hdr, vk::Extent2D area,
               const vk_core::Image* near_only_depth = nullptr) const;

  private:
    struct Impl;
    const vk_core::Context& ctx_;
    std::unique_ptr<Impl> impl_;
};

}  // namespace monoplane::passes
