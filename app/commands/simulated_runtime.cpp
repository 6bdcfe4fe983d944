// RuntimeSelection (study_headset.h) in a file of its own, so that what needs only to point the
// loader at a runtime (the launcher's headset probe and check) links without the study's session
// loop.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "app/commands/study_headset.h"
#include "app/install/install_layout.h"
#include "common/result.h"

namespace monoplane::app {

namespace fs = std::filesystem;

namespace {

std::optional<std::string> variable(const char* name) {
    const char* value = std::getenv(name);
    return value ? std::optional<std::string>(value) : std::nullopt;
}

void put_back(const char* name, const std::optional<std::string>& value) {
    if (value)
        setenv(name, value->c_str(), 1);
    else
        unsetenv(name);
}

// simxr's script from the options, in the temporary folder; its path.
fs::path write_simxr_script(const HeadsetStudyOptions& options) {
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
    return script;
}

// simxr's manifest: in the data folder beside the executable (app/install/install_layout.h); a
// test executable, which lives elsewhere in the build folder, is given the build's.
std::string simxr_manifest_path() {
    if (const auto manifest = simxr_manifest()) return manifest->string();
#ifdef MONOPLANE_SIMXR_MANIFEST
    return MONOPLANE_SIMXR_MANIFEST;
#else
    throw UserError(
        "--headset simulated: the simulated runtime's manifest (share/monoplane/simxr/"
        "simxr.json) is not beside " +
        executable_path().string() + "; reinstall monoplane");
#endif
}

}  // namespace

RuntimeSelection::RuntimeSelection(const HeadsetStudyOptions& options)
    : runtime_(variable("XR_RUNTIME_JSON")), script_variable_(variable("SIMXR_SCRIPT")) {
    if (options.headset != "simulated") return;  // the machine's (or the caller's) runtime
    if (!options.sim_script.empty() && !fs::exists(options.sim_script)) {
        throw UserError("--sim-script " + options.sim_script + ": no such file");
    }
    setenv("XR_RUNTIME_JSON", simxr_manifest_path().c_str(), 1);
    if (!options.sim_script.empty()) {
        setenv("SIMXR_SCRIPT", fs::absolute(options.sim_script).c_str(), 1);
        return;
    }
    written_ = write_simxr_script(options);
    setenv("SIMXR_SCRIPT", written_->c_str(), 1);
}

RuntimeSelection::~RuntimeSelection() {
    instance_created();
}

void RuntimeSelection::instance_created() {
    if (restored_) return;
    restored_ = true;
    put_back("XR_RUNTIME_JSON", runtime_);
    put_back("SIMXR_SCRIPT", script_variable_);
    if (written_) {
        std::error_code ignored;
        fs::remove(*written_, ignored);
    }
}

}  // namespace monoplane::app
