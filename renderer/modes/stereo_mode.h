// The reference: the full scene once per eye in two passes (DESIGN.md section 6, `stereo`).
// Pass order per frame: shadow (only when the light region changed), then for each eye
// forward+sky, then for each eye tonemap and readback.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "renderer/modes/view_setup.h"
#include "renderer/passes/forward/forward_pass.h"
#include "renderer/passes/shadow/shadow_pass.h"
#include "renderer/passes/tonemap/tonemap_pass.h"
#include "renderer/profile/frame_profiler.h"

namespace monoplane::modes {

struct RendererOptions {
    passes::ShadowParams shadow;
    passes::TonemapParams tonemap;
    bool read_back = true;  // copy the display images to the host (for PNGs and tests)
};

class StereoMode {
  public:
    // The scene must outlive the mode. eye_extent is the per-eye render target size.
    StereoMode(const vk_core::Context& ctx, const scenes::Scene& scene, vk::Extent2D eye_extent,
               const RendererOptions& options);
    ~StereoMode();

    // Renders one frame and waits for it; returns what it cost.
    profile::FrameStats render_frame(const StereoViewInputs& inputs);

    // The display image of the last frame (requires options.read_back).
    const RgbaImage& eye_image(Eye eye) const;

  private:
    struct EyeView;

    const vk_core::Context& ctx_;
    const scenes::Scene& scene_;
    RendererOptions options_;
    passes::SceneGeometry geometry_;
    passes::ShadowPass shadow_;
    passes::ForwardPass forward_;
    passes::TonemapPass tonemap_;
    passes::DrawList shadow_draws_;
    profile::FrameProfiler profiler_;
    vk::raii::DescriptorPool descriptor_pool_{nullptr};
    std::array<std::unique_ptr<EyeView>, 2> eyes_;
    // The shadow map is redrawn only when the region it covers moves (static scene and light).
    std::optional<glm::dmat4> shadow_light_view_proj_;
};

}  // namespace monoplane::modes
