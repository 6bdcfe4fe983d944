#include "study/scene_files.h"

#include <system_error>

#include "common/programming_error.h"
#include "common/scene_file_name.h"

namespace monoplane::study {
namespace {

std::string digest_text(const FileDigest& digest) {
    return "sha256 " + digest.sha256 + " (" + std::to_string(digest.size_bytes) + " bytes)";
}

}  // namespace

bool names_scene_file(std::string_view scene) {
    return names_gltf_file(scene);
}

std::filesystem::path resolve_scene_file(std::string_view scene,
                                         const std::filesystem::path& directory) {
    MONOPLANE_EXPECTS(names_scene_file(scene));
    std::filesystem::path path(scene);
    if (path.is_relative()) path = directory / path;
    // absolute() of an absolute path only normalises it; for a relative one it prepends the
    // current directory, which cannot fail on Linux short of a deleted working directory.
    std::error_code ignored;
    const std::filesystem::path absolute = std::filesystem::absolute(path, ignored);
    return (absolute.empty() ? path : absolute).lexically_normal();
}

std::map<std::string, std::filesystem::path> recorded_scene_paths(
    const std::vector<SceneFileRecord>& records) {
    std::map<std::string, std::filesystem::path> paths;
    for (const SceneFileRecord& record : records) {
        if (record.file_index == 0) paths[record.scene] = record.path;
    }
    return paths;
}

std::vector<SceneFileChange> changed_scene_files(const std::vector<SceneFileRecord>& records) {
    std::vector<SceneFileChange> changes;
    for (const SceneFileRecord& record : records) {
        Result<FileDigest> now = digest_file(record.path);
        if (!now) {
            changes.push_back({record, std::nullopt, now.error().message});
        } else if (*now != record.digest) {
            changes.push_back({record, *now, {}});
        }
    }
    return changes;
}

std::string describe(const SceneFileChange& change) {
    const SceneFileRecord& r = change.recorded;
    std::string text = "scene '" + r.scene + "': " + r.path.string();
    if (!change.now) {
        return text + " cannot be read (" + change.problem + "): recorded " +
               digest_text(r.digest) + ", now none";
    }
    return text + " changed: recorded " + digest_text(r.digest) + ", now " +
           digest_text(*change.now);
}

}  // namespace monoplane::study
