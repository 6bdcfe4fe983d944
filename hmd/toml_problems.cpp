#include "hmd/toml_problems.h"

#include <algorithm>
#include <cassert>
#include <charconv>
#include <iterator>

namespace monoplane::hmd {

void TomlProblems::add(const toml::source_region& where, std::string_view message) {
    if (where.begin.line == 0) {
        add(message);
        return;
    }
    problems_.push_back({where.begin, source_name_ + ":" + std::to_string(where.begin.line) + ":" +
                                          std::to_string(where.begin.column) + ": " +
                                          std::string(message)});
}

void TomlProblems::add(std::string_view message) {
    problems_.push_back({toml::source_position{}, source_name_ + ": " + std::string(message)});
}

Error TomlProblems::error() const {
    assert(!problems_.empty());
    std::vector<Problem> sorted = problems_;
    std::ranges::stable_sort(sorted, [](const Problem& a, const Problem& b) {
        return a.position.line != b.position.line ? a.position.line < b.position.line
                                                  : a.position.column < b.position.column;
    });
    std::string text;
    for (const Problem& problem : sorted) {
        if (!text.empty()) text += '\n';
        text += problem.text;
    }
    return Error{text};
}

std::string_view toml_type_phrase(toml::node_type type) {
    switch (type) {
        case toml::node_type::table:
            return "a table";
        case toml::node_type::array:
            return "an array";
        case toml::node_type::string:
            return "a string";
        case toml::node_type::integer:
            return "an integer";
        case toml::node_type::floating_point:
            return "a floating-point number";
        case toml::node_type::boolean:
            return "a boolean";
        case toml::node_type::date:
            return "a date";
        case toml::node_type::time:
            return "a time";
        case toml::node_type::date_time:
            return "a date-time";
        case toml::node_type::none:
            break;
    }
    return "nothing";
}

std::string format_number(double value) {
    char buffer[32];
    const auto [end, error] = std::to_chars(std::begin(buffer), std::end(buffer), value);
    assert(error == std::errc{});
    return std::string(buffer, end);
}

}  // namespace monoplane::hmd
