// Binomial proportions for 2AFC results: how often one alternative (e.g. hybrid) was chosen, with
// confidence intervals and an exact test against chance (Fink et al. 2019 report, e.g., 175 of
// 452 SPHERES decisions for hybrid).
//
// Error channel: the counts come from the study database or a validated export, never straight
// from a user, so invalid arguments are programming errors. They are
// checked in every build type, not only with asserts on: a violated precondition prints the
// reason and aborts, instead of returning a NaN that could end up in a report. Callers holding
// untrusted counts check is_valid() first.
#pragma once

namespace monoplane::analysis {

struct Proportion {
    int successes = 0;
    int trials = 0;
};

struct Interval {
    double lower = 0.0;
    double upper = 0.0;
};

// trials > 0 and 0 <= successes <= trials.
bool is_valid(Proportion proportion);

// successes / trials. Requires is_valid(proportion).
double estimate(Proportion proportion);

// Wilson score interval (Wilson 1927): good coverage at small n without the Wald interval's
// collapse at 0 or n successes; lower is exactly 0 at 0 successes, upper exactly 1 at n. Requires
// is_valid(proportion) and 0 < confidence < 1.
Interval wilson_interval(Proportion proportion, double confidence = 0.95);

// Clopper-Pearson "exact" interval from beta quantiles: coverage at least the nominal level,
// hence conservative. Lower is exactly 0 at 0 successes, upper exactly 1 at n successes.
// Requires is_valid(proportion) and 0 < confidence < 1.
Interval clopper_pearson_interval(Proportion proportion, double confidence = 0.95);

// Exact two-sided binomial test of "success probability = p0", as R's binom.test: the sum of the
// probabilities of all outcomes no more likely than the observed one (with R's relative
// tolerance of 1e-7 for ties). Requires is_valid(proportion) and 0 <= p0 <= 1.
double binomial_two_sided_p(Proportion proportion, double p0 = 0.5);

}  // namespace monoplane::analysis
