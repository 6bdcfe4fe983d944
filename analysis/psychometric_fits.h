// Psychometric functions (psychometric_function.h) fitted to a study's choices: one per
// participant and scene, and one per scene for the group, each with the threshold's 95 %
// interval or the reason the data cannot locate a threshold. `analyze` reports them
// (summary.json "psychometric", psychometric.csv, the report's figures).
//
// Intervals: a participant's from the profile likelihood (their trials are independent given
// their curve); the group's from a bootstrap over participants (Efron & Tibshirani 1993,
// percentile interval), because one participant's decisions are correlated and participants
// differ: resampling participants, not trials, carries both into the interval (Wichmann & Hill
// 2001b; Moscatelli et al. 2012 on pooling psychophysical data). The group curve itself is the
// maximum-likelihood fit to all participants' trials pooled.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/dataset.h"
#include "analysis/psychometric_function.h"

namespace monoplane::analysis {

struct PsychometricFit {
    std::string participant;  // participant code, or "all" for the group
    std::string scene;
    int n = 0;                          // analysable trials fitted
    int participants = 0;               // 1, or how many the group pools
    std::vector<StimulusLevel> levels;  // the data: reference choices per distance, ascending m
    bool estimable = false;
    std::string reason;  // why not, when !estimable
    // When estimable:
    PsychometricParameters parameters;
    double log_likelihood = 0.0;
    // The threshold's 95 % interval; an unset end lies beyond the tested distances (the data
    // do not bound the threshold on that side).
    std::optional<double> threshold_lower, threshold_upper;
    std::string interval_method;   // "profile likelihood" or "participant bootstrap"
    int bootstrap_replicates = 0;  // for the bootstrap
};

struct PsychometricOptions {
    int bootstrap_replicates = 1000;
    // The bootstrap's seed, fixed so that one data set always gives one report.
    std::uint64_t seed = 20190323;
    double confidence = 0.95;
};

// One fit per scene for the group ("all", first) followed by one per participant (codes in
// ascending order), scenes in ascending order, over the analysable trials (others are skipped).
// "Reference chosen" is a decided trial whose choice was not the test mode. Never fails: a fit
// the data cannot support is estimable = false with a reason (no trials, a single distance,
// the reference chosen in every trial, or a fitted threshold outside the tested distances, as
// with choices at chance everywhere). May be called any time.
std::vector<PsychometricFit> fit_psychometric_functions(const std::vector<TrialRow>& trials,
                                                        const PsychometricOptions& options = {});

// The fit of one set of levels, as above with the profile-likelihood interval; `participant`,
// `scene` and `participants` are left for the caller. Levels with no trials are ignored.
PsychometricFit fit_levels(std::vector<StimulusLevel> levels, double confidence = 0.95);

}  // namespace monoplane::analysis
