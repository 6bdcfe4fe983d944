// The 2AFC psychometric function and its maximum-likelihood fit (docs/analysis.md):
//
//     P(reference chosen at m) = 0.5 + (0.5 - lapse) / (1 + (m / threshold)^slope)
//
// Near the eyes (m << threshold) hybrid's error is plain and the reference is chosen with
// probability 1 - lapse (the lapse rate: answers given without looking, Wichmann & Hill 2001);
// far beyond the threshold the alternatives look alike and the choice is a coin flip (0.5). At
// m = threshold the reference is chosen with probability 0.75 - lapse / 2, halfway between. The
// slope is the steepness over log m: doubling m around the threshold takes P from
// 0.5 + (0.5 - lapse) / (1 + 2^-slope) to 0.5 + (0.5 - lapse) / (1 + 2^slope).
//
// Why a fit: with a constant procedure (papers/000: ten distances, one decision each) nothing
// says where m becomes indistinguishable; the threshold with its interval does.
#pragma once

#include <optional>
#include <vector>

namespace monoplane::analysis {

struct PsychometricParameters {
    double threshold = 1.0;  // metres, > 0
    double slope = 1.0;      // > 0
    double lapse = 0.0;      // in [0, 0.5)
};

// The probability above; requires m > 0 and valid parameters (asserted).
double reference_probability(const PsychometricParameters& parameters, double m);

// The decisions at one mono-plane distance: `reference` of `trials` chose the reference.
struct StimulusLevel {
    double m = 0.0;  // metres, > 0
    int reference = 0;
    int trials = 0;
};

// The parameter space the fit searches. Thresholds a decade beyond the tested distances either
// way are allowed so that an estimate outside them shows as such instead of sticking to the
// last distance; the slope's upper end stands for "a step" (perfectly separated data); the lapse
// rate is limited as Wichmann & Hill (2001) recommend, here to 0.1, so a few stray answers near
// the eyes do not drag the whole curve towards chance.
struct PsychometricBounds {
    double threshold_min = 0.1, threshold_max = 100.0;  // metres
    double slope_min = 0.2, slope_max = 50.0;
    double lapse_min = 0.0, lapse_max = 0.1;
};

// Threshold bounds of a decade below the smallest and above the largest m of `levels`, the rest
// as the defaults. Requires at least one level.
PsychometricBounds bounds_for(const std::vector<StimulusLevel>& levels);

// Sum over levels of k log P + (n - k) log(1 - P) (without the binomial coefficients, which do
// not depend on the parameters). Finite for every parameter value inside the bounds.
double psychometric_log_likelihood(const std::vector<StimulusLevel>& levels,
                                   const PsychometricParameters& parameters);

struct PsychometricMaximum {
    PsychometricParameters parameters;
    double log_likelihood = 0.0;
};

// The maximum-likelihood parameters within `bounds`: bounded quasi-Newton (NLopt's L-BFGS over
// log threshold, log slope and lapse, with the analytic gradient) from the best few points of a
// coarse grid, so a local maximum of a ragged small-sample likelihood is not taken for the
// global one. With `fixed_threshold` the threshold is held there and only slope and lapse are
// fitted (the profile likelihood). Requires at least one level with trials > 0 and a
// fixed_threshold within the bounds; any data give an answer (a threshold on a bound when the
// data do not locate it: callers check).
PsychometricMaximum maximize_psychometric_likelihood(
    const std::vector<StimulusLevel>& levels, const PsychometricBounds& bounds,
    std::optional<double> fixed_threshold = std::nullopt);

// The threshold's profile-likelihood interval: the thresholds whose profile log-likelihood lies
// within chi-square(1, confidence) / 2 of the maximum (Venzon & Moolgavkar 1988), searched
// within [search_min, search_max] (the tested distances); an end that lies beyond them is
// nullopt: the data do not bound the threshold on that side. Requires `maximum` from
// maximize_psychometric_likelihood on the same levels and bounds, search_min <= its threshold
// <= search_max, and 0 < confidence < 1.
struct ThresholdInterval {
    std::optional<double> lower, upper;
};
ThresholdInterval profile_threshold_interval(const std::vector<StimulusLevel>& levels,
                                             const PsychometricBounds& bounds,
                                             const PsychometricMaximum& maximum, double search_min,
                                             double search_max, double confidence = 0.95);

}  // namespace monoplane::analysis
