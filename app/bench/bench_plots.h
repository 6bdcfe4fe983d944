// The figures of `monoplane bench`, per scene, in the manner of papers/000 Fig. 5: GPU time per
// pass stacked over the mono-plane distance with each configuration's frame time as a line,
// drawn primitives per view over m, and frame time against error (analytic and SSIM).
#pragma once

#include <filesystem>
#include <vector>

#include "app/bench/bench_results.h"
#include "common/result.h"

namespace monoplane::app {

// Writes <scene>_time.svg, <scene>_primitives.svg and <scene>_time_vs_error.svg into `out` for
// every scene with hybrid runs; returns the files written.
Result<std::vector<std::filesystem::path>> write_bench_plots(const BenchReport& report,
                                                             const std::filesystem::path& out);

}  // namespace monoplane::app
