#include "study/protocol_study_day.h"

#include <algorithm>

#include "common/name_table.h"

namespace monoplane::study {
namespace {

// These names are protocol keys' values, database values and appear in exports: never change
// one.
constexpr NameTable<VariableType> kVariableTypeNames = {
    {VariableType::Integer, "integer"},
    {VariableType::Number, "number"},
    {VariableType::Choice, "choice"},
    {VariableType::Text, "text"},
};

}  // namespace

std::string_view variable_type_name(VariableType type) {
    return find_name(kVariableTypeNames, type, "invalid");
}

std::optional<VariableType> parse_variable_type(std::string_view name) {
    return parse_name(kVariableTypeNames, name);
}

std::vector<std::string_view> variable_type_names() {
    return names_of(kVariableTypeNames);
}

std::string_view blocking_name(Blocking blocking) {
    return blocking == Blocking::None ? "none" : "scene";
}

Result<void> check_variable_name(std::string_view name) {
    const bool ok = !name.empty() && name.size() <= kMaxVariableName && name[0] >= 'a' &&
                    name[0] <= 'z' && std::ranges::all_of(name, [](char c) {
                        return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_';
                    });
    if (ok) return Ok{};
    return Error{"'" + std::string(name) +
                 "' is not a variable name: a lower-case letter, then lower-case letters, digits "
                 "or '_', at most " +
                 std::to_string(kMaxVariableName) + " characters"};
}

}  // namespace monoplane::study
