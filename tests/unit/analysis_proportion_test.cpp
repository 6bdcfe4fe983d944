// Binomial proportions against values obtained without Boost: closed forms written out here,
// pmfs enumerated by hand, and, where stated, exact rational (Python fractions) or 60-digit
// decimal arithmetic.
#include <gtest/gtest.h>

#include <cmath>

#include "analysis/proportion.h"

namespace monoplane::analysis {
namespace {

// Fink et al. 2019, Fig. 7: decisions for hybrid out of all decisions per scene.
constexpr Proportion kSpheres{175, 452};    // 175 hybrid / 277 stereo
constexpr Proportion kLandscape{162, 459};  // 162 hybrid / 297 stereo
constexpr Proportion kBeams{147, 451};      // 147 hybrid / 304 stereo

TEST(Proportion, ThePapersPercentages) {
    EXPECT_NEAR(100.0 * estimate(kSpheres), 38.72, 0.005);
    EXPECT_NEAR(100.0 * estimate(kLandscape), 35.29, 0.005);
    EXPECT_NEAR(100.0 * estimate(kBeams), 32.59, 0.005);
}

TEST(Proportion, Validity) {
    EXPECT_TRUE(is_valid({0, 1}));
    EXPECT_TRUE(is_valid({5, 5}));
    EXPECT_FALSE(is_valid({0, 0}));
    EXPECT_FALSE(is_valid({-1, 5}));
    EXPECT_FALSE(is_valid({6, 5}));
}

// Wilson's interval in the other common arrangement of the same formula:
// (2 n p + z^2 -+ z sqrt(z^2 + 4 n p (1 - p))) / (2 (n + z^2)).
Interval wilson_by_hand(Proportion proportion) {
    const double z = 1.959963984540054;  // standard normal quantile at 0.975
    const double n = proportion.trials;
    const double p = static_cast<double>(proportion.successes) / n;
    const double centre = 2.0 * n * p + z * z;
    const double spread = z * std::sqrt(z * z + 4.0 * n * p * (1.0 - p));
    const double denominator = 2.0 * (n + z * z);
    return {(centre - spread) / denominator, (centre + spread) / denominator};
}

TEST(WilsonInterval, MatchesTheClosedFormForTheSpheresResult) {
    const Interval expected = wilson_by_hand(kSpheres);  // [0.343393020811669, 0.432844971529168]
    const Interval actual = wilson_interval(kSpheres);
    EXPECT_NEAR(actual.lower, expected.lower, 1e-12);
    EXPECT_NEAR(actual.upper, expected.upper, 1e-12);
    EXPECT_NEAR(actual.lower, 0.343393020811669, 1e-12);
    EXPECT_NEAR(actual.upper, 0.432844971529168, 1e-12);
}

TEST(WilsonInterval, MatchesTheClosedFormAtSmallN) {
    for (Proportion proportion : {Proportion{7, 20}, Proportion{1, 3}, Proportion{9, 10}}) {
        const Interval expected = wilson_by_hand(proportion);
        const Interval actual = wilson_interval(proportion);
        EXPECT_NEAR(actual.lower, expected.lower, 1e-12) << proportion.successes;
        EXPECT_NEAR(actual.upper, expected.upper, 1e-12) << proportion.successes;
    }
}

TEST(WilsonInterval, ExtremesStayInsideTheUnitInterval) {
    // At 0 successes the closed form gives lower = 0 and upper = z^2 / (n + z^2).
    const double z = 1.959963984540054;
    const Interval none = wilson_interval({0, 10});
    EXPECT_EQ(none.lower, 0.0);
    EXPECT_NEAR(none.upper, z * z / (10.0 + z * z), 1e-12);  // 0.277532799862889
    const Interval all = wilson_interval({10, 10});
    EXPECT_NEAR(all.lower, 10.0 / (10.0 + z * z), 1e-12);
    EXPECT_EQ(all.upper, 1.0);
}

TEST(WilsonInterval, WiderAtHigherConfidence) {
    const Interval at90 = wilson_interval(kBeams, 0.90);
    const Interval at99 = wilson_interval(kBeams, 0.99);
    EXPECT_LT(at99.lower, at90.lower);
    EXPECT_GT(at99.upper, at90.upper);
}

TEST(ClopperPearsonInterval, ZeroSuccesses) {
    // P(X = 0 | p) = (1 - p)^n = alpha / 2  =>  upper = 1 - (alpha / 2)^(1 / n).
    for (int n : {1, 10, 452}) {
        const Interval interval = clopper_pearson_interval({0, n});
        EXPECT_EQ(interval.lower, 0.0);
        EXPECT_NEAR(interval.upper, 1.0 - std::pow(0.025, 1.0 / n), 1e-13) << n;
    }
    EXPECT_NEAR(clopper_pearson_interval({0, 10}).upper, 0.308497107818761, 1e-13);
}

TEST(ClopperPearsonInterval, AllSuccesses) {
    // P(X = n | p) = p^n = alpha / 2  =>  lower = (alpha / 2)^(1 / n).
    for (int n : {1, 10, 452}) {
        const Interval interval = clopper_pearson_interval({n, n});
        EXPECT_NEAR(interval.lower, std::pow(0.025, 1.0 / n), 1e-13) << n;
        EXPECT_EQ(interval.upper, 1.0);
    }
}

TEST(ClopperPearsonInterval, SingleTrialAt90Percent) {
    // n = 1, k = 1: lower solves p = alpha / 2 = 0.05, so [0.05, 1].
    const Interval interval = clopper_pearson_interval({1, 1}, 0.90);
    EXPECT_NEAR(interval.lower, 0.05, 1e-15);
    EXPECT_EQ(interval.upper, 1.0);
}

TEST(ClopperPearsonInterval, MatchesIndependentBisection) {
    // Reference: bisection for P(X >= k | lower) = 0.025 and P(X <= k | upper) = 0.025 on binomial
    // tails summed in 60-digit decimal arithmetic (Python, no Boost). The 7/20 pair is also R's
    // binom.test(7, 20)$conf.int.
    struct Case {
        Proportion proportion;
        double lower, upper;
    };
    for (const Case& c : {Case{{7, 20}, 0.153909204784541, 0.592188534532828},
                          Case{kSpheres, 0.342023520723283, 0.433799554551195},
                          Case{kLandscape, 0.309204016467982, 0.398587351276280},
                          Case{kBeams, 0.282839665624516, 0.371346513659428}}) {
        const Interval interval = clopper_pearson_interval(c.proportion);
        EXPECT_NEAR(interval.lower, c.lower, 1e-12) << c.proportion.successes;
        EXPECT_NEAR(interval.upper, c.upper, 1e-12) << c.proportion.successes;
    }
}

TEST(ClopperPearsonInterval, IsSymmetricUnderSwappingOutcomes) {
    const Interval hybrid = clopper_pearson_interval(kSpheres);
    const Interval stereo = clopper_pearson_interval({452 - 175, 452});
    EXPECT_NEAR(hybrid.lower, 1.0 - stereo.upper, 1e-14);
    EXPECT_NEAR(hybrid.upper, 1.0 - stereo.lower, 1e-14);
}

TEST(ClopperPearsonInterval, ContainsWilson) {
    // Clopper-Pearson is the conservative one.
    for (Proportion proportion : {kSpheres, kLandscape, kBeams, Proportion{7, 20}}) {
        const Interval exact = clopper_pearson_interval(proportion);
        const Interval wilson = wilson_interval(proportion);
        EXPECT_LT(exact.lower, wilson.lower);
        EXPECT_GT(exact.upper, wilson.upper);
    }
}

TEST(BinomialTest, SmallNByEnumeration) {
    // n = 10, p0 = 1/2: pmf * 1024 = 1 10 45 120 210 252 210 120 45 10 1. Observed k = 2
    // (45/1024); outcomes no more likely: 0, 1, 2, 8, 9, 10 -> (1+10+45+45+10+1)/1024 = 112/1024.
    EXPECT_DOUBLE_EQ(binomial_two_sided_p({2, 10}), 0.109375);
    EXPECT_DOUBLE_EQ(binomial_two_sided_p({8, 10}), 0.109375);
    // k = 5 is the mode: every outcome is no more likely, p = 1.
    EXPECT_DOUBLE_EQ(binomial_two_sided_p({5, 10}), 1.0);
    // k = 4 (210/1024): every outcome but 5 (252/1024) -> 772/1024.
    EXPECT_DOUBLE_EQ(binomial_two_sided_p({4, 10}), 772.0 / 1024.0);
}

TEST(BinomialTest, KnownRValue) {
    // binom.test(7, 20)$p.value = 0.2632: 2 * (sum of C(20, i), i = 0..7) / 2^20
    // = 2 * 137980 / 1048576 exactly.
    EXPECT_DOUBLE_EQ(binomial_two_sided_p({7, 20}), 2.0 * 137980.0 / 1048576.0);
}

TEST(BinomialTest, AsymmetricNullByEnumeration) {
    // n = 10, p0 = 0.3, pmf: 0.0282475249 0.121060821 0.2334744405 0.266827932 0.200120949
    // 0.1029193452 0.036756909 0.009001692 0.0014467005 0.000137781 0.0000059049.
    // k = 2: all but k = 3 are no more likely -> 1 - 0.266827932.
    EXPECT_NEAR(binomial_two_sided_p({2, 10}, 0.3), 0.733172068, 1e-12);
    // k = 8: only 8, 9, 10 -> 0.0014467005 + 0.000137781 + 0.0000059049.
    EXPECT_NEAR(binomial_two_sided_p({8, 10}, 0.3), 0.0015903864, 1e-14);
}

TEST(BinomialTest, ThePapersResultsAgainstChance) {
    // Exact rational sums of the pmf over outcomes no more likely than the observed one
    // (Python fractions), rounded to double.
    EXPECT_NEAR(binomial_two_sided_p(kSpheres) / 1.8433476580908287e-06, 1.0, 1e-9);
    EXPECT_NEAR(binomial_two_sided_p(kLandscape) / 2.9906375938215362e-10, 1.0, 1e-9);
    EXPECT_NEAR(binomial_two_sided_p(kBeams) / 1.1629202943055471e-13, 1.0, 1e-9);
}

TEST(BinomialTest, DegenerateNulls) {
    // 0 successes in 30 fair trials: 2 / 2^30.
    EXPECT_DOUBLE_EQ(binomial_two_sided_p({0, 30}), 2.0 / 1073741824.0);
    // p0 = 0 makes any success impossible, and 0 successes certain.
    EXPECT_EQ(binomial_two_sided_p({0, 10}, 0.0), 1.0);
    EXPECT_EQ(binomial_two_sided_p({1, 10}, 0.0), 0.0);
    EXPECT_EQ(binomial_two_sided_p({10, 10}, 1.0), 1.0);
    EXPECT_EQ(binomial_two_sided_p({9, 10}, 1.0), 0.0);
}

TEST(ProportionDeathTest, InvalidCountsAbortInEveryBuildType) {
    EXPECT_DEATH((void)wilson_interval({1, 0}), "precondition violated");
    EXPECT_DEATH((void)clopper_pearson_interval({6, 5}), "precondition violated");
    EXPECT_DEATH((void)binomial_two_sided_p({-1, 5}), "precondition violated");
    EXPECT_DEATH((void)wilson_interval({1, 5}, 1.0), "0 < confidence < 1");
    EXPECT_DEATH((void)binomial_two_sided_p({1, 5}, 1.5), "0 <= p0 <= 1");
}

}  // namespace
}  // namespace monoplane::analysis
