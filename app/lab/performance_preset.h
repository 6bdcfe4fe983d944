// The launcher's session settings (`monoplane lab`, docs/lab.md, "Session settings"): named
// performance presets, the `study run` options each stands for, and the verdict on an estimated
// frame time against the headset's refresh rate, worded for the experimenter.
//
// A preset chooses only what `study run` lets a session choose: `--detail` (the built-in scenes'
// detail, stored with the session) and `--resolution-scale` (the eye size relative to the
// runtime's recommendation). The protocol's [render] anti_aliasing and ssao are never changed:
// participants compare images rendered with them, so the protocol fixes them and `study run` has
// no option to override them; a preset only reports them.
//
// Plain functions of their arguments: no file, no GPU, any thread, any time.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "study/protocol.h"

namespace monoplane::lab {

struct PerformancePreset {
    std::string name;         // "full", "balanced", "fast" or "minimal"
    std::string description;  // one line for the window, e.g. "the protocol's scenes, ..."
    std::string detail;       // the scene detail the session renders with
    // false: --detail replaces the protocol's [render] detail, so the built-in scenes hold fewer
    // objects than the protocol's design (the session stores the detail it used).
    bool protocol_detail = true;
    double resolution_scale = 1.0;  // of the runtime's recommended eye size
    std::string anti_aliasing;      // the protocol's [render] anti_aliasing, unchanged
    std::string ssao;               // the protocol's [render] ssao, unchanged
};

// The presets' names from the most faithful to the cheapest: "full", "balanced", "fast",
// "minimal". The launcher's default is the first.
std::span<const std::string_view> performance_preset_names();

// Every preset, in performance_preset_names()' order, resolved for `protocol`: every protocol
// allows all four. full, balanced and fast render the protocol's scenes at its detail, with eyes
// of 1, 0.7 and 0.5 times the recommended size (all, about half and a quarter of its pixels);
// minimal renders a quarter of the size (a sixteenth of the pixels) with detail "test", except
// where that changes nothing (the protocol's detail is "test" already, or every scene is a glTF
// file, which detail does not touch): then at the protocol's detail.
std::vector<PerformancePreset> presets_for(const study::Protocol& protocol);

// The preset of that name for `protocol`. Refuses an unknown name, listing the presets.
Result<PerformancePreset> preset_for(const study::Protocol& protocol, std::string_view name);

// The `study run` options the preset stands for, to append to the session's command line:
// nothing for what equals the command's defaults (the protocol's detail, scale 1), else
// {"--detail", D} and/or {"--resolution-scale", S} with S as short as it reads exactly ("0.7").
std::vector<std::string> study_run_arguments(const PerformancePreset& preset);

// An eye's image size at `scale` of the recommended size, as the OpenXR session makes its
// swapchains: each side rounded to the nearest pixel and at least 16 (the runtime's maximum
// may cap it further, which this cannot know). Recommended sizes must be positive.
struct EyeSize {
    int width = 0;
    int height = 0;
};
EyeSize scaled_eye_size(int recommended_width, int recommended_height, double scale);

// The refresh rate assumed while the runtime has not reported one (refresh_hz <= 0): the common
// rate of PC headsets.
inline constexpr double kAssumedRefreshHz = 90.0;

// One preset's estimated frame time (both eyes, ms), from a probe (frame_time_probe.h).
struct PresetEstimate {
    std::string preset;
    double frame_ms = 0.0;
};

struct FrameTimeVerdict {
    double refresh_hz = 0.0;  // the rate judged against (kAssumedRefreshHz when not reported)
    double budget_ms = 0.0;   // 1000 / refresh_hz
    double ratio = 0.0;       // frame_ms / budget_ms: above 1 the headset misses frames
    bool fits = false;        // ratio <= 1
    bool tight = false;       // fits, but above 90 % of the budget: a busier view may miss
    // The window's line, e.g. "cannot reach 90 Hz: about 180 ms per frame, 16x too slow; choose
    // 'fast' (about 9.8 ms per frame)" or "reaches 90 Hz: about 8.2 ms per frame of 11.1 ms".
    std::string text;
};

// Judges `frame_ms` (the estimate for preset `preset`, both eyes; positive and finite) against
// `refresh_hz` (<= 0: not reported, kAssumedRefreshHz assumed and the text says so). When it does
// not fit, the text names the most faithful lower preset whose estimate in `estimates` fits;
// without such estimates it names the lower presets to try; for the cheapest preset, or when
// every lower estimate misses too, it says the device cannot keep the rate. A preset of another
// name (the launcher's "custom") counts every preset as lower.
FrameTimeVerdict judge_frame_time(std::string_view preset, double frame_ms, double refresh_hz,
                                  std::span<const PresetEstimate> estimates = {});

// "8.2 ms", "11.1 ms", "180 ms", "5.5 s": a frame time as the verdicts write it (tenths below
// 100 ms, where the budgets of 72 to 144 Hz lie).
std::string format_frame_time(double ms);

}  // namespace monoplane::lab
