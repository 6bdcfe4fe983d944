// How close `monoplane bench`'s configurations draw to the stereo reference: its images and depth
// read back once per scene, then SSIM, mean and largest channel difference and drift against it.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "renderer/modes/mode_renderer.h"

namespace monoplane::app::bench {

// The stereo reference's images and depth, for the accuracy of every hybrid configuration.
struct Reference {
    std::array<modes::RgbaImage, 2> images;
    std::array<std::vector<float>, 2> depth;
};

struct Accuracy {
    double ssim = 0.0;
    double mean_abs_difference = 0.0;  // 8-bit levels, mean of both eyes
    double drift_px = 0.0;
    std::size_t drift_patches = 0;
};

// One frame's images and linear depth, read back. Leaves read-back off.
Reference read_reference(modes::ModeRenderer& stereo, const modes::FrameInputs& inputs);

// Single-pass stereo against two-pass stereo: the largest channel difference of either eye.
// Renders one frame with read-back.
int max_channel_difference(modes::ModeRenderer& renderer, const modes::FrameInputs& inputs,
                           const Reference& reference);

// Renders one frame with read-back and compares both eyes with the reference. beyond_m: where the
// drift is measured (stereo's pixels beyond it); inputs.mono_plane unless the renderer chooses m
// itself.
Accuracy measure_accuracy(modes::ModeRenderer& renderer, const modes::FrameInputs& inputs,
                          const Reference& reference, std::optional<double> beyond_m = {});

// The farthest depth either eye of the stereo reference shows (the sky left out): no pixel a
// configuration shows lies beyond it, so the error there bounds every visible pixel's.
double farthest_visible_depth(const Reference& reference);

}  // namespace monoplane::app::bench
