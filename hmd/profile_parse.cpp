// Parsing and validation of HMD profile TOML. Every value the rig will use is checked here, so
// the rig may assert on its inputs instead of re-validating them.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include <toml++/toml.h>

#include "common/quoted.h"
#include "common/toml/toml_keys.h"
#include "common/toml/toml_problems.h"
#include "hmd/profile.h"

namespace monoplane::hmd {
namespace {

// Bounds that catch typos and unit mix-ups (millimetres for metres, degrees for tangents) while
// admitting every real headset.
constexpr double kMaxIpd = 0.1;             // metres; human IPDs lie around 0.05 to 0.08
constexpr std::int64_t kMinPixels = 16;     // smaller is no display, only a typo
constexpr std::int64_t kMaxPixels = 16384;  // common maxImageDimension2D of desktop GPUs
constexpr double kMaxAbsTangent = 10.0;     // atan(10) = 84.3 degrees from the view axis

constexpr std::array<std::string_view, 6> kTopLevelKeys = {"name",   "ipd",  "width",
                                                           "height", "left", "right"};
constexpr std::array<std::string_view, 5> kEyeKeys = {"tan_left", "tan_right", "tan_down", "tan_up",
                                                      "cant_deg"};

struct TangentRule {
    std::string_view key;
    double rig::Tangents::*field;
    bool negative;  // left and down lie on the negative side of the view axis
    std::string_view sign_hint;
};

constexpr std::string_view kHorizontalSignHint =
    "tan_left < 0 < tan_right: the view axis lies inside the frustum";
// The most likely cause of a wrong vertical sign is a value copied from OpenVR.
constexpr std::string_view kVerticalSignHint =
    "tan_down < 0 < tan_up: profiles use OpenXR's XrFovf convention, up positive; OpenVR's "
    "GetProjectionRaw gives top and bottom with the opposite sign";

constexpr std::array<TangentRule, 4> kTangentRules = {{
    {"tan_left", &rig::Tangents::left, true, kHorizontalSignHint},
    {"tan_right", &rig::Tangents::right, false, kHorizontalSignHint},
    {"tan_down", &rig::Tangents::down, true, kVerticalSignHint},
    {"tan_up", &rig::Tangents::up, false, kVerticalSignHint},
}};

// Integers are accepted where a real number is expected: `tan_up = 1` means 1.0.
std::optional<double> read_finite_number(const toml::node& node, std::string_view qualified_key,
                                         TomlProblems& problems) {
    double value = 0.0;
    if (const auto* integer = node.as_integer()) {
        value = static_cast<double>(integer->get());
    } else if (const auto* real = node.as_floating_point()) {
        value = real->get();
    } else {
        report_wrong_type(node, qualified_key, "a number", problems);
        return std::nullopt;
    }
    if (!std::isfinite(value)) {
        problems.add(node.source(), "key " + in_quotes(qualified_key) +
                                        " must be a finite number, got " + format_number(value));
        return std::nullopt;
    }
    return value;
}

std::optional<std::string> read_name(const TomlScope& root, TomlProblems& problems) {
    const toml::node* node = find_required(root, "name", "a string", problems);
    if (node == nullptr) return std::nullopt;
    const auto* text = node->as_string();
    if (text == nullptr) {
        report_wrong_type(*node, "name", "a string", problems);
        return std::nullopt;
    }
    if (text->get().empty()) {
        problems.add(node->source(), "key 'name' must not be empty");
        return std::nullopt;
    }
    return text->get();
}

std::optional<double> read_ipd(const TomlScope& root, TomlProblems& problems) {
    const toml::node* node = find_required(root, "ipd", "a number of metres", problems);
    if (node == nullptr) return std::nullopt;
    const std::optional<double> ipd = read_finite_number(*node, "ipd", problems);
    if (!ipd) return std::nullopt;
    // 0 is allowed: the rig's degenerate but well-defined case (C coincides with the eyes).
    if (*ipd < 0.0 || *ipd > kMaxIpd) {
        std::string message = "key 'ipd' = " + format_number(*ipd) + " is outside [0, " +
                              format_number(kMaxIpd) + "] metres";
        if (*ipd >= 1.0) message += " (millimetres? write 0.064 for 64 mm)";
        problems.add(node->source(), message);
        return std::nullopt;
    }
    return ipd;
}

std::optional<int> read_pixels(const TomlScope& root, std::string_view key,
                               TomlProblems& problems) {
    const toml::node* node = find_required(root, key, "an integer number of pixels", problems);
    if (node == nullptr) return std::nullopt;
    const auto* integer = node->as_integer();
    if (integer == nullptr) {
        report_wrong_type(*node, key, "an integer number of pixels", problems);
        return std::nullopt;
    }
    const std::int64_t pixels = integer->get();
    if (pixels < kMinPixels || pixels > kMaxPixels) {
        problems.add(node->source(), "key " + in_quotes(key) + " = " + std::to_string(pixels) +
                                         " is outside [" + std::to_string(kMinPixels) + ", " +
                                         std::to_string(kMaxPixels) + "] pixels");
        return std::nullopt;
    }
    return static_cast<int>(pixels);
}

std::optional<double> read_tangent(const TomlScope& eye, const TangentRule& rule,
                                   TomlProblems& problems) {
    const toml::node* node = find_required(eye, rule.key, "a number", problems);
    if (node == nullptr) return std::nullopt;
    const std::string key = eye.qualified(rule.key);
    const std::optional<double> tangent = read_finite_number(*node, key, problems);
    if (!tangent) return std::nullopt;
    if (rule.negative ? !(*tangent < 0.0) : !(*tangent > 0.0)) {
        problems.add(node->source(), "key " + in_quotes(key) + " must be " +
                                         (rule.negative ? "negative" : "positive") + ", got " +
                                         format_number(*tangent) + " (" +
                                         std::string(rule.sign_hint) + ")");
        return std::nullopt;
    }
    if (std::abs(*tangent) > kMaxAbsTangent) {
        problems.add(node->source(),
                     "key " + in_quotes(key) + " = " + format_number(*tangent) +
                         " is implausible: |tangent| must not exceed " +
                         format_number(kMaxAbsTangent) +
                         " (84 degrees from the view axis); is it an angle in degrees?");
        return std::nullopt;
    }
    return tangent;
}

// The bound on cant_deg: the rig's (rig/rig.h kMaxCant), in degrees.
constexpr double kMaxCantDegrees = 45.0;

// cant_deg: the eye's yaw about the head's +y axis in degrees, positive turning it left
// (docs/headsets.md, "Canted headsets"); 0 when absent.
std::optional<double> read_cant(const TomlScope& eye, TomlProblems& problems) {
    const toml::node* node = eye.table.get("cant_deg");
    if (node == nullptr) return 0.0;
    const std::string key = eye.qualified("cant_deg");
    const std::optional<double> cant = read_finite_number(*node, key, problems);
    if (!cant) return std::nullopt;
    if (std::abs(*cant) > kMaxCantDegrees) {
        problems.add(node->source(), "key " + in_quotes(key) + " = " + format_number(*cant) +
                                         " is implausible: |cant_deg| must not exceed " +
                                         format_number(kMaxCantDegrees) +
                                         " degrees (no headset turns its displays further)");
        return std::nullopt;
    }
    return cant;
}

struct EyeReading {
    rig::Tangents tangents;
    double cant_deg = 0.0;
};

std::optional<EyeReading> read_eye(const TomlScope& root, std::string_view eye_name,
                                   TomlProblems& problems) {
    const toml::node* node = find_required(root, eye_name, "a table of four tangents", problems);
    if (node == nullptr) return std::nullopt;
    const toml::table* table = node->as_table();
    if (table == nullptr) {
        report_wrong_type(
            *node, eye_name,
            "a table ([" + std::string(eye_name) + "] with tan_left, tan_right, tan_down, tan_up)",
            problems);
        return std::nullopt;
    }
    const TomlScope eye{*table, std::string(eye_name)};
    report_unknown_keys(eye, kEyeKeys, problems);
    const std::optional<double> cant = read_cant(eye, problems);
    rig::Tangents tangents;
    bool complete = cant.has_value();
    for (const TangentRule& rule : kTangentRules) {
        const std::optional<double> tangent = read_tangent(eye, rule, problems);
        if (tangent) {
            tangents.*rule.field = *tangent;
        } else {
            complete = false;
        }
    }
    if (!complete) return std::nullopt;
    return EyeReading{tangents, *cant};
}

}  // namespace

Result<HmdProfile> parse_hmd_profile(std::string_view toml_text, std::string_view source_name) {
    Result<toml::table> document = parse_toml(toml_text, source_name);
    MONOPLANE_TRY(document);

    // Every reader records its problems and goes on, so the user sees all of them at once.
    TomlProblems problems(source_name);
    const TomlScope root{*document, ""};
    report_unknown_keys(root, kTopLevelKeys, problems);
    std::optional<std::string> name = read_name(root, problems);
    const std::optional<double> ipd = read_ipd(root, problems);
    const std::optional<int> width = read_pixels(root, "width", problems);
    const std::optional<int> height = read_pixels(root, "height", problems);
    const std::optional<EyeReading> left = read_eye(root, "left", problems);
    const std::optional<EyeReading> right = read_eye(root, "right", problems);
    if (!problems.empty()) return problems.error();

    // A reader returns nullopt only after recording a problem.
    return HmdProfile{.name = std::move(*name),
                      .ipd = *ipd,
                      .width = *width,
                      .height = *height,
                      .left = left->tangents,
                      .right = right->tangents,
                      .cant_deg = {left->cant_deg, right->cant_deg},
                      .source = std::string(source_name)};
}

}  // namespace monoplane::hmd
