// Which scene names are files (docs/scenes.md, "Imported scenes"): one rule for the command
// line (app/commands/scene_source.h) and for study protocols (study/scene_files.h), which may not
// include each other's headers (docs/architecture.md).
#pragma once

#include <algorithm>
#include <cctype>
#include <string_view>

namespace monoplane {

// True for names that end in .gltf or .glb (any case): those are glTF 2.0 files, never built-in
// scene names. Any thread, any time.
inline bool names_gltf_file(std::string_view name) {
    const auto ends_with = [name](std::string_view suffix) {
        if (name.size() < suffix.size()) return false;
        return std::equal(suffix.begin(), suffix.end(), name.end() - suffix.size(),
                          [](char a, char b) {
                              return std::tolower(static_cast<unsigned char>(a)) ==
                                     std::tolower(static_cast<unsigned char>(b));
                          });
    };
    return ends_with(".gltf") || ends_with(".glb");
}

}  // namespace monoplane
