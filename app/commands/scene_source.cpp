#include "app/commands/scene_source.h"

#include <algorithm>
#include <cctype>
#include <system_error>

#include "scenes/gltf/load_gltf.h"

namespace monoplane::app {
namespace {

bool ends_with_ignoring_case(std::string_view text, std::string_view suffix) {
    if (text.size() < suffix.size()) return false;
    return std::equal(suffix.begin(), suffix.end(),
                      text.end() - static_cast<std::ptrdiff_t>(suffix.size()), [](char a, char b) {
                          return std::tolower(static_cast<unsigned char>(a)) ==
                                 std::tolower(static_cast<unsigned char>(b));
                      });
}

}  // namespace

bool names_a_gltf_file(std::string_view name_or_path) {
    return ends_with_ignoring_case(name_or_path, ".gltf") ||
           ends_with_ignoring_case(name_or_path, ".glb");
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
                                 std::uint64_t seed) {
    if (source.builtin) return scenes::generate_scene(*source.builtin, detail, seed);
    return scenes::load_gltf_scene(source.file);
}

}  // namespace monoplane::app
