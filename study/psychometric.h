// The 2AFC psychometric function (docs/analysis.md), for the study's side: the simulated
// observer that answers by it and the QUEST+ staircase that assumes it.
//
//     P(reference chosen at m) = 0.5 + (0.5 - lapse) / (1 + (m / threshold)^slope)
//
// analysis/psychometric_function.h fits the same function to recorded choices; study/ may not
// include analysis/ (docs/architecture.md), and the two are checked against each other by tests.
#pragma once

namespace monoplane::study {

struct PsychometricFunction {
    double threshold = 1.0;  // metres, > 0: where P = 0.75 - lapse / 2
    double slope = 1.0;      // > 0: steepness over log m
    double lapse = 0.0;      // in [0, 0.5): P tends to 1 - lapse near the eyes

    bool operator==(const PsychometricFunction&) const = default;
};

// The probability of choosing the reference at m, and of choosing the test, each computed
// without cancellation (the smaller of the two is never 1 - a rounded larger one), so entropies
// and log-likelihoods stay exact far from the threshold. Require m > 0 and a valid function
// (asserted). Any time.
double reference_probability(const PsychometricFunction& function, double m);
double test_probability(const PsychometricFunction& function, double m);

}  // namespace monoplane::study
