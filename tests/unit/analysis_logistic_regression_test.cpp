// fit_choice_model() against statsmodels 0.13.5 (Debian 12):
//     smf.glm("y ~ mono_plane + C(scene)", data, family=sm.families.Binomial())
//        .fit(cov_type="cluster", cov_kwds={"groups": participant})
// whose default use_correction=True is the CR1 factor G/(G-1) * (N-1)/(N-K) used here, with
// normal (z) tests. Computed by tests/fixtures/analysis/make_reference.py, run as
//     /usr/bin/python3 tests/fixtures/analysis/make_reference.py
// on tests/fixtures/analysis/choices.csv (6 participants, 68 analysable trials). The CR2 columns
// are checked against R's clubSandwich further down.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "analysis/dataset.h"
#include "analysis/linear_algebra.h"
#include "analysis/logistic_regression.h"

namespace monoplane::analysis {
namespace {

const std::filesystem::path kFixtures = MONOPLANE_ANALYSIS_FIXTURES;
constexpr double kRegression = 1e-4;  // relative

testing::AssertionResult near_relative(double actual, double expected, double relative) {
    if (std::abs(actual - expected) <= relative * std::abs(expected))
        return testing::AssertionSuccess();
    return testing::AssertionFailure()
           << actual << " is not within " << relative << " (relative) of " << expected;
}

std::vector<TrialRow> choices() {
    Result<Dataset> data = read_export_csv(kFixtures / "choices.csv");
    EXPECT_TRUE(data.ok()) << data.error().message;
    return data.ok() ? std::move(data).value().trials : std::vector<TrialRow>{};
}

struct Expected {
    const char* name;
    double b, se, z, p, odds_ratio, lower, upper;
};

void expect_coefficient(const Coefficient& c, const Expected& e) {
    SCOPED_TRACE(e.name);
    EXPECT_EQ(c.name, e.name);
    EXPECT_TRUE(near_relative(c.estimate, e.b, kRegression));
    EXPECT_TRUE(near_relative(c.std_error, e.se, kRegression));
    EXPECT_TRUE(near_relative(c.z, e.z, kRegression));
    EXPECT_TRUE(near_relative(c.p, e.p, kRegression));
    EXPECT_TRUE(near_relative(c.odds_ratio, e.odds_ratio, kRegression));
    EXPECT_TRUE(near_relative(c.ci_lower, e.lower, kRegression));
    EXPECT_TRUE(near_relative(c.ci_upper, e.upper, kRegression));
}

TEST(LogisticRegression, MatchesStatsmodelsWithDistanceInMetresAndScenes) {
    const Result<LogisticFit> fit = fit_choice_model(choices());
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    EXPECT_EQ(fit->n, 68);
    EXPECT_EQ(fit->clusters, 6);
    EXPECT_TRUE(fit->converged);
    EXPECT_EQ(fit->distance_term, "mono_plane_m");
    EXPECT_TRUE(near_relative(fit->log_likelihood, -45.2794243575435, 1e-6));
    ASSERT_EQ(fit->coefficients.size(), 4u);
    // statsmodels orders the scene dummies before mono_plane; the values are the same.
    expect_coefficient(fit->coefficients[0],
                       {"intercept", -0.66687530129, 0.548162341029, -1.21656533362, 0.223769639122,
                        0.513310013619, 0.175300480264, 1.50306017236});
    expect_coefficient(fit->coefficients[1],
                       {"mono_plane_m", 0.0225799598393, 0.0146244407409, 1.54398791991,
                        0.122591259126, 1.02283681676, 0.993935049211, 1.05257899352});
    expect_coefficient(fit->coefficients[2],
                       {"scene[landscape]", 0.358423222945, 0.506180090705, 0.70809427223,
                        0.478886716329, 1.43107115448, 0.53063996245, 3.85942408056});
    expect_coefficient(fit->coefficients[3],
                       {"scene[spheres]", 0.802050351873, 0.749577339797, 1.07000346634,
                        0.284617748446, 2.23010875173, 0.51319764364, 9.69097404511});
}

TEST(LogisticRegression, MatchesStatsmodelsWithLog2Distance) {
    const Result<LogisticFit> fit = fit_choice_model(choices(), {.log2_distance = true});
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    EXPECT_EQ(fit->distance_term, "log2_mono_plane_m");
    EXPECT_TRUE(near_relative(fit->log_likelihood, -45.6745028562492, 1e-6));
    ASSERT_EQ(fit->coefficients.size(), 4u);
    expect_coefficient(fit->coefficients[0],
                       {"intercept", -0.724893609624, 0.607699495894, -1.19284879208,
                        0.232928597246, 0.484376099169, 0.147200049708, 1.59388672702});
    expect_coefficient(fit->coefficients[1],
                       {"log2_mono_plane_m", 0.135216517483, 0.113216954755, 1.19431332325,
                        0.23235542787, 1.1447846234, 0.916966227923, 1.42920403617});
    expect_coefficient(fit->coefficients[2],
                       {"scene[landscape]", 0.360955059423, 0.51636563729, 0.699029976738,
                        0.484533297226, 1.43469898323, 0.521470281616, 3.94722622754});
    expect_coefficient(fit->coefficients[3],
                       {"scene[spheres]", 0.792433953551, 0.755126123663, 1.04940609088,
                        0.293991256096, 2.20876592271, 0.502788309861, 9.70318284189});
}

TEST(LogisticRegression, MatchesStatsmodelsWithoutSceneTerms) {
    const Result<LogisticFit> fit = fit_choice_model(choices(), {.scene_terms = false});
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    EXPECT_TRUE(near_relative(fit->log_likelihood, -46.1456208340166, 1e-6));
    ASSERT_EQ(fit->coefficients.size(), 2u);
    expect_coefficient(fit->coefficients[0],
                       {"intercept", -0.262978289785, 0.519581484775, -0.506134836384,
                        0.612761996568, 0.768758587045, 0.277665177963, 2.12842593188});
    expect_coefficient(fit->coefficients[1],
                       {"mono_plane_m", 0.0224282823386, 0.0141873785209, 1.58086163032,
                        0.113909679138, 1.0226816872, 0.994635969468, 1.0515182091});
}

// The small-sample columns against R's clubSandwich 0.5.8 (Debian 12's r-cran-clubsandwich),
// an implementation independent of this one:
//     fit <- glm(y ~ mono_plane + scene, data, family = binomial)
//     coef_test(fit, vcov = vcovCR(fit, cluster = participant, type = "CR2"),
//               test = "Satterthwaite")
// computed by tests/fixtures/analysis/make_cr2_reference.R on the same choices.csv. The CR2
// standard error differs from CR1's (e.g. 0.01422 against 0.01462 for the distance) and the df
// from G - 1 = 5 (4.96), so a formula slip in either shows.
struct ExpectedCr2 {
    const char* name;
    double se, t, df, p, lower, upper;
};

void expect_cr2(const Coefficient& c, const ExpectedCr2& e) {
    SCOPED_TRACE(e.name);
    EXPECT_EQ(c.name, e.name);
    EXPECT_TRUE(near_relative(c.std_error_cr2, e.se, kRegression));
    EXPECT_TRUE(near_relative(c.t_cr2, e.t, kRegression));
    EXPECT_TRUE(near_relative(c.df_cr2, e.df, kRegression));
    EXPECT_TRUE(near_relative(c.p_cr2, e.p, kRegression));
    EXPECT_TRUE(near_relative(c.ci_lower_cr2, e.lower, kRegression));
    EXPECT_TRUE(near_relative(c.ci_upper_cr2, e.upper, kRegression));
}

TEST(LogisticRegression, Cr2MatchesClubSandwichWithDistanceInMetresAndScenes) {
    const Result<LogisticFit> fit = fit_choice_model(choices());
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    ASSERT_EQ(fit->coefficients.size(), 4u);
    expect_cr2(fit->coefficients[0], {"intercept", 0.534752129532, -1.24707367107, 4.92755040163,
                                      0.268364568859, 0.129044143274, 2.04183749372});
    expect_cr2(fit->coefficients[1], {"mono_plane_m", 0.0142153007308, 1.58842646152, 4.9612963798,
                                      0.173509004008, 0.986050664558, 1.06099533353});
    expect_cr2(fit->coefficients[2],
               {"scene[landscape]", 0.493165086998, 0.726781421463, 4.97145770069, 0.500125135524,
                0.401924803109, 5.09539255439});
    expect_cr2(fit->coefficients[3],
               {"scene[spheres]", 0.725832983784, 1.10500675747, 4.96767105213, 0.319780576438,
                0.343894336136, 14.4619568336});
}

TEST(LogisticRegression, Cr2MatchesClubSandwichWithLog2Distance) {
    const Result<LogisticFit> fit = fit_choice_model(choices(), {.log2_distance = true});
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    ASSERT_EQ(fit->coefficients.size(), 4u);
    expect_cr2(fit->coefficients[0], {"intercept", 0.593174020643, -1.2220589311, 4.97953835659,
                                      0.276360023221, 0.105232566289, 2.2295399012});
    expect_cr2(fit->coefficients[1], {"log2_mono_plane_m", 0.110162972605, 1.22742255665,
                                      4.98836044521, 0.274415838827, 0.86228858691, 1.51982973436});
    expect_cr2(fit->coefficients[2],
               {"scene[landscape]", 0.503163830191, 0.717370839803, 4.97106889464, 0.505430685109,
                0.392689461381, 5.24170209519});
    expect_cr2(fit->coefficients[3], {"scene[spheres]", 0.732643859093, 1.08160867482,
                                      4.96678974179, 0.32912159804, 0.334646352918, 14.5785150766});
}

TEST(LogisticRegression, Cr2MatchesClubSandwichWithoutSceneTerms) {
    const Result<LogisticFit> fit = fit_choice_model(choices(), {.scene_terms = false});
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    ASSERT_EQ(fit->coefficients.size(), 2u);
    expect_cr2(fit->coefficients[0], {"intercept", 0.5165401402, -0.509114915412, 4.98648750061,
                                      0.632392897528, 0.203544636036, 2.90348975371});
    expect_cr2(fit->coefficients[1], {"mono_plane_m", 0.0140752496782, 1.59345538099, 4.96778746597,
                                      0.172315488314, 0.986271133767, 1.06043642313});
}

// A small synthetic data set: participants P0..P(participants-1), every participant at every
// distance and scene, the test chosen where `chooses` says so.
template <class Chooses>
std::vector<TrialRow> synthetic(int participants, std::vector<double> distances,
                                std::vector<std::string> scenes, Chooses chooses) {
    std::vector<TrialRow> trials;
    for (int p = 0; p < participants; ++p)
        for (const std::string& scene : scenes)
            for (double m : distances) {
                TrialRow t;
                t.participant = "P" + std::to_string(p);
                t.scene = scene;
                t.mono_plane = m;
                t.decided = t.valid = true;
                t.chose_test = chooses(p, scene, m);
                trials.push_back(t);
            }
    return trials;
}

TEST(LogisticRegression, RefusesSeparatedData) {
    // Hybrid always chosen beyond 8 m, never below: the slope has no finite maximum.
    const auto by_distance = synthetic(5, {1.6, 3, 8, 20, 39.5}, {"beams", "spheres"},
                                       [](int, const std::string&, double m) { return m > 8; });
    const Result<LogisticFit> fit = fit_choice_model(by_distance);
    ASSERT_FALSE(fit.ok());
    EXPECT_NE(fit.error().message.find("separated"), std::string::npos) << fit.error().message;

    // Nobody ever chose hybrid in BEAMS (quasi-complete separation of its dummy).
    const auto by_scene = synthetic(5, {1.6, 8, 39.5}, {"beams", "spheres"},
                                    [](int p, const std::string& s, double m) {
                                        return s == "spheres" && (p + static_cast<int>(m)) % 2 == 0;
                                    });
    const Result<LogisticFit> scene_fit = fit_choice_model(by_scene);
    ASSERT_FALSE(scene_fit.ok());
    EXPECT_NE(scene_fit.error().message.find("scene 'beams'"), std::string::npos)
        << scene_fit.error().message;

    const auto constant =
        synthetic(5, {1.6, 8}, {"beams"}, [](int, const std::string&, double) { return false; });
    const Result<LogisticFit> constant_fit = fit_choice_model(constant);
    ASSERT_FALSE(constant_fit.ok());
    EXPECT_NE(constant_fit.error().message.find("same outcome"), std::string::npos);
}

TEST(LogisticRegression, RefusesTooFewClustersTrialsOrDistances) {
    const auto mixed = [](int p, const std::string&, double m) {
        return (p + static_cast<int>(m * 10)) % 3 == 0;
    };
    const Result<LogisticFit> one_participant =
        fit_choice_model(synthetic(1, {1.6, 3, 8, 20, 39.5}, {"beams", "spheres"}, mixed));
    ASSERT_FALSE(one_participant.ok());
    EXPECT_NE(one_participant.error().message.find("more participants than coefficients"),
              std::string::npos);
    // Two scenes: 3 coefficients. The sandwich from 3 participants has rank <= 2: refused; from
    // 4 it is estimable.
    const Result<LogisticFit> three =
        fit_choice_model(synthetic(3, {1.6, 3, 8, 20, 39.5}, {"beams", "spheres"}, mixed));
    ASSERT_FALSE(three.ok());
    EXPECT_NE(three.error().message.find("3 participant(s) for 3 coefficients"), std::string::npos)
        << three.error().message;
    const Result<LogisticFit> four =
        fit_choice_model(synthetic(4, {1.6, 3, 8, 20, 39.5}, {"beams", "spheres"}, mixed));
    ASSERT_TRUE(four.ok()) << four.error().message;
    for (const Coefficient& c : four->coefficients) EXPECT_GT(c.std_error, 0.0) << c.name;

    // 2 trials for 2 coefficients (no scene terms with one scene).
    const Result<LogisticFit> too_few = fit_choice_model(
        synthetic(1, {1.6, 8}, {"beams"}, [](int, const std::string&, double m) { return m > 2; }));
    ASSERT_FALSE(too_few.ok());
    EXPECT_NE(too_few.error().message.find("too few"), std::string::npos)
        << too_few.error().message;

    const Result<LogisticFit> one_distance = fit_choice_model(synthetic(
        4, {8}, {"beams", "spheres"}, [](int p, const std::string&, double) { return p % 2; }));
    ASSERT_FALSE(one_distance.ok());
    EXPECT_NE(one_distance.error().message.find("only one distance"), std::string::npos);

    TrialRow zero;
    zero.participant = "P9";
    zero.scene = "beams";
    zero.mono_plane = 0.0;
    zero.decided = zero.valid = true;
    std::vector<TrialRow> with_zero = synthetic(4, {1.6, 8, 20}, {"beams", "spheres"}, mixed);
    with_zero.push_back(zero);
    const Result<LogisticFit> log_of_zero = fit_choice_model(with_zero, {.log2_distance = true});
    ASSERT_FALSE(log_of_zero.ok());
    EXPECT_NE(log_of_zero.error().message.find("distances > 0"), std::string::npos);
}

TEST(LogisticRegression, RefusesASingularDesign) {
    // BEAMS only at 8 m and SPHERES only at 20 m: the distance column is 8 + 12 x the SPHERES
    // dummy, so distance and scene cannot be told apart.
    std::vector<TrialRow> trials =
        synthetic(4, {8}, {"beams"}, [](int p, const std::string&, double) { return p % 2; });
    const std::vector<TrialRow> spheres = synthetic(
        4, {20}, {"spheres"}, [](int p, const std::string&, double) { return p < 2 && p; });
    trials.insert(trials.end(), spheres.begin(), spheres.end());
    trials.push_back(trials.front());  // more trials than coefficients
    trials.back().chose_test = !trials.back().chose_test;
    const Result<LogisticFit> fit = fit_choice_model(trials);
    ASSERT_FALSE(fit.ok());
    EXPECT_NE(fit.error().message.find("singular"), std::string::npos) << fit.error().message;
}

// The gaze error as predictor (issue 45): the data of tests/fixtures/analysis/
// make_gaze_reference.py, whose docstring states the rule, fitted there by statsmodels 0.13.5
//     sm.Logit(y, X).fit(cov_type="cluster", cov_kwds={"groups": participant})
// (CR1 with its default correction, z tests), run as
//     /usr/bin/python3 tests/fixtures/analysis/make_gaze_reference.py
std::vector<TrialRow> synthetic_gaze() {
    std::vector<TrialRow> trials;
    for (int p = 0; p < 12; ++p)
        for (int t = 0; t < 20; ++t) {
            TrialRow row;
            row.participant = "P" + std::to_string(p);
            row.scene = t < 10 ? "beams" : "spheres";
            row.mono_plane = 8.0;
            row.decided = true;
            row.valid = !(p == 2 && t == 0);
            const double error = 0.25 * ((3 * p + 7 * t) % 13) + 0.1 * (p % 4);
            if (!(t == 19 && p % 4 == 1)) row.gaze_error_test_arcmin = error;
            const int threshold = 2 + (error > 1.5) + (error > 2.5) + (p % 3 == 0);
            row.chose_test = (5 * p + 3 * t) % 7 < threshold;
            trials.push_back(row);
        }
    return trials;
}

// statsmodels reports b, se, z and p; the odds ratio and its interval follow as exp(b) and
// exp(b -+ 1.959963984540054 se).
void expect_statsmodels(const Coefficient& c, const char* name, double b, double se, double z,
                        double p) {
    SCOPED_TRACE(name);
    EXPECT_EQ(c.name, name);
    EXPECT_TRUE(near_relative(c.estimate, b, kRegression));
    EXPECT_TRUE(near_relative(c.std_error, se, kRegression));
    EXPECT_TRUE(near_relative(c.z, z, kRegression));
    EXPECT_TRUE(near_relative(c.p, p, kRegression));
    EXPECT_TRUE(near_relative(c.odds_ratio, std::exp(b), kRegression));
    EXPECT_TRUE(near_relative(c.ci_lower, std::exp(b - 1.959963984540054 * se), kRegression));
    EXPECT_TRUE(near_relative(c.ci_upper, std::exp(b + 1.959963984540054 * se), kRegression));
}

TEST(LogisticRegression, GazeErrorMatchesStatsmodelsWithoutSceneTerms) {
    const Result<LogisticFit> fit = fit_choice_model(
        synthetic_gaze(), {.predictor = ChoicePredictor::GazeError, .scene_terms = false});
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    // 240 trials less 1 invalid less 3 without gaze.
    EXPECT_EQ(fit->n, 236);
    EXPECT_EQ(fit->clusters, 12);
    EXPECT_EQ(fit->skipped_without_predictor, 3);
    EXPECT_EQ(fit->distance_term, "gaze_error_test_arcmin");
    EXPECT_TRUE(near_relative(fit->log_likelihood, -160.33354219283194, 1e-6));
    ASSERT_EQ(fit->coefficients.size(), 2u);
    expect_statsmodels(fit->coefficients[0], "intercept", -0.667718604442185, 0.17347231348809733,
                       -3.849136447286731, 0.00011853496886176057);
    expect_statsmodels(fit->coefficients[1], "gaze_error_test_arcmin", 0.2792715545044488,
                       0.07965684985810435, 3.5059326975887872, 0.0004550102576277451);
}

TEST(LogisticRegression, GazeErrorMatchesStatsmodelsWithSceneTerms) {
    const Result<LogisticFit> fit =
        fit_choice_model(synthetic_gaze(), {.predictor = ChoicePredictor::GazeError});
    ASSERT_TRUE(fit.ok()) << fit.error().message;
    EXPECT_EQ(fit->n, 236);
    EXPECT_TRUE(near_relative(fit->log_likelihood, -159.65843787635953, 1e-6));
    ASSERT_EQ(fit->coefficients.size(), 3u);
    expect_statsmodels(fit->coefficients[0], "intercept", -0.8221158717719006, 0.17215779068662562,
                       -4.775362581577135, 1.7938375221064418e-06);
    expect_statsmodels(fit->coefficients[1], "gaze_error_test_arcmin", 0.27982326693887705,
                       0.07954689376870931, 3.5177145666113834, 0.00043528028983453774);
    expect_statsmodels(fit->coefficients[2], "scene[spheres]", 0.3072169503632588,
                       0.14090395034732262, 2.1803288666214202, 0.029233092780657506);
}

// Without gaze the model says so; with one gaze error only, its effect is not estimable. The
// distance model ignores the gaze errors.
TEST(LogisticRegression, GazeErrorRefusesDataWithoutGazeOrWithOneValue) {
    std::vector<TrialRow> trials = synthetic_gaze();
    for (TrialRow& t : trials) t.gaze_error_test_arcmin.reset();
    const Result<LogisticFit> none =
        fit_choice_model(trials, {.predictor = ChoicePredictor::GazeError});
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message.find("no analysable trial has a gaze error"), std::string::npos)
        << none.error().message;

