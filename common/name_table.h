// An enum's names as one table, read both ways: each name is spelled once, next to its value, so
// parsing and naming cannot disagree. The CLI, protocols, databases and JSON outputs name the
// project's choices with these.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace monoplane {

template <class Enum>
using NameTable = std::initializer_list<std::pair<Enum, const char*>>;

// Exact, case-sensitive match; none for a name the table lacks.
template <class Enum>
constexpr std::optional<Enum> parse_name(NameTable<Enum> table, std::string_view name) {
    for (const auto& [value, text] : table) {
        if (name == text) return value;
    }
    return std::nullopt;
}

// The table's name for `value`, or `missing` for a value the table lacks (a table missing an
// entry is a bug the unit tests catch). The text lives as long as the program.
template <class Enum>
constexpr std::string_view find_name(NameTable<Enum> table, Enum value,
                                     std::string_view missing = "?") {
    for (const auto& [entry, text] : table) {
        if (entry == value) return text;
    }
    return missing;
}

template <class Enum>
std::string name_of(NameTable<Enum> table, Enum value) {
    return std::string(find_name(table, value));
}

// Every name, in table order (a "did you mean" list, a parser's allowed values).
template <class Enum>
std::vector<std::string_view> names_of(NameTable<Enum> table) {
    std::vector<std::string_view> names;
    for (const auto& entry : table) names.emplace_back(entry.second);
    return names;
}

// "a, b, c": the valid names, in table order, for error messages and help texts.
template <class Enum>
std::string joined_names(NameTable<Enum> table, std::string_view separator = ", ") {
    std::string names;
    for (const auto& [value, text] : table) {
        if (!names.empty()) names += separator;
        names += text;
    }
    return names;
}

}  // namespace monoplane
