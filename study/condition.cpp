#include "study/condition.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <iterator>

#include "study/scene_files.h"

namespace monoplane::study {
namespace {

constexpr std::array<std::string_view, 3> kSceneNames = {"beams", "landscape", "spheres"};

// Shortest text that reads back as the same double: "8", "39.5", "nan".
std::string format_number(double value) {
    char buffer[32];
    const auto result = std::to_chars(std::begin(buffer), std::end(buffer), value);
    return std::string(buffer, result.ptr);
}

std::string scene_list() {
    std::string text;
    for (std::string_view name : kSceneNames) {
        if (!text.empty()) text += ", ";
        text += name;
    }
    return text;
}

}  // namespace

std::span<const std::string_view> study_scene_names() {
    return kSceneNames;
}

std::string describe(const Condition& condition) {
    return condition.scene + " / " + std::string(render_mode_name(condition.mode)) +
           " / m = " + format_number(condition.mono_plane) + " m";
}

Result<Condition> validate_condition(const Condition& condition, double near, double far) {
    if (!std::isfinite(near) || !std::isfinite(far) || !(0.0 < near && near < far)) {
        return Error{"invalid clip range near = " + format_number(near) + " m, far = " +
                     format_number(far) + " m: both must be finite with 0 < near < far"};
    }
    if (std::ranges::find(kSceneNames, condition.scene) == kSceneNames.end() &&
        !names_scene_file(condition.scene)) {
        return Error{"condition " + describe(condition) + ": unknown scene '" + condition.scene +
                     "' (known scenes: " + scene_list() + "; or a glTF file, .gltf or .glb)"};
    }
    if (!std::isfinite(condition.mono_plane)) {
        return Error{"condition " + describe(condition) +
                     ": the mono-plane distance must be a finite number of metres"};
    }
    if (!(near < condition.mono_plane && condition.mono_plane < far)) {
        return Error{"condition " + describe(condition) +
                     ": the mono plane must lie strictly between near = " + format_number(near) +
                     " m and far = " + format_number(far) + " m"};
    }
    return condition;
}

}  // namespace monoplane::study
