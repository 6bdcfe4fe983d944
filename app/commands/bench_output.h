// What `monoplane bench` leaves behind: bench.json's header, then bench.json, bench.csv and the
// figures of app/bench/bench_plots.h in the output directory, and a summary on stderr.
#pragma once

#include <filesystem>
#include <string>

#include "app/bench/bench_results.h"
#include "app/commands/bench_options.h"
#include "app/commands/bench_sweep.h"

namespace monoplane::app::bench {

// bench.json's header: the configuration every run shares. Once the device is known.
BenchReport empty_report(const BenchOptions& o, const std::string& device, const BenchSetup& setup);

// bench.json, bench.csv and the figures into `out` (which exists), then one line per run compared
// with stereo on stderr. After the sweep, its ratios and frontier. Throws when a figure cannot be
// written.
void write_results(const BenchReport& report, const std::filesystem::path& out);

}  // namespace monoplane::app::bench
