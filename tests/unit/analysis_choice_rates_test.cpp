// Exclusions, choice rates and the distance x decision chi-square against values computed
// outside the project: tests/fixtures/analysis/make_reference.py (scipy.stats.binomtest,
// statsmodels proportion_confint wilson/beta, scipy.stats.chi2_contingency(correction=False),
// scipy.stats.contingency.association), run as
//     /usr/bin/python3 tests/fixtures/analysis/make_reference.py
// with Debian 12's scipy 1.10.1 and statsmodels 0.13.5. The literals below are its output.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "analysis/choice_rates.h"
#include "analysis/contingency.h"
#include "analysis/dataset.h"
#include "analysis/exclusions.h"

namespace monoplane::analysis {
namespace {

const std::filesystem::path kFixtures = MONOPLANE_ANALYSIS_FIXTURES;

testing::AssertionResult near_relative(double actual, double expected, double relative) {
    if (std::abs(actual - expected) <= relative * std::abs(expected) ||
        (expected == 0.0 && std::abs(actual) < 1e-15))
        return testing::AssertionSuccess();
    return testing::AssertionFailure()
           << actual << " is not within " << relative << " (relative) of " << expected;
}
constexpr double kClosedForm = 1e-6;

struct ExpectedRate {
    const char* scene;
    double mono_plane;  // NaN: all
    int k, n;
    double wilson_lower, wilson_upper, cp_lower, cp_upper, p;
};

void expect_rate(const ChoiceRate& actual, const ExpectedRate& e) {
    SCOPED_TRACE(std::string(e.scene) + " @ " + std::to_string(e.mono_plane));
    EXPECT_EQ(actual.scene, e.scene);
    if (std::isnan(e.mono_plane))
        EXPECT_TRUE(std::isnan(actual.mono_plane));
    else
        EXPECT_EQ(actual.mono_plane, e.mono_plane);
    EXPECT_EQ(actual.test_chosen, e.k);
    EXPECT_EQ(actual.n, e.n);
    EXPECT_DOUBLE_EQ(actual.rate, static_cast<double>(e.k) / e.n);
    EXPECT_TRUE(near_relative(actual.wilson.lower, e.wilson_lower, kClosedForm));
    EXPECT_TRUE(near_relative(actual.wilson.upper, e.wilson_upper, kClosedForm));
    EXPECT_TRUE(near_relative(actual.clopper_pearson.lower, e.cp_lower, kClosedForm));
    EXPECT_TRUE(near_relative(actual.clopper_pearson.upper, e.cp_upper, kClosedForm));
    EXPECT_TRUE(near_relative(actual.binomial_p, e.p, kClosedForm));
}

std::vector<TrialRow> load(const char* name) {
    Result<Dataset> data = read_export_csv(kFixtures / name);
    EXPECT_TRUE(data.ok()) << data.error().message;
    return data.ok() ? std::move(data).value().trials : std::vector<TrialRow>{};
}

constexpr double kAll = std::numeric_limits<double>::quiet_NaN();

// ---- The paper's published counts (Fink et al. 2019, sect. 6.2 and Fig. 7) ----

std::vector<TrialRow> paper_trials() {
    struct SceneCount {
        const char* scene;
        int hybrid, stereo;
    };
    std::vector<TrialRow> trials;
    for (const SceneCount& c : {SceneCount{"spheres", 175, 277}, SceneCount{"landscape", 162, 297},
                                SceneCount{"beams", 147, 304}}) {
        for (int i = 0; i < c.hybrid + c.stereo; ++i) {
            TrialRow t;
            t.scene = c.scene;
            t.decided = t.valid = true;
            t.reference_mode = "stereo";
            t.test_mode = "hybrid";
            t.chosen_mode = i < c.hybrid ? "hybrid" : "stereo";
            t.chose_test = i < c.hybrid;
            trials.push_back(t);
        }
    }
    return trials;
}

TEST(ChoiceRates, ReproduceThePapersPercentagesAndTheirSignificance) {
    const std::vector<ChoiceRate> rates = rates_by_scene(paper_trials());
    ASSERT_EQ(rates.size(), 3u);  // alphabetical
    EXPECT_EQ(rates[0].scene, "beams");
    EXPECT_EQ(rates[1].scene, "landscape");
    EXPECT_EQ(rates[2].scene, "spheres");
    // "SPHERES: 175 decisions for Hybrid / 277 for Stereo (~ 38,72 %) ... LANDSCAPE: 162 / 297
    // (~ 35,29 %). BEAMS: 147 / 304 (~ 32,59 %)."
    EXPECT_EQ(std::round(10000.0 * rates[2].rate) / 100.0, 38.72);
    EXPECT_EQ(std::round(10000.0 * rates[1].rate) / 100.0, 35.29);
    EXPECT_EQ(std::round(10000.0 * rates[0].rate) / 100.0, 32.59);
    EXPECT_EQ(rates[2].n, 452);
    EXPECT_EQ(rates[1].n, 459);
    EXPECT_EQ(rates[0].n, 451);
    // Each scene's preference for stereo is significant against 50 % (scipy.stats.binomtest).
    EXPECT_TRUE(near_relative(rates[2].binomial_p, 1.84334765809082e-06, kClosedForm));
    EXPECT_TRUE(near_relative(rates[1].binomial_p, 2.99063759382155e-10, kClosedForm));
    EXPECT_TRUE(near_relative(rates[0].binomial_p, 1.16292029430555e-13, kClosedForm));
    for (const ChoiceRate& rate : rates) {
        EXPECT_LT(rate.binomial_p, 0.05);
        EXPECT_LT(rate.wilson.upper, 0.5);
        EXPECT_LT(rate.clopper_pearson.upper, 0.5);
    }
    // The paper's 1362 analysable decisions.
    EXPECT_EQ(overall_rate(paper_trials()).n, 1362);
}

// ---- Exclusions ----

TEST(Exclusions, CountEachTrialOnceUnderItsFirstReason) {
    Exclusions tiny;
    EXPECT_EQ(analysable_trials(load("tiny.csv"), tiny).size(), 6u);
    EXPECT_EQ(tiny.practice, 2);
    EXPECT_EQ(tiny.undecided, 1);
    EXPECT_EQ(tiny.invalid, 1);
    EXPECT_EQ(tiny.kept, 6);

    Exclusions choices{9, 9, 9, 9};  // overwritten
    EXPECT_EQ(analysable_trials(load("choices.csv"), choices).size(), 68u);
    EXPECT_EQ(choices.practice, 12);
    EXPECT_EQ(choices.undecided, 1);
    EXPECT_EQ(choices.invalid, 3);
    EXPECT_EQ(choices.kept, 68);

    // A practice trial that is also undecided and invalid counts once, as practice.
    TrialRow t;
    t.practice = true;
    Exclusions one;
    EXPECT_TRUE(analysable_trials({t}, one).empty());
    EXPECT_EQ(one.practice, 1);
    EXPECT_EQ(one.undecided + one.invalid + one.kept, 0);
}

// ---- Rates on the fixtures ----

TEST(ChoiceRates, MatchScipyOnTheGeneratedFixture) {
    const std::vector<TrialRow> trials = load("choices.csv");  // all rows: the rates filter
    expect_rate(overall_rate(trials), {"", kAll, 36, 68, 0.412409220887279, 0.643268935788011,
                                       0.404491922366421, 0.651688033711369, 0.716300760154337});

    const std::vector<ChoiceRate> scenes = rates_by_scene(trials);
    ASSERT_EQ(scenes.size(), 3u);
    expect_rate(scenes[0], {"beams", kAll, 9, 21, 0.244699689253759, 0.634534456306933,
                            0.21819685688513, 0.659793690719725, 0.663623809814453});
    expect_rate(scenes[1], {"landscape", kAll, 12, 23, 0.329627373364274, 0.707628425833533,
                            0.305878001491374, 0.731803813824446, 1.0});
    expect_rate(scenes[2], {"spheres", kAll, 15, 24, 0.427099624426743, 0.788406324404512,
                            0.405936384007944, 0.812007071803998, 0.307456254959106});

    const std::vector<ChoiceRate> distances = rates_by_distance(trials);
    ASSERT_EQ(distances.size(), 4u);
    expect_rate(distances[0], {"", 1.6, 9, 18, 0.2903102150517, 0.7096897849483, 0.260190582895097,
                               0.739809417104903, 1.0});
    expect_rate(distances[1], {"", 8, 6, 16, 0.184812325588636, 0.613589594544973,
                               0.151983675081122, 0.645653905697922, 0.454498291015625});
    expect_rate(distances[2], {"", 20, 10, 17, 0.360054426429998, 0.783889432097852,
                               0.329247153946757, 0.815563038216053, 0.629058837890625});
    expect_rate(distances[3], {"", 39.5, 11, 17, 0.413003634852187, 0.826902796027563,
                               0.383283663443403, 0.857902516889779, 0.332305908203125});

    const ExpectedRate cells[] = {
        {"beams", 1.6, 3, 6, 0.187616306482651, 0.812383693517349, 0.118117248757025,
         0.881882751242975, 1},
        {"beams", 8, 1, 5, 0.0362241086324302, 0.624465370237475, 0.00505076337946806,
         0.71641793611809, 0.375},
        {"beams", 20, 2, 5, 0.117620774232648, 0.769275718723987, 0.0527449505263169,
         0.853367200365327, 1},
        {"beams", 39.5, 3, 5, 0.230724281276013, 0.882379225767352, 0.146632799634673,
         0.947255049473683, 1},
        {"landscape", 1.6, 4, 6, 0.299993315138392, 0.90322858889422, 0.222778095503512,
         0.956728131707258, 0.6875},
        {"landscape", 8, 1, 5, 0.0362241086324302, 0.624465370237475, 0.00505076337946806,
         0.71641793611809, 0.375},
        {"landscape", 20, 3, 6, 0.187616306482651, 0.812383693517349, 0.118117248757025,
         0.881882751242975, 1},
        {"landscape", 39.5, 4, 6, 0.299993315138392, 0.90322858889422, 0.222778095503512,
         0.956728131707258, 0.6875},
        {"spheres", 1.6, 2, 6, 0.0967714111057804, 0.700006684861608, 0.0432718682927417,
         0.777221904496488, 0.6875},
        {"spheres", 8, 4, 6, 0.299993315138392, 0.90322858889422, 0.222778095503512,
         0.956728131707258, 0.6875},
        {"spheres", 20, 5, 6, 0.43649717781353, 0.969946630251693, 0.358765421002325,
         0.995789255485511, 0.21875},
        {"spheres", 39.5, 4, 6, 0.299993315138392, 0.90322858889422, 0.222778095503512,
         0.956728131707258, 0.6875},
    };
    const std::vector<ChoiceRate> both = rates_by_scene_and_distance(trials);
    ASSERT_EQ(both.size(), std::size(cells));
    for (std::size_t i = 0; i < both.size(); ++i) expect_rate(both[i], cells[i]);
}

TEST(ChoiceRates, MatchScipyOnTheTinyFixtureWithRatesOfZeroAndOne) {
    const std::vector<TrialRow> trials = load("tiny.csv");
    const std::vector<ChoiceRate> cells = rates_by_scene_and_distance(trials);
    ASSERT_EQ(cells.size(), 4u);
    expect_rate(cells[0], {"beams", 3, 0, 1, 0, 0.793450685622763, 0, 0.975, 1});
    expect_rate(cells[1], {"beams", 8, 1, 2, 0.0945312057342307, 0.905468794265769,
                           0.012579117093425, 0.987420882906575, 1});
    expect_rate(cells[2], {"spheres", 3, 1, 1, 0.206549314377237, 1, 0.025, 1, 1});
    expect_rate(cells[3], {"spheres", 8, 2, 2, 0.342380227506653, 1, 0.158113883008419, 1, 0.5});
}

TEST(ChoiceRates, NoTrialsGiveAnEmptyRateNotACrash) {
    const ChoiceRate none = overall_rate({});
    EXPECT_EQ(none.n, 0);
    EXPECT_EQ(none.rate, 0.0);
    EXPECT_EQ(none.wilson.lower, 0.0);
    EXPECT_EQ(none.wilson.upper, 1.0);
    EXPECT_EQ(none.binomial_p, 1.0);
    EXPECT_TRUE(rates_by_scene({}).empty());
}

// ---- Distance x decision chi-square ----

TEST(ChiSquare, MatchesScipyOnTheGeneratedFixture) {
    const std::vector<TrialRow> trials = load("choices.csv");
    const Result<ChiSquareTest> all = chi_square_by_distance(trials);
    ASSERT_TRUE(all.ok()) << all.error().message;
    EXPECT_EQ(all->observed, (std::vector<std::vector<int>>{{9, 9}, {6, 10}, {10, 7}, {11, 6}}));
    EXPECT_EQ(all->row_labels, (std::vector<std::string>{"1.6", "8", "20", "39.5"}));
    EXPECT_EQ(all->column_labels, (std::vector<std::string>{"hybrid", "stereo"}));
    EXPECT_EQ(all->n, 68);
    EXPECT_EQ(all->df, 3);
    EXPECT_TRUE(near_relative(all->chi_square, 2.77430555555556, kClosedForm));
    EXPECT_TRUE(near_relative(all->p, 0.427747164939123, kClosedForm));
    EXPECT_TRUE(near_relative(all->phi, 0.20198666072568, kClosedForm));
    EXPECT_TRUE(near_relative(all->cramers_v, 0.20198666072568, kClosedForm));

    const Result<ChiSquareTest> spheres = chi_square_by_distance(trials, "spheres");
    ASSERT_TRUE(spheres.ok()) << spheres.error().message;
    EXPECT_EQ(spheres->observed, (std::vector<std::vector<int>>{{2, 4}, {4, 2}, {5, 1}, {4, 2}}));
    EXPECT_EQ(spheres->n, 24);
    EXPECT_TRUE(near_relative(spheres->chi_square, 3.37777777777778, kClosedForm));
    EXPECT_TRUE(near_relative(spheres->p, 0.336963300432286, kClosedForm));
    EXPECT_TRUE(near_relative(spheres->phi, 0.375154289247425, kClosedForm));
}

TEST(ChiSquare, MatchesScipyOnTheTinyFixture) {
    const Result<ChiSquareTest> test = chi_square_by_distance(load("tiny.csv"));
    ASSERT_TRUE(test.ok()) << test.error().message;
    EXPECT_EQ(test->observed, (std::vector<std::vector<int>>{{1, 1}, {3, 1}}));
    EXPECT_EQ(test->df, 1);
    EXPECT_TRUE(near_relative(test->chi_square, 0.375, kClosedForm));
    EXPECT_TRUE(near_relative(test->p, 0.54029137460742, kClosedForm));
    EXPECT_TRUE(near_relative(test->phi, 0.25, kClosedForm));
}

TEST(ChiSquare, CramersVDiffersFromPhiBeyondTwoColumns) {
    // 3 x 3 by hand: rows (10,0,0) (0,10,0) (0,0,10): chi2 = 2 n = 60, phi = sqrt(2),
    // V = sqrt(60 / (30 * 2)) = 1; p = P(chi2_4 > 60) = exp(-30) (1 + 30) (closed form for
    // 4 degrees of freedom).
    const Result<ChiSquareTest> test =
        chi_square_independence({{10, 0, 0}, {0, 10, 0}, {0, 0, 10}}, {}, {});
    ASSERT_TRUE(test.ok()) << test.error().message;
    EXPECT_TRUE(near_relative(test->chi_square, 60.0, kClosedForm));
    EXPECT_EQ(test->df, 4);
    EXPECT_TRUE(near_relative(test->phi, std::sqrt(2.0), kClosedForm));
    EXPECT_TRUE(near_relative(test->cramers_v, 1.0, kClosedForm));
    EXPECT_TRUE(near_relative(test->p, std::exp(-30.0) * 31.0, kClosedForm));
}

TEST(ChiSquare, RefusesTablesWithoutAContrast) {
    std::vector<TrialRow> trials = load("tiny.csv");
    const Result<ChiSquareTest> one_scene_one_distance =
        chi_square_by_distance(std::vector<TrialRow>(trials.begin() + 1, trials.begin() + 2));
    ASSERT_FALSE(one_scene_one_distance.ok());
    EXPECT_NE(one_scene_one_distance.error().message.find("needs at least 2"), std::string::npos);

    const Result<ChiSquareTest> unknown = chi_square_by_distance(trials, "castle");
    ASSERT_FALSE(unknown.ok());
    EXPECT_NE(unknown.error().message.find("scene 'castle'"), std::string::npos);

    // spheres in tiny.csv: everyone chose hybrid, so the 'stereo' column is empty.
    const Result<ChiSquareTest> spheres = chi_square_by_distance(trials, "spheres");
    ASSERT_FALSE(spheres.ok());
    EXPECT_NE(spheres.error().message.find("column 'stereo' has no counts"), std::string::npos)
        << spheres.error().message;

    EXPECT_FALSE(chi_square_independence({{1, 2}, {3}}, {}, {}).ok());
    EXPECT_FALSE(chi_square_independence({{1, 2}}, {}, {}).ok());
}

}  // namespace
}  // namespace monoplane::analysis
