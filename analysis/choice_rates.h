// How often the test alternative (e.g. hybrid) was chosen over the reference (e.g. stereo), per
// scene, per mono-plane distance and per both: Fink et al. 2019 sect. 6.2 and Fig. 7 (SPHERES
// 175 of 452 decisions for hybrid, 38.72 %). Each rate has Wilson and Clopper-Pearson 95 %
// intervals and an exact two-sided binomial test against 50 % (analysis/proportion.h).
//
// All functions take trial rows and use only those analysable_trials() keeps (decided, valid,
// not practice), so passing every trial gives the same answer as passing the kept ones. The
// rates pool trials across participants: each participant contributes one trial per scene x
// distance, so per-cell rates are descriptive; for inference over distance and scene with
// repeated measures use fit_choice_model() (logistic_regression.h).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include "analysis/dataset.h"
#include "analysis/proportion.h"

namespace monoplane::analysis {

struct ChoiceRate {
    std::string scene;                                             // "" when pooled over scenes
    double mono_plane = std::numeric_limits<double>::quiet_NaN();  // NaN: all distances
    int test_chosen = 0;
    int n = 0;
    // test_chosen / n. With n == 0 (no trials): rate 0, intervals [0, 1], binomial_p 1.
    double rate = 0;
    Interval wilson, clopper_pearson;  // 95 %
    double binomial_p = 1.0;           // exact two-sided, against 50 %
};

// The rate of a set of trials; `scene` and `mono_plane` label it.
ChoiceRate choice_rate(const std::vector<TrialRow>& trials, std::string scene = "",
                       double mono_plane = std::numeric_limits<double>::quiet_NaN());

// One per scene (alphabetical), mono_plane NaN.
std::vector<ChoiceRate> rates_by_scene(const std::vector<TrialRow>& trials);
// One per distance (ascending), scene "" (all scenes).
std::vector<ChoiceRate> rates_by_distance(const std::vector<TrialRow>& trials);
// One per scene x distance present, by scene then distance.
std::vector<ChoiceRate> rates_by_scene_and_distance(const std::vector<TrialRow>& trials);
// All analysable trials: scene "", mono_plane NaN.
ChoiceRate overall_rate(const std::vector<TrialRow>& trials);

}  // namespace monoplane::analysis
