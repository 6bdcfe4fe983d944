// Each CLI command registers itself on the root CLI::App; main() only dispatches.
#pragma once

#include <CLI/CLI.hpp>

#include "app/commands/global_options.h"

namespace monoplane::app {

void add_render_command(CLI::App& root, const GlobalOptions& global);
void add_devices_command(CLI::App& root, const GlobalOptions& global);
void add_rig_command(CLI::App& root, const GlobalOptions& global);
void add_protocol_command(CLI::App& root, const GlobalOptions& global);
void add_study_command(CLI::App& root, const GlobalOptions& global);
void add_bench_command(CLI::App& root, const GlobalOptions& global);
void add_analyze_command(CLI::App& root, const GlobalOptions& global);
void add_simulate_command(CLI::App& root, const GlobalOptions& global);
void add_simulate_threshold_command(CLI::App& root, const GlobalOptions& global);
void add_lab_command(CLI::App& root, const GlobalOptions& global);

}  // namespace monoplane::app
