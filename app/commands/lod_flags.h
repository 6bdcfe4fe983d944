// --lod and --lod-error-px, as `render` and `bench` take them (bench takes a list of modes to
// sweep: "off,auto").
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "renderer/plan/lod_selection.h"

namespace monoplane::app {

struct LodFlags {
    std::string lod = "auto";
    double error_px = 0.5;
};

// Adds both flags; `list` lets --lod take a comma-separated sweep.
void add_lod_flags(CLI::App& cmd, LodFlags& flags, bool list);

// The options one --lod value asks for; throws UserError naming the flag for a bad value or a
// budget that is not a positive number of pixels.
plan::LodOptions parse_lod_flags(const std::string& lod, double error_px);
// Every entry of a comma-separated --lod, in order, without repeats.
std::vector<plan::LodOptions> parse_lod_list(const LodFlags& flags);

}  // namespace monoplane::app
