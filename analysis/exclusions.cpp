#include "analysis/exclusions.h"

namespace monoplane::analysis {

bool is_analysable(const TrialRow& trial) {
    return !trial.practice && trial.decided && trial.valid;
}

std::vector<TrialRow> analysable_trials(const std::vector<TrialRow>& trials, Exclusions& excluded) {
    excluded = {};
    std::vector<TrialRow> kept;
    for (const TrialRow& trial : trials) {
        if (trial.practice) {
            ++excluded.practice;
        } else if (!trial.decided) {
            ++excluded.undecided;
        } else if (!trial.valid) {
            ++excluded.invalid;
        } else {
            kept.push_back(trial);
        }
    }
    excluded.kept = static_cast<int>(kept.size());
    return kept;
}

}  // namespace monoplane::analysis
