// The weighted up-down rule (Kaernbach 1991; issue 21): its steps, its bounds, its reversals, and
// that it converges where Kaernbach's formula says: the share of reference choices tends to
// target = step_nearer / (step_farther + step_nearer), and m hovers around the m* at which the
// observer's P(reference) equals the target.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "study/weighted_up_down.h"

namespace monoplane::study {
namespace {

double uniform(std::mt19937_64& engine) {
    return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

TEST(WeightedUpDown, StepsFartherAfterAReferenceChoiceAndNearerAfterATestChoice) {
    // Target 0.75: the nearer step is 0.75 / 0.25 = 3 times the farther one.
    WeightedUpDown staircase(1.0, 40.0, 4.0, 0.75, 0.1, 0);
    EXPECT_EQ(staircase.next_mono_plane(), 4.0);
    staircase.record(4.0, true);
    EXPECT_NEAR(staircase.next_mono_plane(), 4.0 * std::pow(10.0, 0.1), 1e-12);
    staircase.record(staircase.next_mono_plane(), false);
    EXPECT_NEAR(staircase.next_mono_plane(), 4.0 * std::pow(10.0, 0.1 - 0.3), 1e-12);
    ASSERT_EQ(staircase.reversals().size(), 1u);  // turned at the second trial's m
    EXPECT_NEAR(staircase.reversals()[0], 4.0 * std::pow(10.0, 0.1), 1e-12);
    EXPECT_EQ(staircase.trials(), 2);
    // The next m is computed from the m recorded, whatever was asked for.
    staircase.record(10.0, false);
    EXPECT_NEAR(staircase.next_mono_plane(), 10.0 * std::pow(10.0, -0.3), 1e-12);
    EXPECT_EQ(staircase.reversals().size(), 1u);  // same direction: no reversal
}

TEST(WeightedUpDown, StaysWithinTheDistances) {
    WeightedUpDown staircase(1.6, 39.5, 30.0, 0.75, 0.5, 0);
    staircase.record(30.0, true);
    EXPECT_EQ(staircase.next_mono_plane(), 39.5);
    staircase.record(2.0, false);
    EXPECT_EQ(staircase.next_mono_plane(), 1.6);
}

TEST(WeightedUpDown, EstimateIsTheGeometricMeanOfTheCountedReversals) {
    WeightedUpDown staircase(1.0, 100.0, 10.0, 0.75, 0.1, 1);
    EXPECT_EQ(staircase.estimate().threshold_m, 10.0);  // no reversals: the next m
    staircase.record(10.0, true);
    staircase.record(12.0, false);  // reversal at 12 (skipped)
    staircase.record(6.0, true);    // reversal at 6
    staircase.record(8.0, false);   // reversal at 8
    EXPECT_NEAR(staircase.estimate().threshold_m, std::sqrt(6.0 * 8.0), 1e-12);
    EXPECT_FALSE(staircase.estimate().sd_log10);
    EXPECT_EQ(staircase.estimate().trials, 4);
}

// Observer: T = 8 m, slope 3, lapse 0.02, P(reference) = 0.5 + 0.48 / (1 + (m / 8)^3). For a
// target p the rule converges on m* = 8 ((0.48 / (p - 0.5)) - 1)^(1/3): 7.78 m for 0.75, 6.85 m
// for 0.8.
TEST(WeightedUpDown, ConvergesWhereKaernbachsFormulaSays) {
    const double t = 8.0, slope = 3.0, lapse = 0.02;
    std::mt19937_64 engine(1991);
    for (const double target : {0.75, 0.8}) {
        const double m_star = t * std::pow((0.5 - lapse) / (target - 0.5) - 1.0, 1.0 / slope);
        const double step = 0.01;
        WeightedUpDown staircase(0.1, 1000.0, 20.0, target, step, 4);
        constexpr int kTrials = 40'000, kBurnIn = 2'000;
        int reference = 0;
        double log_sum = 0.0;
        for (int i = 0; i < kTrials; ++i) {
            const double m = staircase.next_mono_plane();
            const double p = 0.5 + (0.5 - lapse) / (1.0 + std::pow(m / t, slope));
            const bool chose_reference = uniform(engine) < p;
            reference += chose_reference;
            if (i >= kBurnIn) log_sum += std::log10(m);
            staircase.record(m, chose_reference);
        }
        // Never at the bounds, so every step counted: reference * step - test * step * p/(1-p)
        // is the whole displacement, and the share of reference choices is the target up to it.
        const double nearer = step * target / (1.0 - target);
        const double displacement = reference * step - (kTrials - reference) * nearer;
        EXPECT_NEAR(displacement, std::log10(staircase.next_mono_plane() / 20.0), 1e-6);
        EXPECT_NEAR(static_cast<double>(reference) / kTrials, target,
                    std::abs(displacement) / (kTrials * (step + nearer)) + 1e-9);
        // Where it hovers: within 0.01 log10 (2.3 %) of m*; the reversals' mean too.
        EXPECT_NEAR(log_sum / (kTrials - kBurnIn), std::log10(m_star), 0.01) << target;
        EXPECT_NEAR(std::log10(staircase.estimate().threshold_m), std::log10(m_star), 0.01);
    }
}

}  // namespace
}  // namespace monoplane::study
