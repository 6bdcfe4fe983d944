// An enum's names as one table, read both ways: the CLI, protocols and JSON name the renderer's
// choices and the plan's passes, draws and predicates with these.
#pragma once

#include <initializer_list>
#include <optional>
#include <string>
#include <utility>

namespace monoplane::modes {

template <class Enum>
using NameTable = std::initializer_list<std::pair<Enum, const char*>>;

template <class Enum>
std::optional<Enum> parse_name(NameTable<Enum> table, const std::string& name) {
    for (const auto& [value, text] : table) {
        if (name == text) return value;
    }
    return std::nullopt;
}

// "?" for a value the table lacks (a table missing an entry is a bug the unit tests catch).
template <class Enum>
std::string name_of(NameTable<Enum> table, Enum value) {
    for (const auto& [entry, text] : table) {
        if (entry == value) return text;
    }
    return "?";
}

}  // namespace monoplane::modes
