// What a user may set of the pass kinds written as units (RendererOptions, the commands' options),
// as the units' recorders read it (UnitFrameValues::settings): plain values, Vulkan-free, one
// member per unit that has any.
#pragma once

#include <cstdint>

#include "renderer/plan/render_choices.h"

namespace monoplane::passes {

// The tone mapping (renderer/passes/tonemap/tonemap_unit.cpp, and the composite that tone maps):
// the fragment stage's push constant, as tone_mapping.glsl reads it.
struct TonemapParams {
    float exposure = 1.0f;
};

// Temporal anti-aliasing (renderer/passes/taa/taa_unit.cpp).
struct TaaParams {
    // Weight of the history in the exponential blend (Karis: 0.9, about ten frames' memory).
    float history_weight = 0.9f;
    // The colour box grows by this factor per pixel of screen-space motion, up to one pixel
    // (papers/000 Sect. 4.5: "scale the color box according to the current screen space
    // velocities").
    float velocity_box_widening = 1.0f;
};

// The depth histogram's bins (renderer/passes/depth_histogram/depth_histogram_unit.cpp): the
// clip range they span, which `--mono-plane auto`'s chooser reads them by
// (plan::DepthHistogram::near, far).
struct DepthHistogramRange {
    double near = 0.1;
    double far = 1000.0;
};

// Screen-space ambient occlusion (renderer/passes/ssao/ssao_unit.cpp), as ssao_common.glsl
// reads it.
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

// The forward passes (renderer/passes/forward/forward_unit.cpp): what shapes their pipelines.
struct ForwardSettings {
    std::uint32_t msaa_samples = 1;  // MSAA's samples per pixel (1: none, and under TAA)
    // How the eyes' forward pass draws both eyes (plan::StereoPass::kTwoPasses: a pass each).
    plan::StereoPass stereo_pass = plan::StereoPass::kTwoPasses;
    // The benchmark's vertex-heavy configuration (forward_vertex.glsl's rounds); 0 normally.
    std::uint32_t vertex_work = 0;
};

struct UnitSettings {
    TonemapParams tonemap;
    TaaParams taa;
    DepthHistogramRange depth_histogram;
    SsaoParams ssao;
    ForwardSettings forward;
};

}  // namespace monoplane::passes
