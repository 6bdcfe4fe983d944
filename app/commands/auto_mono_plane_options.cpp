#include "app/commands/auto_mono_plane_options.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "common/result.h"

namespace monoplane::app {

void add_auto_mono_plane_flags(CLI::App& cmd, AutoMonoPlaneFlags& flags) {
    cmd.add_option("--error-budget-arcmin", flags.error_budget_arcmin,
                   "--mono-plane auto: the largest error in visual angle (arcminutes; each eye's, "
                   "or with --budget-disparity the disparity's) any content beyond m may show")
        ->capture_default_str();
    cmd.add_flag("--budget-disparity", flags.disparity,
                 "--mono-plane auto: the budget bounds the change of binocular disparity");
    cmd.add_option("--time-budget-ms", flags.time_budget_ms,
                   "--mono-plane auto: render stereo while the estimated stereo frame (GPU ms) "
                   "fits in this; without it, hybrid whenever it saves time");
    cmd.add_option("--auto-step-arcmin", flags.step_arcmin,
                   "--mono-plane auto: the far content's largest apparent shift per frame when m "
                   "moves (arcminutes)")
        ->capture_default_str();
}

plan::AutoMonoPlaneParams auto_mono_plane_params(const AutoMonoPlaneFlags& flags) {
    auto positive = [](double value) { return std::isfinite(value) && value > 0.0; };
    if (!positive(flags.error_budget_arcmin)) {
        throw UserError("--error-budget-arcmin must be a positive number of arcminutes");
    }
    if (!positive(flags.step_arcmin)) {
        throw UserError("--auto-step-arcmin must be a positive number of arcminutes");
    }
    if (flags.time_budget_ms && !positive(*flags.time_budget_ms)) {
        throw UserError("--time-budget-ms must be a positive number of milliseconds");
    }
    plan::AutoMonoPlaneParams params;
    params.error_budget_arcmin = flags.error_budget_arcmin;
    params.measure = flags.disparity ? rig::ErrorMeasure::kDisparity : rig::ErrorMeasure::kEye;
    params.time_budget_ms = flags.time_budget_ms;
    params.max_step_arcmin = flags.step_arcmin;
    return params;
}

std::optional<double> parse_mono_plane_value(const std::string& flag, const std::string& text) {
    if (text == "auto") return std::nullopt;
    char* end = nullptr;
    const double metres = std::strtod(text.c_str(), &end);
    if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(metres) ||
        metres <= 0.0) {
        throw UserError(flag + " " + text + ": give a distance in metres or auto");
    }
    return metres;
}

void write_auto_mono_plane_json(JsonWriter& j, const plan::AutoMonoPlaneParams& params,
                                const std::vector<profile::FrameStats>& frames) {
    std::vector<double> planes;
    for (const profile::FrameStats& f : frames) {
        if (f.mono_plane) planes.push_back(*f.mono_plane);
    }
    std::vector<double> sorted = planes;
    std::sort(sorted.begin(), sorted.end());
    const double nan = std::numeric_limits<double>::quiet_NaN();  // written null
    j.begin_object("mono_plane_auto");
    j.value("error_budget_arcmin", params.error_budget_arcmin);
    j.value("measure", params.measure == rig::ErrorMeasure::kEye ? "eye" : "disparity");
    j.value("time_budget_ms", params.time_budget_ms.value_or(nan));
    j.value("step_arcmin", params.max_step_arcmin);
    j.value("mono_plane_median", sorted.empty() ? nan : sorted[sorted.size() / 2]);
    j.value("mono_plane_min", sorted.empty() ? nan : sorted.front());
    j.value("mono_plane_max", sorted.empty() ? nan : sorted.back());
    const auto stereo = std::count_if(frames.begin(), frames.end(), [](const auto& f) {
        return f.mono_plane_reason.rfind("stereo", 0) == 0;
    });
    j.value("stereo_frames", static_cast<std::int64_t>(stereo));
    j.begin_array("frames");
    for (const profile::FrameStats& f : frames) {
        j.begin_object();
        j.value("mono_plane", f.mono_plane.value_or(nan)).value("reason", f.mono_plane_reason);
        j.end_object();
    }
    j.end_array();
    j.end_object();
}

}  // namespace monoplane::app
