// QUEST+ (issue 21): the posterior is Bayes' rule on the grid (checked against values worked out
// by hand and against the rule written out here), the next stimulus minimises the expected
// posterior entropy (computed here independently), the estimate and its credible interval are
// the marginal posterior's, and simulated observers' thresholds are recovered.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "study/quest_plus.h"

namespace monoplane::study {
namespace {

// The 2AFC function as docs/analysis.md writes it, evaluated plainly: independent of the
// library's cancellation-free form.
double p_reference(double m, double t, double b, double lapse) {
    return 0.5 + (0.5 - lapse) / (1.0 + std::pow(m / t, b));
}

// A uniform draw from a fixed engine, the same on every standard library.
double uniform(std::mt19937_64& engine) {
    return static_cast<double>(engine() >> 11) * 0x1.0p-53;
}

TEST(QuestPlus, PosteriorAfterTwoAnswersIsBayesRuleByHand) {
    // Thresholds 2 and 8 m, slope 2, no lapse. At m = 4: P(reference) is 0.5 + 0.5 / (1 + 4)
    // = 0.6 for T = 2 and 0.5 + 0.5 / (1 + 1/4) = 0.9 for T = 8.
    QuestPlus quest({4.0}, {{2.0, 8.0}, {2.0}, {0.0}});
    EXPECT_DOUBLE_EQ(quest.posterior()[0], 0.5);
    quest.record(4.0, true);  // 0.6 : 0.9 -> 0.4, 0.6
    EXPECT_NEAR(quest.posterior()[0], 0.4, 1e-15);
    EXPECT_NEAR(quest.posterior()[1], 0.6, 1e-15);
    quest.record(4.0, false);  // 0.4 * 0.4 : 0.6 * 0.1 -> 8/11, 3/11
    EXPECT_NEAR(quest.posterior()[0], 8.0 / 11.0, 1e-15);
    EXPECT_NEAR(quest.posterior()[1], 3.0 / 11.0, 1e-15);
    EXPECT_EQ(quest.trials(), 2);

    // The estimate: the median and the equal-tailed 95 % interval of the posterior spread
    // evenly over the bins [1, 4] and [4, 16] m (in log m), and the SD of log10 T over the grid
    // (mean ln T = 8/11 ln 2 + 3/11 ln 8).
    const ThresholdEstimate e = quest.estimate();
    EXPECT_NEAR(e.threshold_m, std::pow(4.0, 0.5 * 11.0 / 8.0), 1e-12);
    EXPECT_NEAR(*e.sd_log10, std::sqrt(24.0) / 11.0 * std::log10(4.0), 1e-12);
    EXPECT_NEAR(*e.lower_m, std::pow(4.0, 0.025 * 11.0 / 8.0), 1e-12);
    EXPECT_NEAR(*e.upper_m, std::pow(4.0, 1.0 + (0.975 - 8.0 / 11.0) * 11.0 / 3.0), 1e-12);
}

TEST(QuestPlus, PosteriorIsThePriorTimesEveryLikelihood) {
    const QuestPlusGrid grid{{1.5, 3.0, 6.0, 12.0, 24.0}, {1.0, 3.0}, {0.0, 0.04}};
    QuestPlus quest({1.6, 5.0, 16.0}, grid);
    const std::vector<std::pair<double, bool>> answers = {{5.0, true},  {16.0, false}, {1.6, true},
                                                          {5.0, false}, {16.0, true},  {2.5, true}};
    for (const auto& [m, reference] : answers) quest.record(m, reference);

    std::vector<double> expected;
    double sum = 0.0;
    for (double lapse : grid.lapses) {
        for (double slope : grid.slopes) {
            for (double t : grid.thresholds) {
                double likelihood = 1.0;
                for (const auto& [m, reference] : answers) {
                    const double p = p_reference(m, t, slope, lapse);
                    likelihood *= reference ? p : 1.0 - p;
                }
                expected.push_back(likelihood);
                sum += likelihood;
            }
        }
    }
    ASSERT_EQ(quest.posterior().size(), expected.size());
    for (std::size_t j = 0; j < expected.size(); ++j) {
        EXPECT_NEAR(quest.posterior()[j], expected[j] / sum, 1e-13) << j;
    }
    // The same answers in another order give the same posterior.
    QuestPlus reversed({1.6, 5.0, 16.0}, grid);
    for (auto it = answers.rbegin(); it != answers.rend(); ++it)
        reversed.record(it->first, it->second);
    for (std::size_t j = 0; j < expected.size(); ++j) {
        EXPECT_NEAR(reversed.posterior()[j], quest.posterior()[j], 1e-15) << j;
    }
}

// -sum p ln p of the posterior after answer r at m, weighted by the answer's predictive
// probability: Watson's (2017) eq. 9-11, written out.
double expected_entropy(const QuestPlus& quest, double m) {
    const std::vector<double>& prior = quest.posterior();
    double total = 0.0;
    for (const bool reference : {true, false}) {
        std::vector<double> joint(prior.size());
        double predictive = 0.0;
        for (std::size_t j = 0; j < prior.size(); ++j) {
            const PsychometricFunction f = quest.parameters(j);
            const double p = p_reference(m, f.threshold, f.slope, f.lapse);
            joint[j] = prior[j] * (reference ? p : 1.0 - p);
            predictive += joint[j];
        }
        double h = 0.0;
        for (double q : joint) {
            if (q > 0.0) h -= q / predictive * std::log(q / predictive);
        }
        total += predictive * h;
    }
    return total;
}

TEST(QuestPlus, NextStimulusMinimisesTheExpectedEntropy) {
    const std::vector<double> stimuli = {1.6, 3.0, 5.0, 8.0, 12.0, 20.0, 39.5};
    QuestPlus quest(stimuli, {log_spaced(1.6, 39.5, 12), {1.0, 2.0, 4.0}, {0.0, 0.03}});
    const std::vector<std::pair<double, bool>> answers = {
        {8.0, true}, {20.0, false}, {12.0, true}, {12.0, false}};
    for (std::size_t step = 0; step <= answers.size(); ++step) {
        std::size_t best = 0;
        for (std::size_t i = 0; i < stimuli.size(); ++i) {
            const double h = expected_entropy(quest, stimuli[i]);
            EXPECT_NEAR(quest.expected_entropy(i), h, 1e-12) << "stimulus " << i;
            if (h < expected_entropy(quest, stimuli[best])) best = i;
        }
        EXPECT_EQ(quest.next_mono_plane(), stimuli[best]) << "after " << step << " answers";
        if (step < answers.size()) quest.record(answers[step].first, answers[step].second);
    }
}

TEST(QuestPlus, LogSpacedGridHasEvenRatiosAndExactEnds) {
    const std::vector<double> t = log_spaced(1.6, 39.5, 5);
    ASSERT_EQ(t.size(), 5u);
    EXPECT_EQ(t.front(), 1.6);
    EXPECT_EQ(t.back(), 39.5);
    const double ratio = std::pow(39.5 / 1.6, 0.25);
    for (std::size_t i = 1; i < t.size(); ++i) EXPECT_NEAR(t[i] / t[i - 1], ratio, 1e-12);
}

// Twenty simulated observers (T = 8 m, slope 3, lapse 0.02) of 60 trials each on fink2019's
// distances and the default grid: the 95 % credible interval covers 8 m in at least 17 (the
// binomial(20, 0.95) 2.5 % quantile is 17), the mean log10 error is within 0.05 and the
// posterior narrows with the trials.
TEST(QuestPlus, RecoversASimulatedObserversThreshold) {
    const std::vector<double> mono_planes = {1.6, 3, 5, 8, 12, 16, 20, 25, 31, 39.5};
    const double t = 8.0, slope = 3.0, lapse = 0.02;
    std::mt19937_64 engine(20261202);
    int covered = 0;
    double error_sum = 0.0;
    for (int run = 0; run < 20; ++run) {
        QuestPlus quest(
            mono_planes,
            {log_spaced(1.6, 39.5, 40), {1.0, 2.0, 3.0, 4.0, 6.0, 8.0}, {0, 0.02, 0.04}});
        double sd_after_10 = 0.0;
        for (int trial = 0; trial < 60; ++trial) {
            const double m = quest.next_mono_plane();
            quest.record(m, uniform(engine) < p_reference(m, t, slope, lapse));
            if (trial == 9) sd_after_10 = *quest.estimate().sd_log10;
        }
        const ThresholdEstimate e = quest.estimate();
        covered += *e.lower_m <= t && t <= *e.upper_m;
        error_sum += std::log10(e.threshold_m / t);
        EXPECT_LT(*e.sd_log10, sd_after_10) << "run " << run;
    }
    EXPECT_GE(covered, 17);
    EXPECT_LT(std::abs(error_sum / 20.0), 0.05);
}

}  // namespace
}  // namespace monoplane::study
