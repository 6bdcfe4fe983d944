// Psychometric-function fits (analysis/psychometric_function.h, psychometric_fits.h):
// - against scipy on tests/fixtures/analysis/psychometric.csv: maximum-likelihood parameters and
//   profile-likelihood intervals written independently with scipy.optimize by
//   tests/fixtures/analysis/make_psychometric_reference.py, run as
//       /usr/bin/python3 tests/fixtures/analysis/make_psychometric_reference.py
//   (scipy 1.10.1, Debian 12), whose printed values are the literals below;
// - on data simulated from known parameters: recovery, interval coverage, the group bootstrap;
// - on data that cannot locate a threshold: a reason, never a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <random>

#include "analysis/dataset.h"
#include "analysis/psychometric_fits.h"

namespace monoplane::analysis {
namespace {

const std::filesystem::path kFixtures = MONOPLANE_ANALYSIS_FIXTURES;
const std::vector<double> kDistances = {1.6, 3, 5, 8, 12, 16, 20, 25, 31, 39.5};

testing::AssertionResult near_relative(double actual, double expected, double relative) {
    if (std::abs(actual - expected) <= relative * std::abs(expected))
        return testing::AssertionSuccess();
    return testing::AssertionFailure()
           << actual << " is not within " << relative << " (relative) of " << expected;
}

std::vector<PsychometricFit> fixture_fits() {
    Result<Dataset> data = read_export_csv(kFixtures / "psychometric.csv");
    EXPECT_TRUE(data.ok()) << data.error().message;
    if (!data.ok()) return {};
    derive_session_fields(data.value().trials);
    return fit_psychometric_functions(data->trials, {.bootstrap_replicates = 50});
}

const PsychometricFit* find(const std::vector<PsychometricFit>& fits, const std::string& who,
                            const std::string& scene) {
    for (const PsychometricFit& f : fits)
        if (f.participant == who && f.scene == scene) return &f;
    return nullptr;
}

struct Reference {
    const char* participant;
    const char* scene;
    double threshold, slope, lapse, log_likelihood;
    std::optional<double> lower, upper;  // profile interval; nullopt: unbounded
};

// scipy's values (make_psychometric_reference.py). Both must reach the same maximum of the
// likelihood (to 1e-9). Where scipy's slope sits on its bound (50: the data step from one distance
// to the next) the likelihood is flat along the slope to about 1e-9 of its value from about 40
// on, and the threshold moves with it by a few tenths of a percent: there the slope is only
// required to be steep and the threshold to match to 1 %; elsewhere to 1e-4 (1e-3 the slope).
const Reference kScipy[] = {
    {"all", "beams", 9.20727616, 1.724724323, 0.01179724477, -171.406323396, {}, {}},
    {"P01", "beams", 12.26658237, 50, 0, -30.7400553103, 10.30536532, 15.16478847},
    {"P02", "beams", 17.00604504, 1.559998346, 0.1, -43.6550791675, std::nullopt, std::nullopt},
    {"P03", "beams", 5.111077041, 50, 0, -41.8304034014, 4.084417336, 9.034781316},
    {"P04", "beams", 8.68010563, 0.9912683993, 0, -44.4729330465, std::nullopt, std::nullopt},
    {"all", "spheres", 7.818202458, 1.732666899, 0.1, -194.032569059, {}, {}},
    {"P01", "spheres", 14.42135992, 1.443125056, 0.1, -45.1886463998, std::nullopt, std::nullopt},
    {"P02", "spheres", 6.814295132, 50, 0.04166666731, -42.9731681606, 4.399373796, 9.296839923},
    {"P03", "spheres", 12.49284996, 4.237770952, 0.07705308318, -41.9670426829, 4.660497593,
     34.93917791},
};

TEST(PsychometricFit, MatchesScipyOnTheFixture) {
    const std::vector<PsychometricFit> fits = fixture_fits();
    ASSERT_EQ(fits.size(), 10u);  // per scene: the group, then P01..P04
    for (const Reference& r : kScipy) {
        SCOPED_TRACE(std::string(r.participant) + " " + r.scene);
        const PsychometricFit* f = find(fits, r.participant, r.scene);
        ASSERT_NE(f, nullptr);
        ASSERT_TRUE(f->estimable) << f->reason;
        EXPECT_TRUE(near_relative(f->log_likelihood, r.log_likelihood, 1e-9));
        const bool step = r.slope == 50;
        EXPECT_TRUE(near_relative(f->parameters.threshold, r.threshold, step ? 1e-2 : 1e-4));
        if (step) {
            EXPECT_GT(f->parameters.slope, 40.0);
        } else {
            EXPECT_TRUE(near_relative(f->parameters.slope, r.slope, 1e-3));
        }
        EXPECT_NEAR(f->parameters.lapse, r.lapse, 1e-4);
        if (std::string(r.participant) == "all") {
            EXPECT_EQ(f->n, 320);
            EXPECT_EQ(f->participants, 4);
            EXPECT_EQ(f->interval_method, "participant bootstrap");
            continue;
        }
        EXPECT_EQ(f->n, 80);
        EXPECT_EQ(f->interval_method, "profile likelihood");
        ASSERT_EQ(f->threshold_lower.has_value(), r.lower.has_value());
        ASSERT_EQ(f->threshold_upper.has_value(), r.upper.has_value());
        if (r.lower) {
            EXPECT_TRUE(near_relative(*f->threshold_lower, *r.lower, 1e-4));
        }
        if (r.upper) {
            EXPECT_TRUE(near_relative(*f->threshold_upper, *r.upper, 1e-4));
        }
    }
    // P04 chose at chance in SPHERES: scipy's threshold, 1.38 m, lies below the tested range.
    const PsychometricFit* chance = find(fits, "P04", "spheres");
    ASSERT_NE(chance, nullptr);
    EXPECT_FALSE(chance->estimable);
    EXPECT_NE(chance->reason.find("below the smallest distance tested (1.6 m)"), std::string::npos)
        << chance->reason;
}

// Reference choices drawn from known parameters, `trials` at each distance.
std::vector<StimulusLevel> simulate(const PsychometricParameters& truth, int trials,
                                    std::mt19937_64& random,
                                    const std::vector<double>& distances = kDistances) {
    std::vector<StimulusLevel> levels;
    for (const double m : distances) {
        std::binomial_distribution<int> draw(trials, reference_probability(truth, m));
        levels.push_back({m, draw(random), trials});
    }
    return levels;
}

TEST(PsychometricFit, RecoversKnownParametersFromManyTrials) {
    // 400 trials at each of ten distances: the estimates' standard errors are a few percent.
    std::mt19937_64 random(7);
    const PsychometricParameters truth{8.0, 3.0, 0.03};
    const PsychometricFit fit = fit_levels(simulate(truth, 400, random));
    ASSERT_TRUE(fit.estimable) << fit.reason;
    EXPECT_NEAR(fit.parameters.threshold, 8.0, 0.4);
    EXPECT_NEAR(fit.parameters.slope, 3.0, 0.45);
    EXPECT_NEAR(fit.parameters.lapse, 0.03, 0.015);
    ASSERT_TRUE(fit.threshold_lower && fit.threshold_upper);
    EXPECT_LT(*fit.threshold_lower, 8.0);
    EXPECT_GT(*fit.threshold_upper, 8.0);
    EXPECT_LT(*fit.threshold_upper - *fit.threshold_lower, 1.6);
}

TEST(PsychometricFit, ProfileIntervalsCoverTheTruth) {
    // 40 simulated observers, 30 trials per distance: a 95 % interval misses the true threshold
    // in about 2 of them; 8 or more misses would have probability 0.001 at 95 % coverage.
    std::mt19937_64 random(11);
    const PsychometricParameters truth{10.0, 2.5, 0.02};
    int covered = 0, estimable = 0;
    for (int observer = 0; observer < 40; ++observer) {
        const PsychometricFit fit = fit_levels(simulate(truth, 30, random));
        if (!fit.estimable) continue;
        ++estimable;
        const bool above_lower = !fit.threshold_lower || *fit.threshold_lower <= 10.0;
        const bool below_upper = !fit.threshold_upper || *fit.threshold_upper >= 10.0;
        covered += above_lower && below_upper ? 1 : 0;
    }
    EXPECT_EQ(estimable, 40);
    EXPECT_GE(covered, 33);
}

// Trial rows for fit_psychometric_functions: participant P<i> answers from parameters[i].
std::vector<TrialRow> study(const std::vector<PsychometricParameters>& parameters, int trials,
                            std::mt19937_64& random) {
    std::vector<TrialRow> rows;
    for (std::size_t p = 0; p < parameters.size(); ++p) {
        for (const StimulusLevel& level : simulate(parameters[p], trials, random)) {
            for (int t = 0; t < level.trials; ++t) {
                TrialRow row;
                row.participant = "P" + std::to_string(p);
                row.scene = "beams";
                row.mono_plane = level.m;
                row.decided = row.valid = true;
                row.chose_test = t >= level.reference;
                rows.push_back(row);
            }
        }
    }
    return rows;
}

double width(const PsychometricFit& fit) {
    EXPECT_TRUE(fit.threshold_lower && fit.threshold_upper) << fit.participant;
    return fit.threshold_upper.value_or(NAN) - fit.threshold_lower.value_or(NAN);
}

TEST(PsychometricFit, GroupIntervalResamplesParticipants) {
    // Two groups of six, 20 trials per distance each: in one everybody's threshold is 8 m, in
    // the other they spread from 4 to 16 m. The profile interval of the pooled trials, which
    // treats every trial as independent, is about as wide for both (2.2 and 2.5 m); resampling
    // participants widens the spread group's interval (about 3 times) and not the alike one's.
    std::mt19937_64 random(3);
    const std::vector<PsychometricParameters> alike(6, {8.0, 3.0, 0.02});
    std::vector<PsychometricParameters> spread;
    for (const double t : {4.0, 5.0, 6.5, 10.0, 13.0, 16.0}) spread.push_back({t, 3.0, 0.02});
    const PsychometricOptions options{.bootstrap_replicates = 150};
    const PsychometricFit a = fit_psychometric_functions(study(alike, 20, random), options).front();
    const PsychometricFit s =
        fit_psychometric_functions(study(spread, 20, random), options).front();
    ASSERT_EQ(a.participant, "all");
    ASSERT_EQ(s.participant, "all");
    ASSERT_TRUE(a.estimable && s.estimable);
    EXPECT_EQ(a.participants, 6);
    EXPECT_EQ(a.n, 6 * 10 * 20);
    EXPECT_EQ(a.interval_method, "participant bootstrap");
    EXPECT_EQ(a.bootstrap_replicates, 150);
    EXPECT_LT(*a.threshold_lower, 8.0);
    EXPECT_GT(*a.threshold_upper, 8.0);
    const double alike_trials = width(fit_levels(a.levels));
    const double spread_trials = width(fit_levels(s.levels));
    EXPECT_LT(width(a), 1.5 * alike_trials);
    EXPECT_GT(width(s), 2.0 * spread_trials);
    EXPECT_GT(width(s), 2.0 * width(a));
    // The same data and seed give the same interval.
    std::mt19937_64 again(3);
    const auto repeated = fit_psychometric_functions(study(alike, 20, again), options);
    EXPECT_EQ(*repeated.front().threshold_lower, *a.threshold_lower);
    EXPECT_EQ(*repeated.front().threshold_upper, *a.threshold_upper);
}

TEST(PsychometricFit, DataThatCannotLocateAThresholdGiveAReason) {
    std::mt19937_64 random(5);
    // At chance everywhere: the best curve is already at 0.5 below the smallest distance.
    const PsychometricFit chance = fit_levels(simulate({0.01, 3.0, 0.0}, 40, random));
    EXPECT_FALSE(chance.estimable);
    EXPECT_NE(chance.reason.find("below the smallest distance tested"), std::string::npos)
        << chance.reason;
    // Perfect discrimination everywhere.
    std::vector<StimulusLevel> all_reference;
    all_reference.reserve(kDistances.size());
    for (const double m : kDistances) all_reference.push_back({m, 10, 10});
    const PsychometricFit reference = fit_levels(all_reference);
    EXPECT_FALSE(reference.estimable);
    EXPECT_NE(reference.reason.find("reference was chosen in all 100 trials"), std::string::npos);
    EXPECT_NE(reference.reason.find("39.5 m"), std::string::npos) << reference.reason;
    // Reference chosen more often than chance even at the largest distance.
    const PsychometricFit beyond = fit_levels(simulate({400.0, 4.0, 0.0}, 40, random));
    EXPECT_FALSE(beyond.estimable);
    EXPECT_NE(beyond.reason.find("beyond the largest distance tested"), std::string::npos)
        << beyond.reason;
    // One distance (given twice: merged), and nothing at all.
    const PsychometricFit single = fit_levels({{8.0, 7, 10}, {8.0, 3, 10}});
    EXPECT_FALSE(single.estimable);
    EXPECT_NE(single.reason.find("all 20 trials are at one distance (8 m)"), std::string::npos)
        << single.reason;
    EXPECT_EQ(single.levels.size(), 1u);
    const PsychometricFit none = fit_levels({});
    EXPECT_FALSE(none.estimable);
    EXPECT_EQ(none.reason, "no analysable trials");
    // A group whose pooled data are at chance is not estimable either, and its participants'
    // fits come with it.
    const auto fits =
        fit_psychometric_functions(study({{0.01, 3, 0}, {0.01, 3, 0}}, 20, random), {});
    ASSERT_EQ(fits.size(), 3u);
    for (const PsychometricFit& f : fits) EXPECT_FALSE(f.estimable) << f.participant;
}

TEST(PsychometricFunction, ProbabilityFollowsTheFormula) {
    const PsychometricParameters p{8.0, 3.0, 0.04};
    // At the threshold: 0.5 + 0.46 / 2; at half of it: 0.5 + 0.46 / (1 + 1/8).
    EXPECT_DOUBLE_EQ(reference_probability(p, 8.0), 0.73);
    EXPECT_NEAR(reference_probability(p, 4.0), 0.5 + 0.46 / 1.125, 1e-15);
    EXPECT_NEAR(reference_probability(p, 16.0), 0.5 + 0.46 / 9.0, 1e-15);
    EXPECT_NEAR(reference_probability(p, 1e-6), 0.96, 1e-12);
    // log L of 3 of 4 at m = 8 and 1 of 2 at m = 16, by hand.
    const double expected = 3 * std::log(0.73) + std::log(0.27) + std::log(0.5 + 0.46 / 9.0) +
                            std::log(0.5 - 0.46 / 9.0);
    EXPECT_NEAR(psychometric_log_likelihood({{8.0, 3, 4}, {16.0, 1, 2}}, p), expected, 1e-12);
}

}  // namespace
}  // namespace monoplane::analysis
