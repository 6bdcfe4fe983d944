#include "scenes/generate.h"

#include <array>
#include <utility>

#include "common/programming_error.h"
#include "scenes/beams.h"
#include "scenes/landscape.h"
#include "scenes/spheres.h"

namespace monoplane::scenes {
namespace {

constexpr std::array<std::pair<SceneId, std::string_view>, 3> kSceneNames = {{
    {SceneId::Beams, "beams"},
    {SceneId::Landscape, "landscape"},
    {SceneId::Spheres, "spheres"},
}};

constexpr std::array<std::pair<Detail, std::string_view>, 5> kDetailNames = {{
    {Detail::Test, "test"},
    {Detail::Low, "low"},
    {Detail::Medium, "medium"},
    {Detail::High, "high"},
    {Detail::Ultra, "ultra"},
}};

}  // namespace

Scene generate_scene(SceneId id, Detail detail, std::uint64_t seed) {
    Scene scene;
    switch (id) {
        case SceneId::Beams:
            scene = generate_beams(detail, seed);
            break;
        case SceneId::Landscape:
            scene = generate_landscape(detail, seed);
            break;
        case SceneId::Spheres:
            scene = generate_spheres(detail, seed);
            break;
        case SceneId::Imported:
            // Imported scenes come from scenes/gltf/load_gltf.h, which needs a file.
            MONOPLANE_EXPECTS(false && "generate_scene() cannot make an imported scene");
            break;
    }
    scene.name = std::string(scene_name(id));
    return scene;
}

std::optional<SceneId> parse_scene_id(std::string_view name) {
    for (const auto& [id, text] : kSceneNames) {
        if (text == name) return id;
    }
    return std::nullopt;
}

std::string_view scene_name(SceneId id) {
    // Not in kSceneNames: parse_scene_id() must never offer a scene generate_scene() cannot make.
    if (id == SceneId::Imported) return "imported";
    for (const auto& [known, text] : kSceneNames) {
        if (known == id) return text;
    }
    return "unknown";
}

std::optional<Detail> parse_detail(std::string_view name) {
    for (const auto& [detail, text] : kDetailNames) {
        if (text == name) return detail;
    }
    return std::nullopt;
}

std::string_view detail_name(Detail detail) {
    for (const auto& [known, text] : kDetailNames) {
        if (known == detail) return text;
    }
    return "unknown";
}

}  // namespace monoplane::scenes
