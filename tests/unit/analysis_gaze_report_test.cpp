// The report's gaze section (issue 45, part 4): a gaze sample projected into the seat's left eye,
// the smoothed density, the section's table, regression, HTML and summary.json on hand-built
// data, and the density figure's SVG. Expected values are worked out by hand in the comments.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/gaze_density.h"
#include "analysis/gaze_projection.h"
#include "analysis/report/gaze_figure.h"
#include "analysis/report/report.h"

namespace monoplane::analysis {
namespace {

// A frustum of 90 degrees each way (tangents -1 .. 1) and the Vive's IPD: u = (tan_x + 1) / 2,
// v = (1 - tan_y) / 2.
SeatEye square_eye() {
    SeatEye eye;
    eye.ipd = 0.064;
    eye.tan_left = eye.tan_down = -1.0;
    eye.tan_right = eye.tan_up = 1.0;
    return eye;
}

GazeSampleRow sample(std::array<double, 3> direction, std::optional<double> depth,
                     std::array<double, 7> head = {0, 0, 0, 1, 0, 0, 0},
                     const std::string& scene = "beams") {
    GazeSampleRow s;
    s.participant = "P1";
    s.scene = scene;
    s.mono_plane = 3.0;
    s.head = head;
    s.direction = direction;
    s.depth_m = depth;
    return s;
}

TEST(GazeProjection, StraightAheadAtInfinityIsTheEyesCentreDirection) {
    const std::optional<EyeImagePoint> p =
        project_into_left_eye(sample({0, 0, -1}, {}), square_eye());
    ASSERT_TRUE(p.has_value());
    EXPECT_DOUBLE_EQ(p->tan_x, 0.0);
    EXPECT_DOUBLE_EQ(p->tan_y, 0.0);
    EXPECT_DOUBLE_EQ(p->u, 0.5);
    EXPECT_DOUBLE_EQ(p->v, 0.5);
}

// The point (0, 0, -z) seen from the left eye at (-ipd/2, 0, 0): tan_x = (ipd/2) / z.
TEST(GazeProjection, StraightAheadAtDepthLiesRightOfTheLeftEyesAxis) {
    const std::optional<EyeImagePoint> p =
        project_into_left_eye(sample({0, 0, -1}, 4.0), square_eye());
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->tan_x, 0.032 / 4.0, 1e-12);
    EXPECT_NEAR(p->tan_y, 0.0, 1e-12);
    EXPECT_NEAR(p->u, (0.008 + 1.0) / 2.0, 1e-12);

    // The Vive's left eye: u = (0.008 + 1.391937) / (1.247409 + 1.391937),
    // v = 1.464287 / (1.464287 + 1.468819).
    const std::optional<EyeImagePoint> vive = project_into_left_eye(sample({0, 0, -1}, 4.0), {});
    ASSERT_TRUE(vive.has_value());
    EXPECT_NEAR(vive->u, 1.399937 / 2.639346, 1e-12);
    EXPECT_NEAR(vive->v, 1.464287 / 2.933106, 1e-12);
}

// An oblique gaze: depth 4 m along -z is reached after 4 / 0.8 = 5 m along (0.6, 0, -0.8), at
// (3, 0, -4); from the left eye (3.032, 0, -4): tan_x = 0.758.
TEST(GazeProjection, AnObliqueGazeMeetsItsDepthAlongTheRay) {
    const std::optional<EyeImagePoint> p =
        project_into_left_eye(sample({0.6, 0, -0.8}, 4.0), square_eye());
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->tan_x, 0.758, 1e-12);
    EXPECT_NEAR(p->tan_y, 0.0, 1e-12);
}

// The head 0.1 m right of and 0.05 m above the seat, looking ahead at 2 m: the point
// (0.1, 0.05, -2), from the eye (0.132, 0.05, -2): tan (0.066, 0.025), u 0.533, v 0.4875.
TEST(GazeProjection, TheHeadsOffsetFromTheSeatMovesThePoint) {
    const std::optional<EyeImagePoint> p =
        project_into_left_eye(sample({0, 0, -1}, 2.0, {0.1, 0.05, 0, 1, 0, 0, 0}), square_eye());
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->tan_x, 0.066, 1e-12);
    EXPECT_NEAR(p->tan_y, 0.025, 1e-12);
    EXPECT_NEAR(p->u, 0.533, 1e-12);
    EXPECT_NEAR(p->v, 0.4875, 1e-12);
}

