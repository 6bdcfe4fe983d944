// Hybrid against stereo on rendered images (Fink et al. 2019, Sect. 5.2 and Fig. 6): SSIM per
// eye and local-SSIM heat maps, written next to the hybrid rendering.
#pragma once

#include <algorithm>
#include <array>
#include <filesystem>

#include "renderer/modes/mode_renderer.h"

namespace monoplane::app {

struct EyeComparison {
    double ssim = 0.0;               // Gaussian 11x11 window (Wang et al. 2004), whole image
    double ssim_local_w4 = 0.0;      // 9x9 box window, the paper's "local SSIM (w = 4)"
    double ssim_beyond_plane = 0.0;  // Gaussian, only pixels whose stereo depth is beyond m
    std::size_t pixels_beyond_plane = 0;
    // The largest difference of any channel of any pixel, in 8-bit levels: 0 or 1 where the mode
    // draws what stereo draws (single-pass stereo).
    int max_channel_difference = 0;
};

struct StereoComparison {
    std::array<EyeComparison, 2> eyes;
    double ssim_mean() const { return 0.5 * (eyes[0].ssim + eyes[1].ssim); }
    int max_channel_difference() const {
        return std::max(eyes[0].max_channel_difference, eyes[1].max_channel_difference);
    }
};

// Renders the reference (stereo, two passes) with the same inputs as `hybrid`'s last frame (any
// mode's: single-pass stereo too) and compares.
// Writes ssim_heat_{left,right}.png ((1 - SSIM) x 10, inferno) and ssim_{left,right}.png (the
// heat map over the hybrid image). May be called after hybrid.render_frame(inputs).
StereoComparison compare_with_stereo(const vk_core::Context& ctx, const scenes::Scene& scene,
                                     vk::Extent2D extent, const modes::RendererOptions& options,
                                     const modes::FrameInputs& inputs,
                                     const modes::ModeRenderer& hybrid,
                                     const std::filesystem::path& out);

}  // namespace monoplane::app
