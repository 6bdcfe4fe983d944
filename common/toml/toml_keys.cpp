#include "common/toml/toml_keys.h"

#include <algorithm>

#include "common/quoted.h"


namespace monoplane {

std::string toml_key_prefix(std::string_view qualified_key) {
    return "key " + in_quotes(qualified_key) + ": ";
}

void report_unknown_keys(const TomlScope& scope, std::span<const std::string_view> known,
                         TomlProblems& problems) {
    for (const auto& [key, node] : scope.table) {
        const std::string_view name = key.str();
        if (std::ranges::find(known, name) != known.end()) continue;
        std::string message = toml_key_prefix(scope.qualified(name)) + "unknown key";
        const std::string_view closest = closest_match(name, known);
        if (!closest.empty()) {
            message += " (did you mean " + in_quotes(scope.qualified(closest)) + "?)";
        } else {
            message += " (known keys" + (scope.name.empty() ? "" : " in [" + scope.name + "]") +
                       ": " + join(known) + ")";
        }
        problems.add(key.source(), message);
    }
}

const toml::node* find_required(const TomlScope& scope, std::string_view key,
                                std::string_view expected, TomlProblems& problems) {
    const toml::node* node = scope.table.get(key);
    if (node == nullptr) {
        const std::string message = toml_key_prefix(scope.qualified(key)) +
                                    "required key is missing (" + std::string(expected) + ")";
        if (scope.name.empty()) {
            problems.add(message);
        } else {
            problems.add(scope.table.source(), message);
        }
    }
    return node;
}

void report_wrong_type(const toml::node& node, std::string_view qualified_key,
                       std::string_view expected, TomlProblems& problems) {
    problems.add(node.source(), toml_key_prefix(qualified_key) + "must be " +
                                    std::string(expected) + ", but is " +
                                    std::string(toml_type_phrase(node.type())));
}

std::optional<double> read_number(const toml::node& node, std::string_view qualified_key,
                                  std::string_view expected, TomlProblems& problems) {
    if (const auto* integer = node.as_integer()) return static_cast<double>(integer->get());
    if (const auto* real = node.as_floating_point()) return real->get();
    report_wrong_type(node, qualified_key, expected, problems);
    return std::nullopt;
}

std::optional<std::int64_t> read_integer_in(const toml::node& node, std::string_view qualified_key,
                                            std::int64_t low, std::int64_t high,
                                            TomlProblems& problems) {
    const std::string range = std::to_string(low) + ".." + std::to_string(high);
    const auto* integer = node.as_integer();
    if (integer == nullptr) {
        report_wrong_type(node, qualified_key, "an integer in " + range, problems);
        return std::nullopt;
    }
    if (integer->get() < low || integer->get() > high) {
        problems.add(node.source(), toml_key_prefix(qualified_key) +
                                        std::to_string(integer->get()) +
                                        " is outside the allowed range " + range);
        return std::nullopt;
    }
    return integer->get();
}

}  // namespace monoplane
