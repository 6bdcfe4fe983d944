#include "app/commands/scene_source.h"

#include <system_error>

#include "common/scene_file_name.h"

namespace monoplane::app {

bool names_a_gltf_file(std::string_view name_or_path) {
    return names_gltf_file(name_or_path);
}

Result<SceneSource> parse_scene_source(std::string_view name_or_path) {
    SceneSource source;
    source.label = std::string(name_or_path);
    if (const auto id = scenes::parse_scene_id(name_or_path)) {
        source.builtin = *id;
        return source;
    }
    if (!names_a_gltf_file(name_or_path)) {
        return Error{
            "neither a built-in scene (beams, landscape, spheres) nor a glTF 2.0 file "
            "(.gltf or .glb)"};
    }
    source.file = std::filesystem::path(name_or_path);
    std::error_code error;
    if (!std::filesystem::is_regular_file(source.file, error)) {
        return Error{"no such glTF file" + (error ? " (" + error.message() + ")" : std::string())};
    }
    return source;
}

Result<scenes::Scene> load_scene(const SceneSource& source, scenes::Detail detail,
                                 std::uint64_t seed, scenes::GltfLoadReport* gltf_report) {
    if (source.builtin) return scenes::generate_scene(*source.builtin, detail, seed);
    return scenes::load_gltf_scene(source.file, {}, gltf_report);
}

}  // namespace monoplane::app
