// Which trials enter the statistics. Fink et al. 2019 (sect. 6.2) drop the 48 of 1410 decisions
// made without viewing both alternatives; practice trials are not data, and an undecided trial
// (an aborted session) has no outcome.
#pragma once

#include <vector>

#include "analysis/dataset.h"

namespace monoplane::analysis {

struct Exclusions {
    int practice = 0;
    int undecided = 0;
    int invalid = 0;
    int kept = 0;
};

// True for a decided, valid, non-practice trial.
bool is_analysable(const TrialRow& trial);

// Keeps the analysable trials, in input order, and counts what was left out: each trial counts
// once, under the first reason in the order practice, undecided, invalid. `excluded` is
// overwritten.
std::vector<TrialRow> analysable_trials(const std::vector<TrialRow>& trials, Exclusions& excluded);

}  // namespace monoplane::analysis
