#include "common/toml/toml_problems.h"

#include <algorithm>
#include <charconv>
#include <iterator>

#include "common/programming_error.h"

namespace monoplane {
namespace {

std::size_t edit_distance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> previous(b.size() + 1);
    std::vector<std::size_t> current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

Error syntax_error(const toml::parse_error& error, std::string_view source_name) {
    TomlProblems problems(source_name);
    problems.add(error.source(), "TOML syntax error: " + std::string(error.description()));
    return problems.error();
}

}  // namespace

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
    MONOPLANE_EXPECTS(!problems_.empty());
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
    MONOPLANE_EXPECTS(error == std::errc{});
    return std::string(buffer, end);
}

std::string join(std::span<const std::string_view> words) {
    std::string text;
    for (std::string_view word : words) {
        if (!text.empty()) text += ", ";
        text += word;
    }
    return text;
}

std::string_view closest_match(std::string_view word,
                               std::span<const std::string_view> candidates) {
    std::string_view best;
    std::size_t best_distance = 3;  // more than 2 edits away is no typo
    for (std::string_view candidate : candidates) {
        const std::size_t distance = edit_distance(word, candidate);
        if (distance < best_distance) {
            best = candidate;
            best_distance = distance;
        }
    }
    if (!best.empty() || word.empty()) return best;
    // A shortened value ("latin" for "latin-square") is no typo but just as clearly meant.
    for (std::string_view candidate : candidates) {
        if (candidate.starts_with(word)) {
            if (!best.empty()) return {};  // ambiguous: suggest nothing
            best = candidate;
        }
    }
    return best;
}

Result<toml::table> parse_toml(std::string_view text, std::string_view source_name) {
#if TOML_EXCEPTIONS
    try {
        return toml::parse(text, source_name);
    } catch (const toml::parse_error& error) {
        return syntax_error(error, source_name);
    }
#else
    toml::parse_result result = toml::parse(text, source_name);
    if (!result) return syntax_error(result.error(), source_name);
    return std::move(result).table();
#endif
}

}  // namespace monoplane
