// Descriptive summaries: decision times and switch counts per scene (Fink et al. 2019 sect. 6.2
// found neither to interact with the distance), choice rates by the scene seen first (the
// paper's order effect: 40 % hybrid choices after SPHERES first, 37 % after LANDSCAPE, 29 % after
// BEAMS), and the questionnaire's Likert items.
#pragma once

#include <string>
#include <vector>

#include "analysis/choice_rates.h"
#include "analysis/dataset.h"

namespace monoplane::analysis {

struct Summary {
    int n = 0;
    // With n == 0 all are 0; with n == 1, sd is 0.
    double mean = 0, sd = 0, median = 0, q1 = 0, q3 = 0, min = 0, max = 0;
};

// sd with the n - 1 denominator; median and quartiles are Hyndman & Fan type 7 quantiles (R's
// and numpy's default): position (n - 1) p in the sorted values, linearly interpolated.
Summary summarize(std::vector<double> values);

// The type-7 quantile at probability p of values sorted ascending (not empty, 0 <= p <= 1).
double quantile_sorted(const std::vector<double>& sorted, double p);

struct GroupSummary {
    std::string group;
    Summary summary;
};

// Over the analysable trials, one group per scene (alphabetical).
std::vector<GroupSummary> decision_times_by_scene(const std::vector<TrialRow>& trials);
std::vector<GroupSummary> switches_by_scene(const std::vector<TrialRow>& trials);

// Order effects: one rate per first scene (alphabetical; ChoiceRate::scene holds the first
// scene), over all the analysable trials of the sessions that began with it. Trials of sessions
// without a block 0 (first_scene "") are grouped under "".
std::vector<ChoiceRate> rates_by_first_scene(const std::vector<TrialRow>& trials);

struct ItemSummary {
    int item = 0;
    std::string text;
    int scale_points = 7;
    Summary summary;
    std::vector<int> counts;  // counts[k - 1]: answers k, for k = 1 .. scale_points
};

// One per item (ascending item number), text and scale of the item's first answer. Answers
// outside 1 .. scale_points are counted in the summary but not in `counts` (the database's CHECK
// constraint keeps them out; a hand-made row might not).
std::vector<ItemSummary> questionnaire_summaries(const std::vector<AnswerRow>& answers);

}  // namespace monoplane::analysis