    for (TrialRow& t : trials) t.gaze_error_test_arcmin = 1.5;
    const Result<LogisticFit> one =
        fit_choice_model(trials, {.predictor = ChoicePredictor::GazeError});
    ASSERT_FALSE(one.ok());
    EXPECT_NE(one.error().message.find("only one gaze error"), std::string::npos)
        << one.error().message;

    const Result<LogisticFit> distance = fit_choice_model(synthetic_gaze());
    ASSERT_FALSE(distance.ok());  // every trial at 8 m
    EXPECT_NE(distance.error().message.find("only one distance"), std::string::npos);
}

TEST(LinearAlgebra, InvertsAPositiveDefiniteMatrixAndRefusesASingularOne) {
    Matrix a(3, 3);
    const double values[3][3] = {{4, 2, 0.4}, {2, 5, 1}, {0.4, 1, 3}};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a(i, j) = values[i][j];
    const std::optional<Matrix> inverse = inverse_positive_definite(a);
    ASSERT_TRUE(inverse.has_value());
    const Matrix identity = a * *inverse;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_NEAR(identity(i, j), i == j ? 1.0 : 0.0, 1e-14);

    Matrix singular(2, 2);
    singular(0, 0) = 1;
    singular(0, 1) = singular(1, 0) = 2;
    singular(1, 1) = 4;
    EXPECT_FALSE(inverse_positive_definite(singular).has_value());
}

TEST(LinearAlgebra, MultipliesRectangularMatrices) {
    Matrix a(2, 3);
    Matrix b(3, 2);
    for (std::size_t i = 0; i < 2; ++i)
        for (std::size_t k = 0; k < 3; ++k) a(i, k) = static_cast<double>(1 + i * 3 + k);  // 1..6
    for (std::size_t k = 0; k < 3; ++k)
        for (std::size_t j = 0; j < 2; ++j) b(k, j) = static_cast<double>(7 + k * 2 + j);  // 7..12
    const Matrix product = a * b;
    ASSERT_EQ(product.rows(), 2u);
    ASSERT_EQ(product.columns(), 2u);
    EXPECT_EQ(product(0, 0), 58.0);
    EXPECT_EQ(product(0, 1), 64.0);
    EXPECT_EQ(product(1, 0), 139.0);
    EXPECT_EQ(product(1, 1), 154.0);
}

// The inverse is exactly symmetric, and the singularity test is relative to the diagonal: the
// same matrix in other units (columns scaled by 1e6) is as invertible.
TEST(LinearAlgebra, TheInverseIsSymmetricAndUnitFree) {
    const double values[3][3] = {{4, 2, 0.4}, {2, 5, 1}, {0.4, 1, 3}};
    const double scale[3] = {1e6, 1, 1e-6};
    Matrix a(3, 3);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a(i, j) = values[i][j] * scale[i] * scale[j];
    const std::optional<Matrix> inverse = inverse_positive_definite(a);
    ASSERT_TRUE(inverse.has_value());
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) EXPECT_EQ((*inverse)(i, j), (*inverse)(j, i));
    // [[4, 2], [2, 5]]^-1 = [[5, -2], [-2, 4]] / 16, here without the third row and column.
    Matrix two(2, 2);
    two(0, 0) = 4;
    two(0, 1) = two(1, 0) = 2;
    two(1, 1) = 5;
    const std::optional<Matrix> two_inverse = inverse_positive_definite(two);
    ASSERT_TRUE(two_inverse.has_value());
    EXPECT_NEAR((*two_inverse)(0, 0), 5.0 / 16.0, 1e-15);
    EXPECT_NEAR((*two_inverse)(0, 1), -2.0 / 16.0, 1e-15);
    EXPECT_NEAR((*two_inverse)(1, 1), 4.0 / 16.0, 1e-15);
}

