// The protocol's `procedure` key and [staircase] table (issue 21): whether each scene is shown
// once at every listed distance (constant, papers/000's design) or an adaptive procedure places
// each next trial's mono plane from the participant's earlier answers. Plain data, validated with
// located errors like the rest of the protocol; the procedures themselves are in study/quest_plus.h
// and study/weighted_up_down.h.
#pragma once

#include <array>
#include <optional>
#include <string_view>
#include <vector>

#include "common/toml/toml_keys.h"

namespace monoplane::study {

enum class Procedure {
    Constant,   // every scene x distance once (the default)
    Staircase,  // one adaptive staircase per scene, trials interleaved
};

enum class StaircaseRule {
    // Watson (2017): a posterior over a threshold x slope x lapse grid; each next m is the
    // candidate that minimises the expected entropy of the posterior after the answer.
    QuestPlus,
    // Kaernbach (1991): m farther by step_log10 after a reference choice, nearer by
    // step_log10 * target / (1 - target) after a test choice: converges on P(reference) = target.
    WeightedUpDown,
};

std::string_view procedure_name(Procedure procedure);      // "constant", "staircase"
std::string_view staircase_rule_name(StaircaseRule rule);  // "quest+", "weighted-up-down"

struct StaircaseSettings {
    StaircaseRule rule = StaircaseRule::QuestPlus;
    // Stopping rule 1: the most trials a scene's staircase gets (its slots in the schedule).
    int trials_per_scene = 40;
    // Stopping rule 2 (QUEST+ only): a scene's staircase stops once the posterior standard
    // deviation of log10(threshold) is at most this, but not before min_trials_per_scene.
    std::optional<double> stop_sd_log10;
    int min_trials_per_scene = 10;

    // QUEST+: the parameter grid, with a uniform prior over it. Thresholds are threshold_steps
    // values evenly spaced in log m between the ends of threshold_range (default: the ends of
    // mono_planes). The stimuli are the protocol's mono_planes themselves.
    std::optional<std::array<double, 2>> threshold_range;
    int threshold_steps = 40;
    std::vector<double> slopes = {1.0, 2.0, 3.0, 4.0, 6.0, 8.0};
    std::vector<double> lapses = {0.0, 0.02, 0.04};

    // Weighted up-down: the probability of choosing the reference it converges on, the step
    // after a reference choice (log10 m; farther), and the first trial's m (default: the
    // geometric mean of the ends of mono_planes). m stays within the ends of mono_planes.
    double target = 0.75;
    double step_log10 = 0.05;
    std::optional<double> start_m;
    // The estimate: the geometric mean of m at the reversals after the first skip_reversals.
    int skip_reversals = 2;

    bool operator==(const StaircaseSettings&) const = default;
};

// Reads `procedure` and [staircase] from the protocol's root. `mono_planes` are the protocol's
// validated distances (the staircase's range); empty when they had problems, and then the checks
// against them are skipped. Reports, located: an unknown procedure (with "did you mean"), a
// staircase procedure without [staircase] or [staircase] without it, unknown keys, a missing
// rule or trials_per_scene, wrong types, values out of range (trials 1..1000, min_trials at most
// trials, stop_sd_log10 > 0, threshold_steps 2..400, slopes > 0, lapses in [0, 0.5), a
// threshold_range outside (0, inf) or not increasing, target in (0.5, 1), step_log10 in (0, 1],
// start_m outside the ends of mono_planes), keys of the other rule, and fewer than two
// mono_planes for a staircase. Any time.
void read_procedure(const TomlScope& root, const std::vector<double>& mono_planes,
                    Procedure& procedure, StaircaseSettings& settings, TomlProblems& problems);

}  // namespace monoplane::study
