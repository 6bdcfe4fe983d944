// `monoplane bench`: sweeps scenes x modes x variants x mono planes,
// measures GPU time per pass, pipeline statistics and each hybrid configuration's accuracy
// against stereo, and writes bench.json, bench.csv and the figures of app/bench/bench_plots.h.
// Speed is reported as ratios to stereo within one run.
//
// The parts: its flags (bench_options.h), the sweep they ask for (bench_sweep.h), the runs of
// each scene (bench_scene.h, bench_auto_plane.cpp), one timed run (bench_measurement.h), the
// accuracy against stereo (bench_accuracy.h), the progress line (bench_progress.h) and the files
// and summary it writes (bench_output.h).
#include <filesystem>
#include <iostream>
#include <memory>

#include <unistd.h>

#include "app/bench/bench_results.h"
#include "app/commands/bench_options.h"
#include "app/commands/bench_output.h"
#include "app/commands/bench_progress.h"
#include "app/commands/bench_scene.h"
#include "app/commands/bench_sweep.h"
#include "app/commands/commands.h"
#include "app/commands/output_directory.h"
#include "app/commands/validation_report.h"
#include "renderer/vk/context.h"

namespace monoplane::app {
namespace bench {
namespace {

void run_bench(const BenchOptions& o, const GlobalOptions& global) {
    const BenchSweep sweep = parse_sweep(o);
    const std::filesystem::path out = prepare_output_directory("--out", o.out);
    const BenchSetup setup = prepare_setup(o, sweep);
    auto ctx = vk_core::Context::create(global.context_options()).value_or_throw();
    std::cerr << "device: " << ctx->device_info().name << "\n";

    BenchReport report = empty_report(o, ctx->device_info().name, setup);
    SweepState state{o, sweep, setup, *ctx, report, Progress(count_runs(sweep, setup.planes))};
    for (const SceneSource& source : sweep.scene_sources) bench_scene(state, source);
    state.show("done");
    if (isatty(2)) std::cerr << "\n";

    add_ratios_to_stereo(report);
    mark_auto_frontier(report);
    write_results(report, out);
    fail_on_validation_messages(*ctx, global);
}

}  // namespace
}  // namespace bench

void add_bench_command(CLI::App& root, const GlobalOptions& global) {
    auto options = std::make_shared<bench::BenchOptions>();
    CLI::App* cmd = root.add_subcommand(
        "bench", "Measure time, primitives and accuracy over scenes x modes x mono planes");
    bench::add_bench_options(*cmd, *options);
    cmd->callback([options, &global] { bench::run_bench(*options, global); });
}

}  // namespace monoplane::app
