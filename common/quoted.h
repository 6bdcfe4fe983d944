// How a message names what a person wrote or chose (a key, a name, a file): in single quotes,
// exactly as written. One rule for every library's messages.
#pragma once

#include <concepts>
#include <filesystem>
#include <string>
#include <string_view>
#include <type_traits>

namespace monoplane {

inline std::string in_quotes(std::string_view text) {
    return "'" + std::string(text) + "'";
}

// A path as the system spells it. Constrained to paths, so that text (which converts to a path
// too) takes the overload above.
template <class Path>
requires std::same_as<std::remove_cvref_t<Path>, std::filesystem::path> std::string in_quotes(
    const Path& path) {
    return in_quotes(path.string());
}

}  // namespace monoplane
