// Checking participant variables (participant_variables.h). The values reach exports, reports and
// spreadsheets, so each is stored in one canonical text: "042" and "42" are the same age, and a
// number reads back the same in any locale.
#include "study/participant_variables.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <system_error>

#include "common/quoted.h"
#include "common/toml/toml_problems.h"
#include "study/export.h"

namespace monoplane::study {
namespace {

// A text value is one cell of a spreadsheet or a line of a form, not a document.
constexpr std::size_t kMaxTextCharacters = 1000;

std::string bound_text(double value, VariableType type) {
    if (type == VariableType::Integer) return std::to_string(static_cast<std::int64_t>(value));
    return number_text(value);
}

// What a value of the declaration may be, for messages: "an integer from 18 to 99".
std::string allowed_text(const ParticipantVariable& d) {
    switch (d.type) {
        case VariableType::Integer:
        case VariableType::Number: {
            std::string text = d.type == VariableType::Integer ? "an integer" : "a number";
            if (d.min && d.max) {
                text += " from " + bound_text(*d.min, d.type) + " to " + bound_text(*d.max, d.type);
            } else if (d.min) {
                text += " of at least " + bound_text(*d.min, d.type);
            } else if (d.max) {
                text += " of at most " + bound_text(*d.max, d.type);
            }
            return text;
        }
        case VariableType::Choice: {
            std::vector<std::string_view> names(d.choices.begin(), d.choices.end());
            return "one of " + join(names);
        }
        case VariableType::Text:
            break;
    }
    return "a text of 1 to " + std::to_string(kMaxTextCharacters) +
           " characters without control characters";
}

// Plain decimal: an optional '-', then digits; no '+', spaces, point or exponent.
std::optional<std::int64_t> parse_integer(std::string_view text) {
    std::int64_t value = 0;
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    if (error != std::errc{} || ptr != end || text.empty()) return std::nullopt;
    return value;
}

// A finite decimal number with '.' as the point (from_chars ignores the locale); an exponent is
// accepted, "inf" and "nan" are not.
std::optional<double> parse_number(std::string_view text) {
    double value = 0.0;
    const char* end = text.data() + text.size();
    const auto [ptr, error] = std::from_chars(text.data(), end, value);
    if (error != std::errc{} || ptr != end || text.empty() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value == 0.0 ? 0.0 : value;  // -0 is 0
}

bool in_range(double value, const ParticipantVariable& d) {
    return (!d.min || value >= *d.min) && (!d.max || value <= *d.max);
}

// The number of UTF-8 code points, or nothing for text that is not valid UTF-8.
std::optional<std::size_t> utf8_length(std::string_view text) {
    std::size_t count = 0;
    for (std::size_t i = 0; i < text.size(); ++count) {
        const auto lead = static_cast<unsigned char>(text[i]);
        const std::size_t size = lead < 0x80           ? 1
                                 : (lead >> 5) == 0x6  ? 2
                                 : (lead >> 4) == 0xe  ? 3
                                 : (lead >> 3) == 0x1e ? 4
                                                       : 0;
        if (size == 0 || i + size > text.size()) return std::nullopt;
        for (std::size_t k = 1; k < size; ++k) {
            if ((static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80) return std::nullopt;
        }
        i += size;
    }
    return count;
}

// The problem with a value, or nothing: `canonical` receives the value's canonical text.
std::optional<std::string> value_problem(const ParticipantVariable& d, std::string_view value,
                                         std::string& canonical) {
    switch (d.type) {
        case VariableType::Integer: {
            const std::optional<std::int64_t> n = parse_integer(value);
            if (!n) return "not an integer";
            if (!in_range(static_cast<double>(*n), d)) return "out of range";
            canonical = std::to_string(*n);
            return std::nullopt;
        }
        case VariableType::Number: {
            const std::optional<double> x = parse_number(value);
            if (!x) {
                return value.find(',') != std::string_view::npos
                           ? "not a number (use '.' as the decimal point)"
                           : "not a number";
            }
            if (!in_range(*x, d)) return "out of range";
            canonical = number_text(*x);
            return std::nullopt;
        }
        case VariableType::Choice:
            if (std::ranges::find(d.choices, value) == d.choices.end()) return "";
            canonical = std::string(value);
            return std::nullopt;
        case VariableType::Text:
            break;
    }
    const std::optional<std::size_t> length = utf8_length(value);
    if (!length) return "not valid UTF-8 text";
    if (*length == 0) return "empty";
    if (*length > kMaxTextCharacters) return std::to_string(*length) + " characters is too long";
    const bool control = std::ranges::any_of(value, [](char c) {
        return c != '\t' && (static_cast<unsigned char>(c) < 0x20 || c == 0x7f);
    });
    if (control) return "has a control character (a line break?)";
    canonical = std::string(value);
    return std::nullopt;
}

std::string value_message(const ParticipantVariable& d, std::string_view value,
                          const std::string& problem, const RequestNames& names) {
    const std::string prefix = names.variable(d.name + "=" + std::string(value)) + ": ";
    if (d.type != VariableType::Choice) {
        return prefix + problem + "; " + d.name + " must be " + allowed_text(d);
    }
    std::vector<std::string_view> choices(d.choices.begin(), d.choices.end());
    std::string message = prefix + "not " + allowed_text(d);
    const std::string_view closest = closest_match(value, choices);
    if (!closest.empty()) message += "; did you mean " + in_quotes(closest) + "?";
    return message;
}

std::string declared_names(const std::vector<ParticipantVariable>& declarations) {
    if (declarations.empty()) return "the protocol declares no variables";
    std::string text = "the protocol declares: ";
    for (std::size_t i = 0; i < declarations.size(); ++i) {
        text += (i > 0 ? ", " : "") + declarations[i].name;
    }
    return text;
}

std::string unknown_name_message(const std::vector<ParticipantVariable>& declarations,
                                 const std::string& assignment, const std::string& name,
                                 const RequestNames& request_names) {
    std::vector<std::string_view> names;
    for (const ParticipantVariable& d : declarations) names.push_back(d.name);
    std::string message =
        request_names.variable(assignment) + ": unknown variable " + in_quotes(name);
    const std::string_view closest = closest_match(name, names);
    if (!closest.empty()) return message + "; did you mean " + in_quotes(closest) + "?";
    return message + " (" + declared_names(declarations) + ")";
}

std::string missing_message(const ParticipantVariable& d, const RequestNames& names) {
    return "variable " + in_quotes(d.name) + " is required" +
           (d.help.empty() ? std::string() : " (" + d.help + ")") + ": give " +
           names.variable(d.name + "=VALUE") + ", " + allowed_text(d);
}

}  // namespace

Result<std::vector<VariableValue>> check_variables(
    const std::vector<ParticipantVariable>& declarations,
    const std::vector<std::string>& assignments, const RequestNames& names) {
    std::vector<std::string> problems;
    std::vector<std::optional<std::string>> given(declarations.size());
    for (const std::string& assignment : assignments) {
        const std::size_t eq = assignment.find('=');
        if (eq == std::string::npos) {
            problems.push_back(names.variable(assignment) + ": expected NAME=VALUE (" +
                               declared_names(declarations) + ")");
            continue;
        }
        const std::string name = assignment.substr(0, eq);
        const auto declared = std::ranges::find(declarations, name, &ParticipantVariable::name);
        if (declared == declarations.end()) {
            problems.push_back(unknown_name_message(declarations, assignment, name, names));
            continue;
        }
        std::optional<std::string>& slot =
            given[static_cast<std::size_t>(declared - declarations.begin())];
        if (slot) {
            problems.push_back(names.variable(assignment) + ": variable " + in_quotes(name) +
                               " is given twice; give each variable once");
            continue;
        }
        Result<std::string> value =
            check_variable_value(*declared, assignment.substr(eq + 1), names);
        if (!value) problems.push_back(value.error().message);
        slot = value ? *value : std::string();  // given, if wrongly: not "missing" as well
    }
    std::vector<VariableValue> values;
    for (std::size_t i = 0; i < declarations.size(); ++i) {
        const ParticipantVariable& d = declarations[i];
        if (given[i])
            values.push_back({d.name, d.type, *given[i]});
        else if (d.required)
            problems.push_back(missing_message(d, names));
    }
    if (problems.empty()) return values;
    std::string text;
    for (const std::string& problem : problems) text += (text.empty() ? "" : "\n") + problem;
    return Error{text};
}

Result<std::string> check_variable_value(const ParticipantVariable& declaration,
                                         std::string_view value, const RequestNames& names) {
    std::string canonical;
    if (std::optional<std::string> problem = value_problem(declaration, value, canonical)) {
        return Error{value_message(declaration, value, *problem, names)};
    }
    return canonical;
}

}  // namespace monoplane::study
