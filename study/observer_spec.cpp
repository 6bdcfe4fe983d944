#include "study/observer_spec.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <optional>
#include <string>

#include "common/toml/toml_problems.h"

namespace monoplane::study {
namespace {

constexpr std::array<std::string_view, 3> kKeys = {"threshold", "slope", "lapse"};

struct Pair {
    std::string_view key, value;
    std::size_t position;  // 1-based character position of the key in the specification
};

std::optional<double> parse_number(std::string_view text) {
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
        return std::nullopt;
    }
    return value;
}

// Why `value` cannot be the key's, or "" when it can.
std::string check_value(std::string_view key, double value) {
    if (key == "lapse") return value >= 0.0 && value < 0.5 ? "" : "must lie in [0, 0.5)";
    return value > 0.0 ? "" : "must be greater than 0";
}

// A specification of threshold, slope and lapse after `prefix` (or without it).
Result<PsychometricFunction> parse_spec(std::string_view spec, std::string_view prefix) {
    const std::string whole(spec);
    const auto fail = [&whole, prefix](std::size_t position, const std::string& what) {
        return Error{"observer '" + whole + "', character " + std::to_string(position) + ": " +
                     what + " (expected " + std::string(prefix) + "threshold=T,slope=B,lapse=L)"};
    };
    std::size_t offset = 0;
    if (spec.starts_with(prefix)) offset = prefix.size();
    std::array<std::optional<double>, 3> values;
    for (std::size_t start = offset; start <= spec.size();) {
        const std::size_t comma = std::min(spec.find(',', start), spec.size());
        const std::string_view item = spec.substr(start, comma - start);
        const std::size_t equals = item.find('=');
        if (equals == std::string_view::npos) {
            return fail(start + 1, "'" + std::string(item) + "' is not key=value");
        }
        const Pair pair{item.substr(0, equals), item.substr(equals + 1), start + 1};
        const auto known = std::ranges::find(kKeys, pair.key);
        if (known == kKeys.end()) {
            std::string what = "unknown key '" + std::string(pair.key) + "'";
            const std::string_view closest = closest_match(pair.key, kKeys);
            if (!closest.empty()) what += "; did you mean '" + std::string(closest) + "'?";
            return fail(pair.position, what);
        }
        std::optional<double>& slot = values[static_cast<std::size_t>(known - kKeys.begin())];
        if (slot) return fail(pair.position, std::string(pair.key) + " is given twice");
        slot = parse_number(pair.value);
        if (!slot) {
            return fail(pair.position + equals + 1, std::string(pair.key) + " = '" +
                                                        std::string(pair.value) +
                                                        "' is not a finite number");
        }
        if (const std::string why = check_value(pair.key, *slot); !why.empty()) {
            return fail(pair.position + equals + 1, std::string(pair.key) + " " + why);
        }
        start = comma + 1;
    }
    for (std::size_t k = 0; k < 2; ++k) {
        if (!values[k]) return fail(spec.size() + 1, std::string(kKeys[k]) + " is missing");
    }
    return PsychometricFunction{*values[0], *values[1], values[2].value_or(0.0)};
}

}  // namespace

Result<PsychometricFunction> parse_psychometric_spec(std::string_view spec) {
    return parse_spec(spec, kPsychometricPrefix);
}

Result<PsychometricFunction> parse_gaze_spec(std::string_view spec) {
    return parse_spec(spec, kGazePrefix);
}

}  // namespace monoplane::study
