// Logistic regression of the choice (test alternative chosen, e.g. hybrid over stereo) on the
// mono-plane distance (or, where the sessions recorded eye gaze, hybrid's error at the gaze
// point) and the scene, with standard errors clustered by participant.
//
// Why: Fink et al. 2019 (sect. 6.2) test distance x decision with a pooled chi-square
// (phi = 0.07, p > 0.05), which treats the 1362 decisions as independent. They are not: each of
// the 47 participants made 30 of them, and participants differ in how readily they spot the
// difference (the paper's order effect). A cluster-robust (sandwich) covariance keeps the
// population-averaged estimates of an ordinary logistic regression but lets its standard errors
// reflect the correlation within a participant (Liang & Zeger 1986; Cameron & Miller 2015).
#pragma once

#include <string>
#include <vector>

#include "analysis/dataset.h"
#include "common/result.h"

namespace monoplane::analysis {

struct Coefficient {
    std::string name;
    double estimate = 0;                // log odds (ratio)
    double std_error = 0;               // cluster-robust
    double z = 0;                       // estimate / std_error
    double p = 1;                       // two-sided, standard normal
    double odds_ratio = 1;              // exp(estimate)
    double ci_lower = 0, ci_upper = 0;  // 95 % interval of the odds ratio: exp(b -+ 1.96 se)
    // Small-sample inference (small_sample_covariance.h), which holds its error rate with few
    // participants: the CR2 standard error, t = estimate / std_error_cr2 referred to Student's t
    // with df_cr2 (Satterthwaite) degrees of freedom, its two-sided p, and the odds ratio's 95 %
    // interval exp(b -+ t(df_cr2, 0.975) std_error_cr2).
    double std_error_cr2 = 0;
    double t_cr2 = 0;
    double df_cr2 = 0;
    double p_cr2 = 1;
    double ci_lower_cr2 = 0, ci_upper_cr2 = 0;
};

struct LogisticFit {
    // In column order: "intercept", distance_term, then "scene[NAME]" for each scene but the
    // first in alphabetical order (the baseline, absorbed by the intercept).
    std::vector<Coefficient> coefficients;
    int n = 0;         // trials used
    int clusters = 0;  // participants
    int iterations = 0;
    bool converged = false;  // always true in a returned fit: non-convergence is an error
    double log_likelihood = 0;
    // The predictor's term (named for the default predictor, the distance): "mono_plane_m",
    // "log2_mono_plane_m" or "gaze_error_test_arcmin".
    std::string distance_term = "mono_plane_m";
    // Analysable trials left out because they have no value of the predictor (a gaze error:
    // trials of sessions that recorded no gaze, or without a gaze point on the test alternative).
    // Always 0 for the distance.
    int skipped_without_predictor = 0;
};

// What the choice is regressed on.
enum class ChoicePredictor {
    Distance,   // the mono-plane distance m (metres, or log2 with log2_distance)
    GazeError,  // TrialRow::gaze_error_test_arcmin: hybrid's error where the participant looked
};

struct LogisticOptions {
    ChoicePredictor predictor = ChoicePredictor::Distance;
    // Distance as log2(metres): one unit per doubling, closer to the projection error's fall
    // with 1/m (section 3) than metres are. Only for the distance predictor.
    bool log2_distance = false;
    // One dummy per scene but the first; false fits choice ~ distance alone.
    bool scene_terms = true;
};

// Fits P(test chosen) = 1 / (1 + exp(-x b)) by iteratively reweighted least squares (Newton's
// method) to the analysable trials (others are skipped; with the gaze error as predictor, so are
// trials without one, counted in skipped_without_predictor). Covariance: CR1 sandwich
// G/(G-1) * (N-1)/(N-K) * B^-1 M B^-1 with B = X'WX, M = sum over participants g of
// s_g s_g', s_g = sum of x_i (y_i - p_i) over g's trials; as Stata's vce(cluster) and statsmodels'
// cov_type="cluster" default, with normal (z) tests; and beside it CR2 with Satterthwaite t tests
// (the *_cr2 fields). May be called any time. Errors: no more trials than coefficients, fewer than
// 2 participants, fewer than 2 distances (gaze errors), a distance <= 0 with log2_distance, a
// singular design (e.g. a scene confounded with distance), (quasi-)complete separation (one outcome
// only, a scene where everyone chose the same, fitted probabilities of 0 or 1, or no convergence).
// The name the fits give the predictor's coefficient (LogisticFit::distance_term) under `options`.
std::string predictor_term(const LogisticOptions& options);

Result<LogisticFit> fit_choice_model(const std::vector<TrialRow>& trials,
                                     const LogisticOptions& options = {});

}  // namespace monoplane::analysis
