// How well a procedure recovers a known threshold (issue 21, the validation by simulation of
// docs/analysis.md): estimates of simulated observers' thresholds after n answers, by two
// estimators, and per estimator and n their coverage, bias and precision.
//
// Estimators: "posterior" is QUEST+'s (study/quest_plus.h: the posterior mean of log T and the
// equal-tailed 95 % credible interval, the protocol's grid, or QUEST+'s default grid for a
// constant procedure: the same Bayesian estimate of trials placed otherwise); "ml" is analyze's
// maximum-likelihood fit with its 95 % profile-likelihood interval (analysis/psychometric_fits.h).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/proportion.h"
#include "study/protocol_staircase.h"

namespace monoplane::app {

// One valid decision of a scene: shown at m, reference chosen or not.
struct Answer {
    double m = 0.0;
    bool reference = false;
};

struct RecoveryEstimate {
    int run = 0;
    std::string scene;
    std::string estimator;  // "posterior" or "ml"
    int trials = 0;         // the scene's first `trials` answers (its slots offered)
    int answers = 0;        // of which it had: fewer when a stopping rule ended it sooner
    bool estimable = false;
    double threshold_m = 0.0;
    std::optional<double> lower_m, upper_m;  // an unset end: the interval is open that side
};

// The posterior estimate after each n in `checkpoints` (1 <= n <= answers.size(), ascending).
void add_posterior_estimates(int run, const std::string& scene, const std::vector<Answer>& answers,
                             const study::StaircaseSettings& settings,
                             const std::vector<double>& mono_planes,
                             const std::vector<int>& checkpoints,
                             std::vector<RecoveryEstimate>& out);
// analyze's fit of the first n answers for each n in `checkpoints`.
void add_ml_estimates(int run, const std::string& scene, const std::vector<Answer>& answers,
                      const std::vector<int>& checkpoints, std::vector<RecoveryEstimate>& out);

struct RecoverySummary {
    std::string estimator;
    int trials = 0;
    int estimates = 0;          // runs x scenes
    double mean_answers = 0.0;  // the answers the estimates used, on average
    int estimable = 0;
    // Intervals that hold the true threshold; a fit that is not estimable counts as a miss.
    int covered = 0;
    double coverage = 0.0;
    analysis::Interval coverage_ci;  // 95 % Wilson: the simulation's own uncertainty
    // Over the estimable: mean log10(estimate / true) with its standard error, and the root
    // mean square of the same (precision).
    double bias_log10 = 0.0, bias_log10_se = 0.0, rmse_log10 = 0.0;
    // The median width log10(upper / lower) of the intervals closed on both sides (NaN: none).
    double median_width_log10 = 0.0;
};

// One summary per (estimator, trials), ordered by estimator then trials.
std::vector<RecoverySummary> summarise_recovery(const std::vector<RecoveryEstimate>& estimates,
                                                double true_threshold_m);

// The fewest trials per scene from which on `estimator` has an RMSE of log10 at most
// precision_log10 with at least 95 % of its fits estimable at every later checkpoint too;
// nullopt if its last checkpoint does not. `summaries` as summarise_recovery orders them.
std::optional<int> trials_to_precision(const std::vector<RecoverySummary>& summaries,
                                       std::string_view estimator, double precision_log10);

// The estimates as CSV (run,scene,estimator,trials,answers,estimable,threshold_m,lower_m,
// upper_m,covered; NA for what is missing or open).
std::string recovery_csv(const std::vector<RecoveryEstimate>& estimates, double true_threshold_m);

}  // namespace monoplane::app
