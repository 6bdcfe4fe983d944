// Summaries against numpy 1.24.2 (np.quantile's default 'linear' method = Hyndman & Fan type 7,
// R's default; std with ddof=1) and the order-effect rates against scipy/statsmodels, all
// computed by tests/fixtures/analysis/make_reference.py, run as
//     /usr/bin/python3 tests/fixtures/analysis/make_reference.py
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "analysis/dataset.h"
#include "analysis/summaries.h"

namespace monoplane::analysis {
namespace {

const std::filesystem::path kFixtures = MONOPLANE_ANALYSIS_FIXTURES;

testing::AssertionResult near_relative(double actual, double expected, double relative) {
    if (std::abs(actual - expected) <= relative * std::abs(expected))
        return testing::AssertionSuccess();
    return testing::AssertionFailure()
           << actual << " is not within " << relative << " (relative) of " << expected;
}
constexpr double kClosedForm = 1e-6;

struct Expected {
    int n;
    double mean, sd, median, q1, q3, min, max;
};

void expect_summary(const Summary& s, const Expected& e) {
    EXPECT_EQ(s.n, e.n);
    EXPECT_TRUE(near_relative(s.mean, e.mean, kClosedForm));
    EXPECT_TRUE(near_relative(s.sd, e.sd, kClosedForm));
    EXPECT_TRUE(near_relative(s.median, e.median, kClosedForm));
    EXPECT_TRUE(near_relative(s.q1, e.q1, kClosedForm));
    EXPECT_TRUE(near_relative(s.q3, e.q3, kClosedForm));
    EXPECT_EQ(s.min, e.min);
    EXPECT_EQ(s.max, e.max);
}

std::vector<TrialRow> choices() {
    Result<Dataset> data = read_export_csv(kFixtures / "choices.csv");
    EXPECT_TRUE(data.ok()) << data.error().message;
    return data.ok() ? std::move(data).value().trials : std::vector<TrialRow>{};
}

TEST(Summarize, MatchesNumpyType7Quantiles) {
    expect_summary(summarize({1, 2, 2, 5, 7, 7, 6}),
                   {7, 4.28571428571429, 2.56347977784662, 5, 2, 6.5, 1, 7});
    expect_summary(summarize({4.5, 1.0, 3.25, 10.0}),
                   {4, 4.6875, 3.82630696625349, 3.875, 2.6875, 5.875, 1, 10});
}

TEST(Summarize, EmptyAndSingleValues) {
    const Summary empty = summarize({});
    EXPECT_EQ(empty.n, 0);
    EXPECT_EQ(empty.mean, 0.0);
    const Summary one = summarize({2.5});
    EXPECT_EQ(one.n, 1);
    EXPECT_EQ(one.mean, 2.5);
    EXPECT_EQ(one.sd, 0.0);
    EXPECT_EQ(one.median, 2.5);
    EXPECT_EQ(one.q1, 2.5);
    EXPECT_EQ(one.q3, 2.5);
}

TEST(Summaries, DecisionTimesAndSwitchesByScene) {
    const std::vector<TrialRow> trials = choices();  // all rows: practice etc. are skipped
    const std::vector<GroupSummary> times = decision_times_by_scene(trials);
    ASSERT_EQ(times.size(), 3u);
    EXPECT_EQ(times[0].group, "beams");
    expect_summary(times[0].summary,
                   {21, 5.96409523809524, 2.82532486459101, 5.137, 3.991, 7.567, 2.24, 13.908});
    EXPECT_EQ(times[1].group, "landscape");
    expect_summary(times[1].summary,
                   {23, 7.31426086956522, 3.9552261539454, 6.874, 4.0245, 9.106, 2.376, 17.876});
    EXPECT_EQ(times[2].group, "spheres");
    expect_summary(times[2].summary, {24, 5.99045833333333, 2.98570202915228, 5.3975, 4.46275,
                                      7.07475, 1.329, 11.752});

    const std::vector<GroupSummary> switches = switches_by_scene(trials);
    ASSERT_EQ(switches.size(), 3u);
    expect_summary(switches[0].summary, {21, 3.38095238095238, 1.4309504001254, 3, 3, 4, 1, 7});
    expect_summary(switches[1].summary, {23, 3.1304347826087, 1.96108383359089, 3, 2, 4, 0, 9});
    expect_summary(switches[2].summary, {24, 3.54166666666667, 1.79320375589193, 4, 2, 4, 1, 8});
}

TEST(Summaries, RatesByFirstScene) {
    const std::vector<ChoiceRate> rates = rates_by_first_scene(choices());
    ASSERT_EQ(rates.size(), 3u);
    struct E {
        const char* scene;
        int k, n;
        double wl, wu, cl, cu, p;
    };
    const E expected[] = {
        {"beams", 9, 23, 0.221576227924779, 0.592144776086183, 0.197076423969014, 0.61458104261115,
         0.404872894287109},
        {"landscape", 17, 23, 0.535299951625746, 0.874513839550136, 0.515948029597562,
         0.897713866084642, 0.0346896648406982},
        {"spheres", 10, 22, 0.269202941808133, 0.653402046792651, 0.243861865923017,
         0.677895245446828, 0.831811904907227},
    };
    for (std::size_t i = 0; i < 3; ++i) {
        SCOPED_TRACE(expected[i].scene);
        EXPECT_EQ(rates[i].scene, expected[i].scene);
        EXPECT_TRUE(std::isnan(rates[i].mono_plane));
        EXPECT_EQ(rates[i].test_chosen, expected[i].k);
        EXPECT_EQ(rates[i].n, expected[i].n);
        EXPECT_TRUE(near_relative(rates[i].wilson.lower, expected[i].wl, kClosedForm));
        EXPECT_TRUE(near_relative(rates[i].wilson.upper, expected[i].wu, kClosedForm));
        EXPECT_TRUE(near_relative(rates[i].clopper_pearson.lower, expected[i].cl, kClosedForm));
        EXPECT_TRUE(near_relative(rates[i].clopper_pearson.upper, expected[i].cu, kClosedForm));
        EXPECT_TRUE(near_relative(rates[i].binomial_p, expected[i].p, kClosedForm));
    }
}

TEST(Summaries, QuestionnaireCountsPerItem) {
    std::vector<AnswerRow> answers;
    const int item0[] = {1, 2, 2, 5, 7, 7, 6};
    for (int i = 0; i < 7; ++i)
        answers.push_back({"a.db", i + 1, "P" + std::to_string(i), 0,
                           "I noticed differences, sometimes", item0[i], 7});
    answers.push_back({"a.db", 1, "P0", 1, "The images were blurred", 3, 5});
    answers.push_back({"a.db", 2, "P1", 1, "The images were blurred", 3, 5});
    const std::vector<ItemSummary> items = questionnaire_summaries(answers);
    ASSERT_EQ(items.size(), 2u);
    EXPECT_EQ(items[0].item, 0);
    EXPECT_EQ(items[0].text, "I noticed differences, sometimes");
    EXPECT_EQ(items[0].scale_points, 7);
    EXPECT_EQ(items[0].counts, (std::vector<int>{1, 2, 0, 0, 1, 1, 2}));
    expect_summary(items[0].summary, {7, 4.28571428571429, 2.56347977784662, 5, 2, 6.5, 1, 7});
    EXPECT_EQ(items[1].item, 1);
    EXPECT_EQ(items[1].scale_points, 5);
    EXPECT_EQ(items[1].counts, (std::vector<int>{0, 0, 2, 0, 0}));
    EXPECT_EQ(items[1].summary.mean, 3.0);
}

}  // namespace
}  // namespace monoplane::analysis
