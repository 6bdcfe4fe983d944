// The depth distribution of a frame's eye pixels: what `--mono-plane auto` reads to find gaps
// (depths few surfaces reach, where a mono plane cuts few of them) and how much of the image lies
// beyond a plane. Filled on the GPU (renderer/passes/depth_histogram) from both eyes' linear
// depth after the composite, so in hybrid it is the depth of what the eyes finally show.
// Plain data; Vulkan-free.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <span>

#include "renderer/plan/depth_histogram_constants.h"

namespace monoplane::plan {

struct DepthHistogram {
    static constexpr int kBins = MONOPLANE_DEPTH_HISTOGRAM_BINS;
    // Bin b holds depths in [near (far / near)^(b / kBins), near (far / near)^((b + 1) / kBins)):
    // equal ratios, since what matters about m is its ratio to the content's depth (the error
    // falls as 1/m). Depths below near count in bin 0, beyond far in the last.
    double near = 0.1;
    double far = 1000.0;
    std::array<std::uint32_t, kBins> counts{};
    std::uint32_t sky = 0;  // pixels showing the sky (nothing drawn)
    double farthest = 0.0;  // the farthest non-sky pixel's depth, metres (0: none)

    double bin_low(int bin) const { return near * std::pow(far / near, double(bin) / kBins); }
    double bin_high(int bin) const { return bin_low(bin + 1); }
    // The bin holding `depth`, clamped to [0, kBins - 1].
    int bin_of(double depth) const;
    std::uint64_t geometry_pixels() const;  // every pixel but the sky's
    // The share of geometry pixels at depths of `depth` or more (by whole bins from bin_of).
    double share_beyond(double depth) const;
};

// The histogram the GPU wrote (MONOPLANE_DEPTH_HISTOGRAM_WORDS words, depth_histogram_constants.h)
// with bins over [near, far]; `words` must hold that many.
DepthHistogram depth_histogram_of(std::span<const std::uint32_t> words, double near, double far);

}  // namespace monoplane::plan