// The head turned 30 degrees to the left (about +y: quaternion cos 15, 0, sin 15, 0): its -z is
// (-sin 30, 0, -cos 30) in the seat's frame; at infinity tan_x = -tan 30 = -0.57735, which the
// Vive's left eye shows at u = (-0.57735 + 1.391937) / 2.639346 = 0.308632.
TEST(GazeProjection, TheHeadsTurnRotatesTheGaze) {
    const std::array<double, 7> turned{0, 0, 0, 0.9659258262890683, 0, 0.25881904510252074, 0};
    const std::optional<EyeImagePoint> p =
        project_into_left_eye(sample({0, 0, -1}, {}, turned), {});
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->tan_x, -std::tan(30.0 * M_PI / 180.0), 1e-9);
    EXPECT_NEAR(p->u, 0.30863203642507436, 1e-9);
    // Turned 90 degrees the point at 2 m lies beside the eye, on its image plane: not shown.
    const std::array<double, 7> aside{0, 0, 0, std::sqrt(0.5), 0, std::sqrt(0.5), 0};
    EXPECT_FALSE(project_into_left_eye(sample({0, 0, -1}, 2.0, aside), square_eye()).has_value());
    EXPECT_FALSE(project_into_left_eye(sample({0, 0, 1}, {}), square_eye()).has_value());
}

// An eye canted 10 degrees to the left sees straight ahead right of its axis: tan_x = tan 10.
TEST(GazeProjection, ACantedEyeSeesStraightAheadOffItsAxis) {
    SeatEye eye = square_eye();
    eye.cant = 10.0 * M_PI / 180.0;
    const std::optional<EyeImagePoint> p = project_into_left_eye(sample({0, 0, -1}, {}), eye);
    ASSERT_TRUE(p.has_value());
    EXPECT_NEAR(p->tan_x, std::tan(eye.cant), 1e-12);
}

// One sample straight ahead at 4 m: u = 0.504, v = 0.5, so bin (floor(0.504 * 64),
// floor(0.5 * 72)) = (32, 36). The blur spreads it by the Gaussian (sigma 1.5 bins, 11 taps):
// the centre tap is 1 / sum(exp(-i^2 / 4.5), i = -5..5) = 0.266011724861794 (python3), so the
// peak is its square and the neighbours in a row are centre x next tap (0.213005537711254).
// A sample far right of the view (tan_x 2) counts as a sample, not inside.
TEST(GazeDensity, OneSampleMakesOneBlurredPeakWhereItLanded) {
    const std::vector<GazeSampleRow> samples{
        sample({0, 0, -1}, 4.0), sample({0.8944271909999159, 0, -0.4472135954999579}, {}),
        sample({0, 0, -1}, 4.0, {0, 0, 0, 1, 0, 0, 0}, "spheres")};
    const GazeDensity d = gaze_density(samples, "beams", square_eye());
    EXPECT_EQ(d.columns, 64);
    EXPECT_EQ(d.rows, 72);
    EXPECT_EQ(d.samples, 2);
    EXPECT_EQ(d.inside, 1);
    EXPECT_NEAR(d.at(32, 36), 0.07076223776394698, 1e-12);
    EXPECT_NEAR(d.peak(), 0.07076223776394698, 1e-12);
    EXPECT_EQ(d.peak_bin(), std::make_pair(32, 36));
    EXPECT_NEAR(d.at(31, 36), 0.05666197049168458, 1e-12);
    EXPECT_NEAR(d.at(32, 37), 0.05666197049168458, 1e-12);
    double total = 0.0;
    for (double share : d.share) total += share;
    EXPECT_NEAR(total, 1.0, 1e-12);  // far from the edges nothing is lost
    EXPECT_EQ(d.at(0, 0), 0.0);
}

}  // namespace

