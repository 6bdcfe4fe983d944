// The glTF files a study protocol's scenes may name (docs/scenes.md, "Imported scenes" and
// "glTF scenes in a study"): which entries are files, where they resolve, the
// record of every file a scene was read from (stored with its session, docs/data.md table
// scene_files), and the check `study resume` makes against that record so that a resumed
// session shows the scene its first trials showed. study/ never loads a glTF file itself: the
// app loads it and hands over the list of files the loader read.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "study/file_digest.h"

namespace monoplane::study {

// One file an imported scene was read from, as recorded when its session began.
struct SceneFileRecord {
    std::string scene;  // the protocol's scenes entry as written, e.g. "models/room.glb"
    // 0: the .gltf/.glb itself; then the external buffers and images it referenced, in the
    // order the loader read them.
    int file_index = 0;
    std::filesystem::path path;  // absolute
    FileDigest digest;

    bool operator==(const SceneFileRecord&) const = default;
};

// True when a scenes entry names a glTF 2.0 file (ends in .gltf or .glb, any case) rather than
// a built-in scene. Any time.
bool names_scene_file(std::string_view scene);

// The absolute, lexically normal path a scenes entry that names a file stands for: relative
// entries resolve against `directory` (the protocol file's folder; a relative `directory` is
// taken from the current one). Touches no file. May be called only when names_scene_file(scene).
std::filesystem::path resolve_scene_file(std::string_view scene,
                                         const std::filesystem::path& directory);

// The path of each imported scene's own file (file_index 0), by scenes entry: where a resumed
// session loads its scenes from.
std::map<std::string, std::filesystem::path> recorded_scene_paths(
    const std::vector<SceneFileRecord>& records);

// A recorded file that is not as it was when the session began.
struct SceneFileChange {
    SceneFileRecord recorded;
    std::optional<FileDigest> now;  // none: the file is missing or cannot be read...
    std::string problem;            // ...and this says why
};

// Reads every recorded file again and returns those whose size or SHA-256 differ from the record
// or that cannot be read, in record order. Any time; reads each file once.
std::vector<SceneFileChange> changed_scene_files(const std::vector<SceneFileRecord>& records);

// One line naming the scene, the file and both digests, e.g. "scene 'room.glb': /data/room.bin
// changed: recorded sha256 9f86... (1024 bytes), now 2c26... (1030 bytes)".
std::string describe(const SceneFileChange& change);

}  // namespace monoplane::study
