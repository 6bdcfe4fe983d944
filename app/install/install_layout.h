// Where monoplane finds the files it ships beside its executable, the same way whether it runs
// from its build folder or from an installed prefix (cmake --install, the .deb):
//
//   installed:     <prefix>/bin/monoplane     <prefix>/share/monoplane/
//   build folder:  <build>/monoplane          <build>/share/monoplane/ (made by CMake)
//
// share/monoplane holds the protocols (protocols/) and the simulated headset's OpenXR manifest
// (simxr/simxr.json, naming the runtime's library relative to itself). Nothing absolute is
// compiled in: the executable's own location (/proc/self/exe) is the only anchor, so a build or
// an installation may be moved.
//
// When may this be called: any time; reads the file system only.
#pragma once

#include <filesystem>
#include <optional>

namespace monoplane::app {

// The running executable, resolved (symbolic links followed).
std::filesystem::path executable_path();

// share/monoplane of the prefix the executable is installed in, or of the build folder it was
// built in; nullopt when neither exists (an executable copied away on its own).
std::optional<std::filesystem::path> data_folder();

// The simulated headset's runtime manifest in data_folder(), if it is there.
std::optional<std::filesystem::path> simxr_manifest();

// The protocols shipped in data_folder(), if they are there.
std::optional<std::filesystem::path> shipped_protocols();

}  // namespace monoplane::app
