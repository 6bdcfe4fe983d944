#include "app/commands/bench_output.h"

#include <fstream>
#include <iomanip>
#include <iostream>

#include "app/bench/bench_plots.h"

namespace monoplane::app::bench {
namespace {

// One line per run compared with stereo on stderr: its time and count ratios, accuracy and
// error, and for auto runs whether a fixed m beat them.
void print_run_summary(const BenchRun& run) {
    std::cerr << "  " << std::left << std::setw(10) << run.scene << std::setw(16) << run.mode
              << std::setw(15) << run.variant << " m " << std::setw(6)
              << (!run.mono_plane         ? std::string("-")
                  : run.mono_plane_auto   ? "auto~" + plane_text(*run.mono_plane)
                  : run.mono_plane_is_far ? std::string("far")
                                          : plane_text(*run.mono_plane))
              << " time " << std::fixed << std::setprecision(2) << *run.time_ratio
              << "x  primitives " << run.primitive_ratio.value_or(0.0) << "x  vertices "
              << run.vertex_invocation_ratio.value_or(0.0) << "x";
    if (run.max_channel_difference)
        std::cerr << "  max difference " << *run.max_channel_difference << "/255";
    if (run.ssim_vs_stereo) std::cerr << "  SSIM " << std::setprecision(4) << *run.ssim_vs_stereo;
    if (run.visible_error_arcmin)
        std::cerr << "  error " << std::setprecision(2) << *run.visible_error_arcmin << "'";
    if (run.on_fixed_m_frontier) {
        std::cerr << (*run.on_fixed_m_frontier ? "  on the fixed-m frontier"
                                               : "  dominated by a fixed m");
        if (!run.dominated_by.empty()) {
            std::cerr << " (" << run.dominated_beyond_spread_by.size() << " of "
                      << run.dominated_by.size() << " beyond the frame-to-frame spread)";
        }
    }
    std::cerr << std::defaultfloat << "\n";
}

}  // namespace

BenchReport empty_report(const BenchOptions& o, const std::string& device,
                         const BenchSetup& setup) {
    BenchReport report;
    report.device = device;
    report.hmd = setup.profile.name;
    report.width = static_cast<int>(setup.extent.width);
    report.height = static_cast<int>(setup.extent.height);
    report.detail = o.detail;
    report.view = o.view;
    report.seed = o.seed;
    report.anti_aliasing = o.anti_aliasing;
    report.ssao = o.ssao;
    report.vertex_work = o.vertex_work;
    report.depth_prepass = o.depth_prepass;
    report.warmup = o.warmup;
    report.frames = o.frames;
    return report;
}

void write_results(const BenchReport& report, const std::filesystem::path& out) {
    std::ofstream(out / "bench.json") << bench_json(report) << "\n";
    std::ofstream(out / "bench.csv") << bench_csv(report);
    const auto plots = write_bench_plots(report, out).value_or_throw();
    std::cerr << "wrote " << (out / "bench.json").string() << ", bench.csv and " << plots.size()
              << " figures\n";
    for (const BenchRun& run : report.runs) {
        if (!run.time_ratio || run.mode == "stereo") continue;
        print_run_summary(run);
    }
}

}  // namespace monoplane::app::bench
