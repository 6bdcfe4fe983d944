// Reading `procedure` and [staircase] (protocol_staircase.h). Each reader records its problems and
// goes on, as protocol.cpp's do, so a user sees every mistake of the table at once.
#include "common/quoted.h"
#include "study/protocol_staircase.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

namespace monoplane::study {
namespace {

constexpr std::array<std::string_view, 2> kProcedures = {"constant", "staircase"};
constexpr std::array<std::string_view, 2> kRules = {"quest+", "weighted-up-down"};
constexpr std::array<std::string_view, 4> kCommonKeys = {"rule", "trials_per_scene",
                                                         "min_trials_per_scene", "stop_sd_log10"};
constexpr std::array<std::string_view, 4> kQuestKeys = {"threshold_range", "threshold_steps",
                                                        "slopes", "lapses"};
constexpr std::array<std::string_view, 4> kUpDownKeys = {"target", "step_log10", "start_m",
                                                         "skip_reversals"};

// A staircase of more than 1000 trials per scene is a typo, not a session.
constexpr std::int64_t kMaxTrialsPerScene = 1000;
// A grid of 2 thresholds locates nothing finer than the range; 400 is far finer than any study
// resolves, and keeps one QUEST+ update at a few milliseconds.
constexpr std::int64_t kMinThresholdSteps = 2;
constexpr std::int64_t kMaxThresholdSteps = 400;

std::string qualified(std::string_view key) {
    return "staircase." + std::string(key);
}

// One of `names`, or nothing after a problem that lists them and suggests the closest.
std::optional<std::string_view> read_name(const toml::node& node, const std::string& key,
                                          std::span<const std::string_view> names,
                                          TomlProblems& problems) {
    const std::optional<std::string> text = node.value<std::string>();
    if (!text) {
        report_wrong_type(node, key, "a string, one of " + join(names), problems);
        return std::nullopt;
    }
    const auto found = std::ranges::find(names, *text);
    if (found != names.end()) return *found;
    std::string message = toml_key_prefix(key) + "unknown value " + in_quotes(*text) +
                          " (allowed: " + join(names) + ")";
    const std::string_view closest = closest_match(*text, names);
    if (!closest.empty()) message += "; did you mean " + in_quotes(closest) + "?";
    problems.add(node.source(), message);
    return std::nullopt;
}

// A real number (integers accepted) that satisfies `valid`; else a problem saying `expected`.
template <class Valid>
std::optional<double> read_real(const toml::node& node, const std::string& key,
                                std::string_view expected, Valid valid, TomlProblems& problems) {
    const std::optional<double> value =
        read_number(node, key, "a number " + std::string(expected), problems);
    if (!value) return std::nullopt;
    if (!std::isfinite(*value) || !valid(*value)) {
        problems.add(node.source(), toml_key_prefix(key) + format_number(*value) + " is not " +
                                        std::string(expected));
        return std::nullopt;
    }
    return value;
}

std::optional<int> read_count(const toml::node& node, const std::string& key, std::int64_t low,
                              std::int64_t high, TomlProblems& problems) {
    const std::optional<std::int64_t> count = read_integer_in(node, key, low, high, problems);
    if (!count) return std::nullopt;
    return static_cast<int>(*count);
}

// A non-empty array of numbers, each satisfying `valid`, none repeated; nothing when any is not.
template <class Valid>
std::optional<std::vector<double>> read_reals(const toml::node& node, const std::string& key,
                                              std::string_view expected, Valid valid,
                                              TomlProblems& problems) {
    const toml::array* array = node.as_array();
    if (array == nullptr || array->empty()) {
        if (array == nullptr) {
            report_wrong_type(node, key, "an array of numbers " + std::string(expected), problems);
        } else {
            problems.add(node.source(), toml_key_prefix(key) + "must not be empty");
        }
        return std::nullopt;
    }
    std::vector<double> values;
    bool all_valid = true;
    for (std::size_t i = 0; i < array->size(); ++i) {
        const std::optional<double> value = read_real(
            (*array)[i], key + " element " + std::to_string(i + 1), expected, valid, problems);
        if (!value) {
            all_valid = false;
        } else if (std::ranges::find(values, *value) != values.end()) {
            problems.add((*array)[i].source(), toml_key_prefix(key) + "duplicate value " +
                                                   format_number(*value) + "; list each once");
            all_valid = false;
        } else {
            values.push_back(*value);
        }
    }
    if (!all_valid) return std::nullopt;
    return values;
}

void read_threshold_range(const toml::node& node, StaircaseSettings& settings,
                          TomlProblems& problems) {
    const std::string key = qualified("threshold_range");
    const auto positive = [](double v) { return v > 0.0; };
    std::optional<std::vector<double>> ends =
        read_reals(node, key, "> 0 (metres)", positive, problems);
    if (!ends) return;
    if (ends->size() != 2 || !((*ends)[0] < (*ends)[1])) {
        problems.add(node.source(), toml_key_prefix(key) +
                                        "must be two distances in metres, the smaller first, "
                                        "e.g. [1, 40]");
        return;
    }
    settings.threshold_range = std::array<double, 2>{(*ends)[0], (*ends)[1]};
}

void read_quest_keys(const toml::table& table, StaircaseSettings& settings,
                     TomlProblems& problems) {
    if (const toml::node* node = table.get("threshold_range")) {
        read_threshold_range(*node, settings, problems);
    }
    if (const toml::node* node = table.get("threshold_steps")) {
        if (auto steps = read_count(*node, qualified("threshold_steps"), kMinThresholdSteps,
                                    kMaxThresholdSteps, problems)) {
            settings.threshold_steps = *steps;
        }
    }
    if (const toml::node* node = table.get("slopes")) {
        const auto positive = [](double v) { return v > 0.0; };
        if (auto slopes = read_reals(*node, qualified("slopes"), "> 0", positive, problems)) {
            settings.slopes = std::move(*slopes);
        }
    }
    if (const toml::node* node = table.get("lapses")) {
        // A lapse rate of 0.5 or more leaves the reference no more likely than chance anywhere.
        const auto rate = [](double v) { return v >= 0.0 && v < 0.5; };
        if (auto lapses = read_reals(*node, qualified("lapses"), "in [0, 0.5)", rate, problems)) {
            settings.lapses = std::move(*lapses);
        }
    }
}

void read_up_down_keys(const toml::table& table, const std::vector<double>& mono_planes,
                       StaircaseSettings& settings, TomlProblems& problems) {
    if (const toml::node* node = table.get("target")) {
        // 2AFC: the reference is chosen with probability between 0.5 (chance) and 1.
        const auto inside = [](double v) { return v > 0.5 && v < 1.0; };
        if (auto target = read_real(*node, qualified("target"), "in (0.5, 1), a 2AFC probability",
                                    inside, problems)) {
            settings.target = *target;
        }
    }
    if (const toml::node* node = table.get("step_log10")) {
        const auto inside = [](double v) { return v > 0.0 && v <= 1.0; };
        if (auto step = read_real(*node, qualified("step_log10"), "in (0, 1] (log10 m)", inside,
                                  problems)) {
            settings.step_log10 = *step;
        }
    }
    if (const toml::node* node = table.get("skip_reversals")) {
        if (auto skip = read_count(*node, qualified("skip_reversals"), 0, 100, problems)) {
            settings.skip_reversals = *skip;
        }
    }
    if (const toml::node* node = table.get("start_m")) {
        const auto ends = std::ranges::minmax(
            mono_planes.empty() ? std::vector<double>{0.0, INFINITY} : mono_planes);
        const double low = ends.min, high = ends.max;
        const std::string range = "within the ends of mono_planes [" + format_number(low) + ", " +
                                  format_number(high) + "] m";
        const auto inside = [low, high](double v) { return v >= low && v <= high; };
        if (auto start = read_real(*node, qualified("start_m"), range, inside, problems)) {
            settings.start_m = *start;
        }
    }
}

// Keys of the rule not chosen are refused: they would silently do nothing.
void refuse_other_rule_keys(const toml::table& table, StaircaseRule rule, TomlProblems& problems) {
    const bool quest = rule == StaircaseRule::QuestPlus;
    const std::span<const std::string_view> others =
        quest ? std::span<const std::string_view>(kUpDownKeys)
              : std::span<const std::string_view>(kQuestKeys);
    const std::string other_rule(
        staircase_rule_name(quest ? StaircaseRule::WeightedUpDown : StaircaseRule::QuestPlus));
    for (std::string_view key : others) {
        if (const toml::node* node = table.get(key)) {
            problems.add(node->source(), toml_key_prefix(qualified(key)) + "applies to rule " +
                                             in_quotes(other_rule) + ", but the rule is " +
                                             in_quotes(staircase_rule_name(rule)));
        }
    }
    if (const toml::node* node = table.get("stop_sd_log10"); node != nullptr && !quest) {
        problems.add(node->source(), toml_key_prefix(qualified("stop_sd_log10")) +
                                         "needs a posterior, which rule 'weighted-up-down' "
                                         "has not; stop it by trials_per_scene");
    }
}

void read_stopping_rule(const toml::table& table, StaircaseSettings& settings,
                        TomlProblems& problems) {
    if (const toml::node* node = table.get("stop_sd_log10")) {
        const auto positive = [](double v) { return v > 0.0; };
        if (auto sd = read_real(*node, qualified("stop_sd_log10"), "> 0 (log10 units)", positive,
                                problems)) {
            settings.stop_sd_log10 = *sd;
        }
    }
    if (const toml::node* node = table.get("min_trials_per_scene")) {
        if (auto count = read_count(*node, qualified("min_trials_per_scene"), 1, kMaxTrialsPerScene,
                                    problems)) {
            if (*count > settings.trials_per_scene) {
                problems.add(
                    node->source(),
                    toml_key_prefix(qualified("min_trials_per_scene")) + std::to_string(*count) +
                        " exceeds trials_per_scene = " + std::to_string(settings.trials_per_scene));
            } else {
                settings.min_trials_per_scene = *count;
            }
        }
    }
}

void read_staircase_table(const toml::table& table, const std::vector<double>& mono_planes,
                          StaircaseSettings& settings, TomlProblems& problems) {
    const TomlScope scope{table, "staircase"};
    std::vector<std::string_view> known(kCommonKeys.begin(), kCommonKeys.end());
    known.insert(known.end(), kQuestKeys.begin(), kQuestKeys.end());
    known.insert(known.end(), kUpDownKeys.begin(), kUpDownKeys.end());
    report_unknown_keys(scope, known, problems);

    const std::string rules = "the rule: " + join(kRules);
    if (const toml::node* node = find_required(scope, "rule", rules, problems)) {
        if (auto name = read_name(*node, qualified("rule"), kRules, problems)) {
            settings.rule =
                *name == kRules[0] ? StaircaseRule::QuestPlus : StaircaseRule::WeightedUpDown;
            refuse_other_rule_keys(table, settings.rule, problems);
        }
    }
    if (const toml::node* node = find_required(scope, "trials_per_scene",
                                               "the most trials per scene, e.g. 40", problems)) {
        if (auto count =
                read_count(*node, qualified("trials_per_scene"), 1, kMaxTrialsPerScene, problems)) {
            settings.trials_per_scene = *count;
        }
    }
    settings.min_trials_per_scene =
        std::min(settings.min_trials_per_scene, settings.trials_per_scene);
    read_stopping_rule(table, settings, problems);
    read_quest_keys(table, settings, problems);
    read_up_down_keys(table, mono_planes, settings, problems);
}

}  // namespace

std::string_view procedure_name(Procedure procedure) {
    return kProcedures[procedure == Procedure::Constant ? 0 : 1];
}

std::string_view staircase_rule_name(StaircaseRule rule) {
    return kRules[rule == StaircaseRule::QuestPlus ? 0 : 1];
}

void read_procedure(const TomlScope& root, const std::vector<double>& mono_planes,
                    Procedure& procedure, StaircaseSettings& settings, TomlProblems& problems) {
    const toml::node* procedure_node = root.table.get("procedure");
    bool procedure_known = true;  // a wrong value was reported: no second problem from it
    if (procedure_node != nullptr) {
        const auto name = read_name(*procedure_node, "procedure", kProcedures, problems);
        procedure_known = name.has_value();
        if (name) procedure = *name == kProcedures[0] ? Procedure::Constant : Procedure::Staircase;
    }
    const toml::node* table_node = root.table.get("staircase");
    if (procedure == Procedure::Staircase && table_node == nullptr) {
        problems.add(procedure_node->source(),
                     toml_key_prefix("procedure") +
                         "'staircase' needs a [staircase] table naming the rule and "
                         "trials_per_scene");
    }
    if (procedure == Procedure::Staircase && !mono_planes.empty() && mono_planes.size() < 2) {
        problems.add(procedure_node->source(),
                     toml_key_prefix("procedure") +
                         "a staircase needs at least two mono_planes: their range is where it "
                         "places the trials");
    }
    if (table_node == nullptr) return;
    const toml::table* table = table_node->as_table();
    if (table == nullptr) {
        report_wrong_type(*table_node, "staircase", "a table ([staircase] with rule, ...)",
                          problems);
        return;
    }
    if (procedure != Procedure::Staircase && procedure_known) {
        problems.add(table_node->source(), toml_key_prefix("staircase") +
                                               "applies to procedure = 'staircase', but the "
                                               "procedure is 'constant'");
    }
    read_staircase_table(*table, mono_planes, settings, problems);
}

}  // namespace monoplane::study
