// Where a scene comes from (docs/scenes.md): one of the procedural scenes by name ("beams",
// "landscape", "spheres") or a glTF 2.0 file (".gltf" or ".glb"), accepted wherever a scene name
// is. CPU only; no Vulkan.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include "common/result.h"
#include "scenes/generate.h"
#include "scenes/gltf/load_gltf.h"
#include "scenes/scene.h"

namespace monoplane::app {

struct SceneSource {
    std::optional<scenes::SceneId> builtin;  // set: a procedural scene
    std::filesystem::path file;              // otherwise: the glTF file
    std::string label;                       // as the user wrote it, for messages and results
};

// True for names that end in .gltf or .glb (any case): those are files, never built-in names.
bool names_a_gltf_file(std::string_view name_or_path);

// A built-in name, or a path to an existing .gltf/.glb file. Errors say what is accepted; the
// caller names the argument and the value. Touches the file system only to check that the file
// exists.
Result<SceneSource> parse_scene_source(std::string_view name_or_path);

// Generates the procedural scene (detail, seed) or loads the file (detail and seed do not apply
// to files; the loader's progress goes to stderr). Errors name the file and the problem.
// gltf_report (optional) receives the loader's report of a file, e.g. the files it read.
Result<scenes::Scene> load_scene(const SceneSource& source, scenes::Detail detail,
                                 std::uint64_t seed = scenes::kDefaultSeed,
                                 scenes::GltfLoadReport* gltf_report = nullptr);

}  // namespace monoplane::app
