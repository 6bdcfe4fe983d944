// `monoplane study probe`: the launcher's frame-time probe from the command line
// (docs/lab.md, "Session settings"), printing each performance preset's estimate and verdict as
// JSON, for whoever chooses a session's settings in a shell and for the end-to-end tests.
#pragma once

#include <CLI/CLI.hpp>

#include "app/commands/global_options.h"

namespace monoplane::app {

// Adds `probe` under `study`. Call once, while the command line is being declared.
void add_study_probe_command(CLI::App* study, const GlobalOptions& global);

}  // namespace monoplane::app
