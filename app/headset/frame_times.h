// Where a headset loop's wall time goes, per displayed frame: the steps of a frame timed on the
// host, summed per frame, and reported as medians at the end of a session (docs/benchmarks.md,
// "The headset frame"). Pure and Vulkan-free.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace monoplane::headset {

// Whether the display slot before a frame went unfilled (the runtime showed the last frame
// again): predicted display times more than 1.5 display periods apart. False without a period.
bool missed_slot(std::int64_t previous_display_ns, std::int64_t display_ns, std::int64_t period_ns);

enum class FrameStep {
    kOpenXrBegin,  // xrWaitFrame, xrBeginFrame, locating the views, syncing the controls
    kSession,      // the session's logic and the observer
    kRender,       // the renderer's frame: waiting for its slot, preparing, recording, submitting
    kOpenXrEnd,    // releasing the swapchain images, xrEndFrame (simxr's dumps included)
    kLog,          // storing what was shown (SQLite)
    kWindow,       // the experimenter window
};
inline constexpr int kFrameSteps = 6;

class FrameTimes {
  public:
    // Adds to the current frame's step.
    void add(FrameStep step, double ms) { current_[static_cast<int>(step)] += ms; }
    // Closes the current frame: a scene frame (a trial's rendering) or another (neutral screen,
    // questionnaire), whose times are kept apart.
    void end_frame(bool scene);
    // The renderer's GPU time of a completed scene frame (its timestamps).
    void add_gpu_ms(double ms) { gpu_ms_.push_back(ms); }

    int scene_frames() const { return static_cast<int>(scene_.size()); }
    // The median wall time of a scene frame (its steps' sum), ms; 0 without scene frames.
    double scene_frame_ms_median() const;
    double step_ms_median(FrameStep step) const;
    double gpu_ms_median() const;
    // One paragraph for stderr: frames, medians per step, GPU time.
    std::string summary() const;

  private:
    std::array<double, kFrameSteps> current_{};
    std::vector<std::array<double, kFrameSteps>> scene_;
    int other_frames_ = 0;
    std::vector<double> gpu_ms_;
};

}  // namespace monoplane::headset
