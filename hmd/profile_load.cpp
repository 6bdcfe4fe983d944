// Finding an HMD profile by built-in name or file path (a path is accepted anywhere a name is).
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "hmd/builtin_profiles.h"
#include "hmd/profile.h"

namespace monoplane::hmd {
namespace {

std::string builtin_names_text() {
    std::string text;
    for (const std::string& name : builtin_hmd_names()) {
        if (!text.empty()) text += ", ";
        text += name;
    }
    return text;
}

Result<std::string> read_text_file(const std::filesystem::path& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        return Error{"cannot open HMD profile file '" + path.string() +
                     "': " + std::strerror(errno)};
    }
    std::ostringstream text;
    text << file.rdbuf();
    if (file.bad()) return Error{"cannot read HMD profile file '" + path.string() + "'"};
    return text.str();
}

}  // namespace

std::vector<std::string> builtin_hmd_names() {
    std::vector<std::string> names;
    for (const BuiltinProfile& profile : builtin_profiles()) names.emplace_back(profile.name);
    return names;
}

Result<HmdProfile> load_hmd_profile(std::string_view name_or_path) {
    for (const BuiltinProfile& profile : builtin_profiles()) {
        if (profile.name == name_or_path) {
            return parse_hmd_profile(profile.toml_text, "built-in " + std::string(profile.name));
        }
    }

    const std::filesystem::path path{std::string(name_or_path)};
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (!std::filesystem::exists(status)) {
        return Error{"unknown HMD profile '" + std::string(name_or_path) +
                     "': neither a built-in profile (" + builtin_names_text() +
                     ") nor an existing file"};
    }
    if (std::filesystem::is_directory(status)) {
        return Error{"HMD profile '" + std::string(name_or_path) +
                     "' is a directory; expected a TOML file or one of " + builtin_names_text()};
    }
    Result<std::string> text = read_text_file(path);
    MONOPLANE_TRY(text);
    return parse_hmd_profile(*text, name_or_path);
}

rig::RigInputs rig_inputs(const HmdProfile& profile, double mono_plane) {
    rig::RigInputs inputs;
    inputs.eyes = {profile.left, profile.right};
    inputs.eye_width = profile.width;
    inputs.eye_height = profile.height;
    inputs.ipd = profile.ipd;
    inputs.mono_plane = mono_plane;
    inputs.cant = cant_radians(profile);
    return inputs;
}

std::array<double, 2> cant_radians(const HmdProfile& profile) {
    constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
    return {profile.cant_deg[0] * kRadiansPerDegree, profile.cant_deg[1] * kRadiansPerDegree};
}

}  // namespace monoplane::hmd
