// `--mono-plane auto` and its budget flags, as `render` and `bench` take them (issue 20;
// renderer/plan/mono_plane_chooser.h): --error-budget-arcmin, --budget-disparity,
// --time-budget-ms, --auto-step-arcmin.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "common/json_writer.h"
#include "renderer/plan/mono_plane_chooser.h"
#include "renderer/profile/frame_stats.h"

namespace monoplane::app {

struct AutoMonoPlaneFlags {
    double error_budget_arcmin = 6.0;
    bool disparity = false;
    std::optional<double> time_budget_ms;
    double step_arcmin = 0.25;
};

// Adds the four flags to `cmd`; when may this be called: while building the command line.
void add_auto_mono_plane_flags(CLI::App& cmd, AutoMonoPlaneFlags& flags);

// The chooser's parameters from the flags. Throws UserError naming the flag for a budget or step
// that is not a positive number.
plan::AutoMonoPlaneParams auto_mono_plane_params(const AutoMonoPlaneFlags& flags);

// A --mono-plane value: "auto", or metres. Nothing for "auto"; throws UserError naming `flag`
// for anything else that is not a positive number.
std::optional<double> parse_mono_plane_value(const std::string& flag, const std::string& text);

// "mono_plane_auto": {"error_budget_arcmin", "measure" ("eye" | "disparity"), "time_budget_ms"
// (null: none), "step_arcmin", "mono_plane_median", "mono_plane_min", "mono_plane_max" (metres;
// the far plane for frames drawn as stereo), "stereo_frames", "frames": [{"mono_plane",
// "reason"}, ...]} over the measured frames, for render's and bench's JSON.
void write_auto_mono_plane_json(JsonWriter& j, const plan::AutoMonoPlaneParams& params,
                                const std::vector<profile::FrameStats>& frames);

}  // namespace monoplane::app
