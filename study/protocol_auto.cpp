#include "study/protocol_auto.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace monoplane::study {
namespace {

constexpr std::array<std::string_view, 4> kAutoKeys = {"error_budget_arcmin", "measure",
                                                       "step_arcmin", "time_budget_ms"};
constexpr std::array<std::string_view, 2> kMeasures = {"eye", "disparity"};

std::optional<double> read_positive(const toml::table& table, std::string_view key,
                                    std::string_view unit, TomlProblems& problems) {
    const toml::node* node = table.get(key);
    if (node == nullptr) return std::nullopt;
    const std::string qualified = "auto." + std::string(key);
    const std::optional<double> value =
        read_number(*node, qualified, "a number of " + std::string(unit), problems);
    if (!value) return std::nullopt;
    if (!(std::isfinite(*value) && *value > 0.0)) {
        problems.add(node->source(), toml_key_prefix(qualified) + "is " + format_number(*value) +
                                         "; it must be a positive number of " + std::string(unit));
        return std::nullopt;
    }
    return value;
}

}  // namespace

void read_auto_plane(const TomlScope& root, bool uses_auto, AutoPlaneSettings& settings,
                     TomlProblems& problems) {
    const toml::node* node = root.table.get("auto");
    if (node == nullptr) return;
    const toml::table* table = node->as_table();
    if (table == nullptr) {
        report_wrong_type(*node, "auto", "a table ([auto] with error_budget_arcmin, ...)",
                          problems);
        return;
    }
    if (!uses_auto) {
        problems.add(node->source(), toml_key_prefix("auto") +
                                         "applies to a hybrid-auto alternative, but neither "
                                         "alternative is hybrid-auto");
    }
    const TomlScope scope{*table, "auto"};
    report_unknown_keys(scope, kAutoKeys, problems);
    if (auto v = read_positive(*table, "error_budget_arcmin", "arcminutes", problems)) {
        settings.error_budget_arcmin = *v;
    }
    if (auto v = read_positive(*table, "step_arcmin", "arcminutes", problems)) {
        settings.step_arcmin = *v;
    }
    if (auto v = read_positive(*table, "time_budget_ms", "milliseconds", problems)) {
        settings.time_budget_ms = *v;
    }
    if (const toml::node* measure = table->get("measure")) {
        const std::optional<std::string> name = measure->value<std::string>();
        if (!name) {
            report_wrong_type(*measure, "auto.measure", "a string: eye or disparity", problems);
        } else if (std::find(kMeasures.begin(), kMeasures.end(), *name) == kMeasures.end()) {
            problems.add(measure->source(), toml_key_prefix("auto.measure") + "'" + *name +
                                                "' is not eye or disparity");
        } else {
            settings.measure = *name;
        }
    }
}

}  // namespace monoplane::study
