// Medians and 90th percentiles of per-frame measurements over the measured frames.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "renderer/profile/frame_stats.h"

namespace monoplane::app {

double percentile(std::vector<double> values, double fraction);

struct FrameSummary {
    int frames = 0;
    double frame_ms_median = 0.0;
    double frame_ms_p10 = 0.0;
    double frame_ms_p90 = 0.0;
    double cpu_ms_median = 0.0;
    std::map<std::string, double> pass_ms_median;  // over the frames in which the pass ran
    std::map<std::string, double> pass_ms_p10;
    std::map<std::string, double> pass_ms_p90;
    std::vector<profile::ViewStatistics> views;  // of the last frame (counters are repeatable)
};

FrameSummary summarize(const std::vector<profile::FrameStats>& frames);

}  // namespace monoplane::app
