#include "app/install/install_layout.h"

#include <system_error>

namespace monoplane::app {

namespace fs = std::filesystem;

namespace {

// The folder if it is one.
std::optional<fs::path> existing_folder(const fs::path& folder) {
    std::error_code ec;
    if (fs::is_directory(folder, ec)) return folder.lexically_normal();
    return std::nullopt;
}

}  // namespace

fs::path executable_path() {
    std::error_code ec;
    const fs::path self = fs::canonical("/proc/self/exe", ec);
    return ec ? fs::path() : self;
}

std::optional<fs::path> data_folder() {
    const fs::path folder = executable_path().parent_path();
    if (folder.empty()) return std::nullopt;
    // Installed: bin/ beside share/. Built: share/ inside the build folder.
    if (auto installed = existing_folder(folder.parent_path() / "share" / "monoplane")) {
        return installed;
    }
    return existing_folder(folder / "share" / "monoplane");
}

std::optional<fs::path> simxr_manifest() {
    const std::optional<fs::path> data = data_folder();
    if (!data) return std::nullopt;
    const fs::path manifest = *data / "simxr" / "simxr.json";
    std::error_code ec;
    if (fs::is_regular_file(manifest, ec)) return manifest;
    return std::nullopt;
}

std::optional<fs::path> shipped_protocols() {
    const std::optional<fs::path> data = data_folder();
    if (!data) return std::nullopt;
    return existing_folder(*data / "protocols");
}

}  // namespace monoplane::app
