// The output folder of a command, created (with its parents) before any work, so that nothing
// is computed and then lost to a path that cannot be written.
#pragma once

#include <filesystem>
#include <string>

namespace monoplane::app {

// Creates `path` if needed; throws UserError naming the option (e.g. "--out") otherwise.
std::filesystem::path prepare_output_directory(const std::string& option, const std::string& path);

}  // namespace monoplane::app
