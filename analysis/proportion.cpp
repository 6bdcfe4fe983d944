#include "analysis/proportion.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/special_functions/beta.hpp>

namespace monoplane::analysis {
namespace {

// An assert that stays on in release builds (see proportion.h for why).
void require(bool condition, const char* what) {
    if (condition) return;
    std::fprintf(stderr, "monoplane analysis: precondition violated: %s\n", what);
    std::abort();
}

void require_valid(Proportion proportion, double confidence) {
    require(is_valid(proportion), "trials > 0 and 0 <= successes <= trials");
    require(confidence > 0.0 && confidence < 1.0, "0 < confidence < 1");
}

}  // namespace

bool is_valid(Proportion proportion) {
    return proportion.trials > 0 && proportion.successes >= 0 &&
           proportion.successes <= proportion.trials;
}

double estimate(Proportion proportion) {
    require(is_valid(proportion), "trials > 0 and 0 <= successes <= trials");
    return static_cast<double>(proportion.successes) / proportion.trials;
}

Interval wilson_interval(Proportion proportion, double confidence) {
    require_valid(proportion, confidence);
    const double alpha = 1.0 - confidence;
    const double z =
        boost::math::quantile(boost::math::normal_distribution<double>(), 1.0 - alpha / 2.0);
    const double n = proportion.trials;
    const double p = estimate(proportion);
    const double z2_over_n = z * z / n;
    const double centre = (p + z2_over_n / 2.0) / (1.0 + z2_over_n);
    const double half_width =
        z / (1.0 + z2_over_n) * std::sqrt(p * (1.0 - p) / n + z2_over_n / (4.0 * n));
    // At 0 (n) successes the lower (upper) bound is exactly 0 (1); say so rather than leave a
    // rounding error of either sign, which would put 1 - 1e-16 into a report or escape [0, 1].
    const double lower = proportion.successes == 0 ? 0.0 : centre - half_width;
    const double upper = proportion.successes == proportion.trials ? 1.0 : centre + half_width;
    return {std::clamp(lower, 0.0, 1.0), std::clamp(upper, 0.0, 1.0)};
}

Interval clopper_pearson_interval(Proportion proportion, double confidence) {
    require_valid(proportion, confidence);
    const double alpha = 1.0 - confidence;
    const double k = proportion.successes;
    const double n = proportion.trials;
    // lower = Beta(k, n - k + 1) quantile at alpha/2, upper = Beta(k + 1, n - k) quantile at
    // 1 - alpha/2; the upper one through the complement, which keeps full precision near 1.
    const double lower =
        proportion.successes == 0 ? 0.0 : boost::math::ibeta_inv(k, n - k + 1.0, alpha / 2.0);
    const double upper = proportion.successes == proportion.trials
                             ? 1.0
                             : boost::math::ibetac_inv(k + 1.0, n - k, alpha / 2.0);
    return {lower, upper};
}

double binomial_two_sided_p(Proportion proportion, double p0) {
    require(is_valid(proportion), "trials > 0 and 0 <= successes <= trials");
    require(p0 >= 0.0 && p0 <= 1.0, "0 <= p0 <= 1");
    // Follows R's binom.test (stats/R/binom.test.R): sum one tail up to the observation, then the
    // y outcomes of the other tail whose probability does not exceed the observed one. The
    // binomial pmf is unimodal with its mode next to n * p0, so those y outcomes are the
    // outermost ones and their sum is a tail probability.
    const int x = proportion.successes;
    const int n = proportion.trials;
    const boost::math::binomial_distribution<double> binomial(n, p0);
    const double observed = boost::math::pdf(binomial, x);
    const double tolerance = 1.0 + 1e-7;
    const double mean = n * p0;
    const auto no_more_likely = [&](int outcome) {
        return boost::math::pdf(binomial, outcome) <= observed * tolerance;
    };

    double p = 1.0;
    if (x < mean) {
        int y = 0;
        for (int i = static_cast<int>(std::ceil(mean)); i <= n; ++i) y += no_more_likely(i);
        // P(X <= x) + P(X > n - y)
        p = boost::math::cdf(binomial, x) +
            boost::math::cdf(boost::math::complement(binomial, n - y));
    } else if (x > mean) {
        int y = 0;
        for (int i = 0; i <= static_cast<int>(std::floor(mean)); ++i) y += no_more_likely(i);
        // P(X <= y - 1) + P(X >= x)
        const double lower_tail = y == 0 ? 0.0 : boost::math::cdf(binomial, y - 1);
        p = lower_tail + boost::math::cdf(boost::math::complement(binomial, x - 1));
    }
    return std::min(1.0, p);
}

}  // namespace monoplane::analysis
