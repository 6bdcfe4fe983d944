#include "app/commands/frame_summary.h"

#include <algorithm>
#include <cmath>

namespace monoplane::app {

double percentile(std::vector<double> values, double fraction) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    // Linear interpolation between closest ranks (R's type 7, numpy's default).
    const double rank = fraction * static_cast<double>(values.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(rank));
    const std::size_t hi = std::min(lo + 1, values.size() - 1);
    return values[lo] + (rank - static_cast<double>(lo)) * (values[hi] - values[lo]);
}

FrameSummary summarize(const std::vector<profile::FrameStats>& frames) {
    FrameSummary summary;
    summary.frames = static_cast<int>(frames.size());
    std::vector<double> gpu;
    std::vector<double> cpu;
    std::map<std::string, std::vector<double>> passes;
    for (const profile::FrameStats& f : frames) {
        gpu.push_back(f.gpu_frame_ms);
        cpu.push_back(f.cpu_record_ms);
        for (const profile::PassTime& p : f.passes) passes[p.name].push_back(p.gpu_ms);
    }
    summary.frame_ms_median = percentile(gpu, 0.5);
    summary.frame_ms_p10 = percentile(gpu, 0.1);
    summary.frame_ms_p90 = percentile(gpu, 0.9);
    summary.cpu_ms_median = percentile(cpu, 0.5);
    for (auto& [name, times] : passes) {
        summary.pass_ms_median[name] = percentile(times, 0.5);
        summary.pass_ms_p10[name] = percentile(times, 0.1);
        summary.pass_ms_p90[name] = percentile(times, 0.9);
    }
    if (!frames.empty()) summary.views = frames.back().views;
    return summary;
}

}  // namespace monoplane::app
