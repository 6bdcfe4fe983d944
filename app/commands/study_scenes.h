// The imported (glTF) scenes of a study session (docs/scenes.md, "glTF scenes in a study"):
// loaded once, before the session begins, through load_scene (scene_source.h), together with the
// size and SHA-256 of every file each was read from: the evidence the session's database row
// keeps (study::SceneFileRecord). A headset session then renders these very scenes, so no file
// is read twice and what was digested is what was drawn.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "common/result.h"
#include "scenes/scene.h"
#include "study/scene_files.h"
#include "study/study_store.h"

namespace monoplane::app {

struct ImportedStudyScene {
    scenes::Scene scene;
    std::vector<study::SceneFileRecord> files;  // file 0: the .gltf/.glb itself
};

// By the protocol's scenes entry, as written.
using ImportedStudyScenes = std::map<std::string, ImportedStudyScene>;

// Loads each scene of `paths` (scenes entry -> absolute path: study::Protocol::scene_files, or a
// resumed session's study::recorded_scene_paths()) and digests every file the loader read;
// prints one line per scene on stderr. Refuses when any scene cannot be loaded or a file cannot
// be digested: one line per failing scene, naming `protocol` (its file or session), the scenes
// entry and the loader's message. Any time; reads every file.
Result<ImportedStudyScenes> load_imported_scenes(
    const std::map<std::string, std::filesystem::path>& paths, const std::string& protocol);

// "1 triangle in 1 chunk", "1200 triangles in 3 chunks": for the lines about a loaded scene.
std::string describe_size(const scenes::Scene& scene);

// Every file record of every scene, scene by scene: what study::SessionInfo::scene_files takes.
std::vector<study::SceneFileRecord> scene_file_records(const ImportedStudyScenes& scenes);

// Before `study resume` continues a session: its remaining trials must show the scenes its first
// trials showed, so every recorded scene file is read again. Refuses (a UserError naming each
// changed or unreadable file with its recorded and its present digest, and how to go on) unless
// `accept_changes`; then the session's notes record what changed, for whoever reviews the data,
// and a warning goes to stderr. Throws the store's errors too.
void check_scene_files_before_resume(study::StudyStore& store, const study::SessionInfo& session,
                                     bool accept_changes);

}  // namespace monoplane::app