// Refused: not positive definite (a negative diagonal, an indefinite matrix), singular to
// working precision (a pivot below 1e-10 of its diagonal entry), not a number.
TEST(LinearAlgebra, RefusesWhatIsNotSafelyPositiveDefinite) {
    const auto matrix = [](double a00, double a01, double a11) {
        Matrix m(2, 2);
        m(0, 0) = a00;
        m(0, 1) = m(1, 0) = a01;
        m(1, 1) = a11;
        return m;
    };
    EXPECT_FALSE(inverse_positive_definite(matrix(-1, 0, 1)).has_value());
    EXPECT_FALSE(inverse_positive_definite(matrix(1, 0, 0)).has_value());
    EXPECT_FALSE(inverse_positive_definite(matrix(1, 2, 1)).has_value());  // eigenvalues 3, -1
    // Pivot 1 - 1 / (1 + 1e-12) ~ 1e-12: singular to working precision; 1e-8 is not.
    EXPECT_FALSE(inverse_positive_definite(matrix(1 + 1e-12, 1, 1)).has_value());
    EXPECT_TRUE(inverse_positive_definite(matrix(1 + 1e-8, 1, 1)).has_value());
    EXPECT_FALSE(inverse_positive_definite(matrix(std::nan(""), 0, 1)).has_value());
    EXPECT_FALSE(inverse_positive_definite(matrix(1, std::nan(""), 1)).has_value());
}

}  // namespace
}  // namespace monoplane::analysis