namespace report {
namespace {

TrialRow trial(const std::string& participant, const std::string& scene,
               std::optional<double> error, std::optional<double> share, bool chose_test) {
    TrialRow t;
    t.source = "hand";
    t.participant = participant;
    t.scene = scene;
    t.mono_plane = 3.0;
    t.decided = t.valid = true;
    t.label1_mode = "stereo";
    t.label2_mode = "hybrid";
    t.chosen_mode = chose_test ? "hybrid" : "stereo";
    t.gaze_error_test_arcmin = error;
    t.gaze_share_beyond_m = share;
    return t;
}

// BEAMS: errors 2 and 4 (mean 3), shares 0.5 and 1 (mean 0.75), one trial without gaze;
// SPHERES: error 6, share 0.25. All: errors 2, 4, 6 (mean 4), shares 0.5, 1, 0.25 (7/12).
Dataset hand_built() {
    Dataset data;
    data.trials = {trial("A", "beams", 2.0, 0.5, true), trial("A", "beams", 4.0, 1.0, false),
                   trial("B", "beams", {}, {}, true), trial("B", "spheres", 6.0, 0.25, false)};
    data.trials.push_back(trial("B", "spheres", 1.0, 0.0, true));
    data.trials.back().practice = true;  // not analysed
    derive_session_fields(data.trials);
    data.gaze_samples = {GazeSampleRow{.participant = "A", .scene = "beams"},
                         GazeSampleRow{.participant = "A", .scene = "beams"},
                         GazeSampleRow{.participant = "B", .scene = "spheres"}};
    return data;
}

TEST(GazeSection, TheTablePerSceneAveragesTheTrialsThatHaveGaze) {
    const AnalysisResults r = analyse(hand_built());
    const GazeResults& g = r.gaze;
    ASSERT_TRUE(g.recorded);
    ASSERT_EQ(g.by_scene.size(), 3u);
    EXPECT_EQ(g.by_scene[0].scene, "beams");
    EXPECT_EQ(g.by_scene[0].trials, 3);
    EXPECT_EQ(g.by_scene[0].trials_with_gaze, 2);
    EXPECT_EQ(g.by_scene[0].samples, 2);
    EXPECT_DOUBLE_EQ(*g.by_scene[0].error_test_arcmin, 3.0);
    EXPECT_DOUBLE_EQ(*g.by_scene[0].share_beyond_m, 0.75);
    EXPECT_EQ(g.by_scene[1].scene, "spheres");
    EXPECT_EQ(g.by_scene[1].trials, 1);
    EXPECT_EQ(g.by_scene[1].samples, 1);
    EXPECT_DOUBLE_EQ(*g.by_scene[1].error_test_arcmin, 6.0);
    EXPECT_EQ(g.by_scene[2].scene, "");
    EXPECT_EQ(g.by_scene[2].trials_with_gaze, 3);
    EXPECT_EQ(g.by_scene[2].samples, 3);
    EXPECT_DOUBLE_EQ(*g.by_scene[2].error_test_arcmin, 4.0);
    EXPECT_DOUBLE_EQ(*g.by_scene[2].share_beyond_m, 7.0 / 12.0);
    // Three trials with an error at gaze for three coefficients (intercept, error, SPHERES): the
    // section says why there is no fit.
    EXPECT_FALSE(g.fit.has_value());
    EXPECT_EQ(g.fit_error,
              "logistic regression: 3 analysable trials with a gaze error are too few for 3 "
              "coefficients");
    ASSERT_EQ(g.densities.size(), 2u);

    const std::vector<Figure> figures = report_figures(r);
    const std::string html = report_html(r, figures);
    EXPECT_NE(html.find("<h2 id=\"gaze\">Where participants looked</h2>"), std::string::npos);
    EXPECT_NE(html.find("<td class=\"num\">3.00</td>"), std::string::npos);  // BEAMS' error
    EXPECT_NE(html.find("<td class=\"num\">75.0&nbsp;%</td>"), std::string::npos);
    EXPECT_NE(html.find("<b>Not estimable</b> on these data: logistic regression: 3 analysable"),
              std::string::npos);
    EXPECT_NE(html.find("id=\"figure-gaze_density_beams\""), std::string::npos);
    EXPECT_NE(html.find("id=\"figure-gaze_density_spheres\""), std::string::npos);

    const std::string json = summary_json(r);
    EXPECT_NE(json.find("\"gaze\": {\n    \"recorded\": true,\n    \"trials_with_gaze\": 3,\n"
                        "    \"samples\": 3,"),
              std::string::npos)
        << json;
    EXPECT_NE(json.find("\"share_beyond_m\": 0.75"), std::string::npos);
    EXPECT_NE(json.find("\"estimable\": false"), std::string::npos);
}

TEST(GazeSection, AbsentWithoutGaze) {
    Dataset data = hand_built();
    for (TrialRow& t : data.trials) t.gaze_error_test_arcmin = t.gaze_share_beyond_m = {};
    data.gaze_samples.clear();
    const AnalysisResults r = analyse(data);
    EXPECT_FALSE(r.gaze.recorded);
    const std::vector<Figure> figures = report_figures(r);
    for (const Figure& f : figures) EXPECT_EQ(f.name.find("gaze"), std::string::npos) << f.name;
    const std::string html = report_html(r, figures);
    EXPECT_EQ(html.find("id=\"gaze\""), std::string::npos);
    EXPECT_EQ(html.find("#gaze"), std::string::npos);
    EXPECT_NE(summary_json(r).find("\"gaze\": {\n    \"recorded\": false\n  }"), std::string::npos);
}

// The rule of tests/fixtures/analysis/make_gaze_reference.py (12 participants x 20 trials, two
// scenes): the section's regression has scene terms as the distance model, and matches
// statsmodels' fit with scene terms (b = 0.27982326693887705, CR1 se = 0.07954689376870931).
TEST(GazeSection, TheRegressionMatchesStatsmodels) {
    Dataset data;
    for (int p = 0; p < 12; ++p)
        for (int t = 0; t < 20; ++t) {
            const double error = 0.25 * ((3 * p + 7 * t) % 13) + 0.1 * (p % 4);
            const int threshold = 2 + (error > 1.5) + (error > 2.5) + (p % 3 == 0);
            TrialRow row = trial("P" + std::to_string(p), t < 10 ? "beams" : "spheres", error, 0.5,
                                 (5 * p + 3 * t) % 7 < threshold);
            row.mono_plane = t % 2 == 0 ? 3.0 : 8.0;
            row.valid = !(p == 2 && t == 0);
            if (t == 19 && p % 4 == 1) row.gaze_error_test_arcmin.reset();
            data.trials.push_back(row);
        }
    derive_session_fields(data.trials);
    const AnalysisResults r = analyse(data);
    ASSERT_TRUE(r.gaze.fit.has_value()) << r.gaze.fit_error;
    const LogisticFit& f = *r.gaze.fit;
    EXPECT_EQ(f.n, 236);
    EXPECT_EQ(f.clusters, 12);
    EXPECT_EQ(f.skipped_without_predictor, 3);
    ASSERT_EQ(f.coefficients.size(), 3u);
    EXPECT_NEAR(f.coefficients[1].estimate, 0.27982326693887705, 1e-6);
    EXPECT_NEAR(f.coefficients[1].std_error, 0.07954689376870931, 1e-6);
    EXPECT_NEAR(f.coefficients[1].odds_ratio, std::exp(0.27982326693887705), 1e-6);
    const std::string html = report_html(r, report_figures(r));
    EXPECT_NE(html.find("multiplied the odds of choosing hybrid by 1.323"), std::string::npos);
    EXPECT_NE(html.find("3 analysed trial(s) without an error at gaze left out"),
              std::string::npos);
    const std::string json = summary_json(r);
    EXPECT_NE(json.find("\"skipped_without_gaze\": 3"), std::string::npos);
    EXPECT_NE(json.find("\"name\": \"gaze_error_test_arcmin\""), std::string::npos);
}

TEST(GazeFigure, DrawsTheDensityOverThePictureOrAlone) {
    GazeDensity d;
    d.scene = "beams";
    d.columns = 2;
    d.rows = 1;
    d.share = {0.0, 0.5};
    d.samples = 3;
    d.inside = 2;
    const std::string alone = gaze_density_svg(d, SeatEye{}, std::nullopt);
    EXPECT_NE(alone.find("no picture of the scene"), std::string::npos);
    EXPECT_EQ(alone.find("<image"), std::string::npos);
    // Only the right bin is drawn, at the peak's colour and opacity 0.25 + 0.5.
    EXPECT_NE(alone.find("<rect x=\"270\" y=\"58\""), std::string::npos) << alone;
    EXPECT_NE(alone.find("fill=\"#fcffa4\" fill-opacity=\"0.75\""), std::string::npos);
    EXPECT_EQ(alone.find("<rect x=\"0\" y=\"58\" width=\"270"), std::string::npos);
    EXPECT_NE(alone.find("2 of 3 samples inside the view"), std::string::npos);

    const std::string over = gaze_density_svg(d, SeatEye{}, SceneImage{"Man", 4, 2});
    // 540 wide at the picture's 2:1 aspect: 270 high.
    EXPECT_NE(over.find("<image x=\"0\" y=\"58\" width=\"540\" height=\"270\""), std::string::npos)
        << over;
    EXPECT_NE(over.find("href=\"data:image/png;base64,TWFu\""), std::string::npos);
}

TEST(GazeFigure, Base64AndColoursAsSpecified) {
    // RFC 4648 section 10's test vectors.
    EXPECT_EQ(base64(""), "");
    EXPECT_EQ(base64("f"), "Zg==");
    EXPECT_EQ(base64("fo"), "Zm8=");
    EXPECT_EQ(base64("foo"), "Zm9v");
    EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
    EXPECT_EQ(heat_color(0.0), "#000004");
    EXPECT_EQ(heat_color(1.0), "#fcffa4");
    EXPECT_EQ(heat_color(0.2), "#420a68");  // the second of six evenly spaced stops
}

}  // namespace
}  // namespace report
}  // namespace monoplane::analysis
