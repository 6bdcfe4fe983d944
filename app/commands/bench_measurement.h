// One timed run of `monoplane bench`: a renderer's frames, optionally interleaved with a
// reference renderer's, reduced to GPU times per pass, pipeline statistics and time ratios.
#pragma once

#include "app/bench/bench_results.h"
#include "app/commands/bench_options.h"
#include "renderer/modes/mode_renderer.h"

namespace monoplane::app::bench {

// Warm-up frames (shader compilation, the one-off shadow map, C's allocation), then measured
// frames without read-back. With a reference renderer (stereo), its frames are interleaved with
// the measured ones (in alternating order) and the time ratio is the median of the per-pair
// ratios: a CPU rasterizer on a shared machine drifts by tens of percent over minutes, and only
// frames taken side by side compare. With o.turning_frames, turning-head pairs follow.
BenchRun measure(modes::ModeRenderer& renderer, const modes::FrameInputs& inputs,
                 const BenchOptions& o, modes::ModeRenderer* reference = nullptr,
                 const modes::FrameInputs* reference_inputs = nullptr);

}  // namespace monoplane::app::bench
