// select_simulated_runtime (study_headset.h) in a file of its own, so that what needs only to
// point the loader at simxr (the launcher's headset probe and check) links without the study's
// session loop.
#include <unistd.h>
#include <filesystem>
#include <fstream>

#include "app/commands/study_headset.h"
#include "common/result.h"

#ifndef MONOPLANE_SIMXR_MANIFEST
#error "MONOPLANE_SIMXR_MANIFEST must name the simulated runtime's manifest"
#endif

namespace monoplane::app {

namespace fs = std::filesystem;

std::optional<fs::path> select_simulated_runtime(const HeadsetStudyOptions& options) {
    // The simulated runtime, whatever runtime the machine has active: a dry run must never
    // reach a real headset.
    setenv("XR_RUNTIME_JSON", MONOPLANE_SIMXR_MANIFEST, 1);
    if (!options.sim_script.empty()) {
        if (!fs::exists(options.sim_script)) {
            throw UserError("--sim-script " + options.sim_script + ": no such file");
        }
        setenv("SIMXR_SCRIPT", fs::absolute(options.sim_script).c_str(), 1);
        return std::nullopt;
    }
    // A built-in profile name stays a name; a file is made absolute, as the script's relative
    // paths are read against the script's folder.
    std::string hmd = options.hmd;
    if (fs::exists(hmd) && fs::is_regular_file(hmd)) hmd = fs::absolute(hmd).string();
    const fs::path script =
        fs::temp_directory_path() / ("monoplane-simxr-" + std::to_string(getpid()) + ".toml");
    std::ofstream out(script);
    out << "# written by monoplane study run --headset simulated\n";
    out << "hmd = \"" << hmd << "\"\n";
    out << "display_rate_hz = " << options.sim_rate_hz << "\n";
    out << "head_motion = \"" << options.sim_head_motion << "\"\n";
    if (!options.dump_frames.empty()) {
        fs::create_directories(options.dump_frames);
        out << "dump_dir = \"" << fs::absolute(options.dump_frames).string() << "\"\n";
    }
    if (!out) throw UserError("cannot write the simulated runtime's script " + script.string());
    setenv("SIMXR_SCRIPT", script.c_str(), 1);
    return script;
}

}  // namespace monoplane::app
