#include "app/headset/frame_times.h"

#include <algorithm>
#include <cstdio>
#include <numeric>

namespace monoplane::headset {
namespace {

double median(std::vector<double> values) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const std::size_t n = values.size();
    return n % 2 == 1 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

constexpr std::array<const char*, kFrameSteps> kStepNames = {"OpenXR begin", "session", "render",
                                                             "OpenXR end",   "log",     "window"};

}  // namespace

bool missed_slot(std::int64_t previous_display_ns, std::int64_t display_ns,
                 std::int64_t period_ns) {
    if (period_ns <= 0) return false;
    return 2 * (display_ns - previous_display_ns) > 3 * period_ns;
}

void FrameTimes::end_frame(bool scene) {
    if (scene) {
        scene_.push_back(current_);
    } else {
        ++other_frames_;
    }
    current_.fill(0.0);
}

double FrameTimes::scene_frame_ms_median() const {
    std::vector<double> totals;
    for (const auto& frame : scene_)
        totals.push_back(std::accumulate(frame.begin(), frame.end(), 0.0));
    return median(totals);
}

double FrameTimes::step_ms_median(FrameStep step) const {
    std::vector<double> values;
    for (const auto& frame : scene_) values.push_back(frame[static_cast<int>(step)]);
    return median(values);
}

double FrameTimes::gpu_ms_median() const {
    return median(gpu_ms_);
}

std::string FrameTimes::summary() const {
    char line[160];
    std::snprintf(line, sizeof(line),
                  "headset frames: %d of scenes, %d others; a scene frame took %.1f ms of wall "
                  "time (median), the GPU %.1f ms of it (timestamps)\n",
                  scene_frames(), other_frames_, scene_frame_ms_median(), gpu_ms_median());
    std::string text = line;
    text += "  medians per step:";
    for (int s = 0; s < kFrameSteps; ++s) {
        std::snprintf(line, sizeof(line), " %s %.1f ms%s", kStepNames[static_cast<std::size_t>(s)],
                      step_ms_median(static_cast<FrameStep>(s)), s + 1 < kFrameSteps ? "," : "\n");
        text += line;
    }
    return text;
}

}  // namespace monoplane::headset
