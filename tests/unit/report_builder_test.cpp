// The analysis report on a small hand-made dataset whose counts are worked out below: two
// sources, five sessions (session ids repeat across sources), practice, undecided and invalid
// trials, questionnaire answers. Checks what the report shows (counts, inline SVG, no external
// reference) and summary.json's values by string search on its one-key-per-line layout.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/report/power.h"
#include "analysis/report/psychometric_section.h"
#include "analysis/report/report.h"
#include "analysis/report/text_output.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {
namespace {

TrialRow trial(const std::string& source, std::int64_t session, const std::string& participant,
               int index, const std::string& scene, double m, bool chose_hybrid) {
    TrialRow t;
    t.source = source;
    t.session_id = session;
    t.participant = participant;
    t.protocol = "test";
    t.trial_index = index;
    t.block = scene == "beams" ? 0 : 1;
    t.scene = scene;
    t.mono_plane = m;
    t.label1_mode = index % 2 == 0 ? "stereo" : "hybrid";
    t.label2_mode = index % 2 == 0 ? "hybrid" : "stereo";
    t.decided = true;
    t.valid = true;
    t.chosen_mode = chose_hybrid ? "hybrid" : "stereo";
    t.switches = 1 + index % 3;
    t.decision_time_s = 2.0 + index;
    return t;
}

// Per participant: beams at 3 and 8 m, spheres at 3 and 8 m; 1 = hybrid chosen.
//   P1: 0 1 1 0   P2: 0 0 1 1   P3: 1 1 0 1   P4: 0 1 0 0
// hybrid: 8 of 16; beams 4 of 8, spheres 4 of 8; 3 m: 3 of 8, 8 m: 5 of 8.
Dataset make_dataset() {
    const int choices[4][4] = {{0, 1, 1, 0}, {0, 0, 1, 1}, {1, 1, 0, 1}, {0, 1, 0, 0}};
    Dataset d;
    d.sources = {"site-a.sqlite", "site-b.csv"};
    for (int p = 0; p < 4; ++p) {
        const std::string source = p < 3 ? "site-a.sqlite" : "site-b.csv";
        const std::int64_t session = p < 3 ? p + 1 : 1;
        const std::string code = "P" + std::to_string(p + 1);
        TrialRow practice = trial(source, session, code, 0, "spheres", 5, true);
        practice.practice = true;
        practice.block = -1;
        d.trials.push_back(practice);
        int i = 1;
        for (const char* scene : {"beams", "spheres"}) {
            for (double m : {3.0, 8.0}) {
                d.trials.push_back(
                    trial(source, session, code, i, scene, m, choices[p][i - 1] == 1));
                ++i;
            }
        }
    }
    // P5 (site b, session 2): one undecided, one invalid trial: nothing to analyse.
    TrialRow undecided = trial("site-b.csv", 2, "P5", 0, "beams", 3, false);
    undecided.decided = false;
    undecided.valid = false;
    undecided.chosen_mode = "";
    d.trials.push_back(undecided);
    TrialRow invalid = trial("site-b.csv", 2, "P5", 1, "beams", 8, true);
    invalid.valid = false;
    d.trials.push_back(invalid);
    for (auto& t : d.trials) t.reference_mode = "stereo";
    derive_session_fields(d.trials);
    for (int p = 0; p < 3; ++p) {
        for (int item = 0; item < 2; ++item) {
            d.answers.push_back({"site-a.sqlite", p + 1, "P" + std::to_string(p + 1), item,
                                 item == 0 ? "I noticed differences" : "Comfortable", 2 + p + item,
                                 7});
        }
    }
    return d;
}

// analyse() with a short bootstrap: the tests below are about counts, tables and files, not the
// group threshold's interval (PsychometricFitsInJsonCsvAndHtml and analysis_psychometric_test
// are), and 1000 refits per scene take seconds under the sanitizers.
AnalysisResults analyse_quickly(const Dataset& data) {
    ReportOptions options;
    options.psychometric.bootstrap_replicates = 20;
    return analyse(data, options);
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST(ReportBuilder, CountsSourcesAndExclusions) {
    const AnalysisResults r = analyse_quickly(make_dataset());
    ASSERT_EQ(r.sources.size(), 2u);
    EXPECT_EQ(r.sources[0].source, "site-a.sqlite");
    EXPECT_EQ(r.sources[0].sessions, 3);
    EXPECT_EQ(r.sources[0].trials, 15);
    EXPECT_EQ(r.sources[0].answers, 6);
    EXPECT_EQ(r.sources[1].sessions, 2);  // session 1 of site b is not session 1 of site a
    EXPECT_EQ(r.sources[1].trials, 7);
    EXPECT_EQ(r.sources[1].analysed, 4);
    EXPECT_EQ(r.sessions, 5);
    EXPECT_EQ(r.participants, 5);
    EXPECT_EQ(r.trials, 22);
    EXPECT_EQ(r.data_trials, 18);
    EXPECT_EQ(r.exclusions.practice, 4);
    EXPECT_EQ(r.exclusions.undecided, 1);
    EXPECT_EQ(r.exclusions.invalid, 1);
    EXPECT_EQ(r.exclusions.kept, 16);
    EXPECT_EQ(r.reference_mode, "stereo");
    EXPECT_EQ(r.test_mode, "hybrid");
    EXPECT_EQ(r.overall.test_chosen, 8);
    EXPECT_EQ(r.overall.n, 16);
    ASSERT_EQ(r.by_distance.size(), 2u);
    EXPECT_EQ(r.by_distance[0].test_chosen, 3);
    EXPECT_EQ(r.by_distance[1].test_chosen, 5);
    EXPECT_EQ(r.by_scene_distance.size(), 4u);
    ASSERT_TRUE(r.chi_square.test.has_value()) << r.chi_square.error;
    EXPECT_EQ(r.chi_square.test->n, 16);
    EXPECT_EQ(r.chi_square_by_scene.size(), 2u);
    ASSERT_TRUE(r.logistic.has_value()) << r.logistic_error;
    EXPECT_EQ(r.logistic->clusters, 4);
    EXPECT_EQ(r.logistic->n, 16);
    EXPECT_EQ(r.by_first_scene.size(), 1u);  // every session begins with beams
    EXPECT_EQ(r.by_first_scene[0].sessions, 4);
    ASSERT_EQ(r.questionnaire.size(), 2u);
    EXPECT_EQ(r.questionnaire[0].summary.n, 3);
}

TEST(ReportBuilder, HtmlIsSelfContainedWithFiguresAndCounts) {
    const AnalysisResults r = analyse_quickly(make_dataset());
    const std::vector<Figure> figures = report_figures(r);
    // Choices, decision times, switches, and the psychometric functions of both scenes.
    ASSERT_EQ(figures.size(), 5u);
    EXPECT_EQ(figures[3].name, "psychometric_beams");
    EXPECT_EQ(figures[4].name, "psychometric_spheres");
    const std::string html = report_html(r, figures);
    EXPECT_TRUE(contains(html, "<!DOCTYPE html>"));
    // Five inline figures, none pointing anywhere.
    std::size_t svgs = 0;
    for (std::size_t at = html.find("<svg"); at != std::string::npos;
         at = html.find("<svg", at + 1)) {
        ++svgs;
    }
    EXPECT_EQ(svgs, 5u);
    EXPECT_FALSE(contains(html, "http://"));
    EXPECT_FALSE(contains(html, "https://"));
    EXPECT_FALSE(contains(html, "<link"));
    EXPECT_FALSE(contains(html, "<script"));
    EXPECT_FALSE(contains(html, "src="));
    // The counts: all trials, practice, undecided, invalid, analysed.
    EXPECT_TRUE(contains(html, "<td>all trials merged</td><td class=\"num\">22</td>"));
    EXPECT_TRUE(contains(html, "<td>excluded: practice</td><td class=\"num\">4</td>"));
    EXPECT_TRUE(contains(html, "<td class=\"num\"><b>16</b></td>"));
    EXPECT_TRUE(contains(html, "<code>site-b.csv</code>"));
    EXPECT_TRUE(contains(html, "Of 16 valid decisions, 8 (50.00&nbsp;%"));
    // The regression, its reason and the distance term, CR2 first and CR1 for comparison; the
    // chi-square with phi and V.
    EXPECT_TRUE(contains(html, "repeated measures"));
    EXPECT_LT(html.find("<th class=\"num\">CR2 SE</th>"), html.find("For comparison: CR1"));
    EXPECT_TRUE(contains(html, "<th class=\"num\">CR1 SE</th>"));
    EXPECT_TRUE(contains(html, "<code>mono_plane_m</code>"));
    EXPECT_TRUE(contains(html, "Cram&eacute;r's V"));
    EXPECT_TRUE(contains(html, "I noticed differences"));
    EXPECT_TRUE(contains(html, "50 %"));  // the chance line of the choices figure
}

TEST(ReportBuilder, SummaryJsonHasTheValues) {
    const std::string json = summary_json(analyse_quickly(make_dataset()));
    for (const char* expected : {"\"schema_version\": 1",
                                 "\"total\": 22",
                                 "\"data\": 18",
                                 "\"practice\": 4",
                                 "\"undecided\": 1",
                                 "\"invalid\": 1",
                                 "\"analysed\": 16",
                                 "\"sessions\": 5",
                                 "\"participants\": 5",
                                 "\"analysed_participants\": 4",
                                 "\"reference_mode\": \"stereo\"",
                                 "\"test_mode\": \"hybrid\"",
                                 "\"estimable\": true",
                                 "\"clusters\": 4",
                                 "\"distance_term\": \"mono_plane_m\"",
                                 "\"small_sample_method\": \"CR2 with Satterthwaite t\"",
                                 "\"std_error_cr2\": ",
                                 "\"df_cr2\": ",
                                 "\"p_cr2\": ",
                                 "\"source\": \"site-b.csv\"",
                                 "\"first_scene\": \"beams\"",
                                 "\"mono_plane\": 8",
                                 "\"decision_time_s\": [",
                                 "\"questionnaire\": ["}) {
        EXPECT_TRUE(contains(json, expected)) << expected << "\n" << json;
    }
    // overall: 8 of 16, rate 0.5, binomial p 1.
    const auto overall = json.find("\"overall\": {");
    ASSERT_NE(overall, std::string::npos);
    const std::string block = json.substr(overall, json.find('}', overall) - overall);
    EXPECT_TRUE(contains(block, "\"test_chosen\": 8")) << block;
    EXPECT_TRUE(contains(block, "\"n\": 16")) << block;
    EXPECT_TRUE(contains(block, "\"rate\": 0.5")) << block;
    EXPECT_TRUE(contains(block, "\"binomial_p\": 1")) << block;
    // Balanced braces and brackets, no NaN.
    int depth = 0;
    for (char c : json) depth += (c == '{' || c == '[') ? 1 : (c == '}' || c == ']') ? -1 : 0;
    EXPECT_EQ(depth, 0);
    EXPECT_FALSE(contains(json, "nan"));
}

// make_dataset() with what a study day adds: each participant's session (P1 with a second one),
// variables and notes whose text would be markup if it were not escaped; participant numbers that
// fill the 2-row Latin square of its two scenes unevenly (4 and 1).
Dataset study_day_dataset() {
    Dataset d = make_dataset();
    const std::string hostile = "<script>alert('x')</script> & \"quoted\"";
    for (int p = 1; p <= 5; ++p) {
        SessionRow s;
        s.source = p < 4 ? "site-a.sqlite" : "site-b.csv";
        s.session_id = p < 4 ? p : p - 3;
        s.participant = "P" + std::to_string(p);
        s.participant_number = p == 5 ? 1 : 0;
        s.first_scene_order = "latin-square";
        s.scenes = 2;
        s.latin_square_rows = 2;
        s.variables = {{"age", std::to_string(20 + p)}};
        if (p == 1) s.variables.emplace_back("remark", hostile);
        d.sessions.push_back(s);
    }
    d.sessions[0].notes.push_back({"2026-03-01T10:00:00Z", 3, "window", hostile});
    SessionRow second = d.sessions[0];
    second.session_id = 7;
    second.session_number = 2;
    second.participant_number = 1;  // a later session does not move P1's row
    second.notes = {{"2026-03-02T09:00:00Z", std::nullopt, "command", "headset\nadjusted"}};
    d.sessions.push_back(second);
    return d;
}

TEST(ReportBuilder, StudyDayParticipantsNotesAndCounterbalancing) {
    const AnalysisResults r = analyse_quickly(study_day_dataset());
    const std::string html = report_html(r, report_figures(r));
    // Escaped wherever the text appears: in the variables table and in the notes.
    EXPECT_FALSE(contains(html, "<script"));
    EXPECT_TRUE(contains(html,
                         "<td>&lt;script&gt;alert(&apos;x&apos;)&lt;/script&gt; &amp; "
                         "&quot;quoted&quot;</td>"))
        << html;
    std::size_t escaped = 0;
    for (std::size_t at = html.find("&lt;script&gt;"); at != std::string::npos;
         at = html.find("&lt;script&gt;", at + 1))
        ++escaped;
    EXPECT_EQ(escaped, 2u);  // the variable and the note
    // The participants table: P1's sessions 1 and 2, participant number and row from 1.
    EXPECT_TRUE(contains(html, "<th><code>age</code></th><th><code>remark</code></th>"));
    EXPECT_TRUE(contains(html, "<td>P1</td><td class=\"num\">1, 2</td>")) << html;
    EXPECT_TRUE(contains(html,
                         "<td>P5</td><td class=\"num\">1</td><td><code>site-b.csv</code>"
                         "</td><td class=\"num\">2</td><td class=\"num\">2</td>"));
    // Notes: time, trial, who; a note's line break kept.
    EXPECT_TRUE(contains(html,
                         "<td>2026-03-01T10:00:00Z</td><td class=\"num\">3</td>"
                         "<td>window</td>"));
    EXPECT_TRUE(contains(html, "headset<br>adjusted"));
    // Counterbalancing: rows 1 and 2 with 4 and 1 participants, and the warning.
    EXPECT_TRUE(contains(html, "id=\"counterbalancing\""));
    EXPECT_TRUE(contains(html, "<td class=\"num\">1</td><td class=\"num\">4</td>"));
    EXPECT_TRUE(contains(html, "differ by more than one"));

    const std::string json = summary_json(r);
    const auto at = json.find("\"counterbalancing\": {");
    ASSERT_NE(at, std::string::npos) << json;
    const std::string block = json.substr(at, json.find("\"applicable\"", at) - at);
    EXPECT_TRUE(contains(block, "\"rows\": {\n      \"1\": 4,\n      \"2\": 1\n    }")) << block;
    EXPECT_TRUE(contains(block, "\"balanced\": false")) << block;
    EXPECT_TRUE(contains(json, "\"rule\": \"refuse\""));
    EXPECT_TRUE(contains(json, "\"remark\": \"<script>alert('x')</script> & \\\"quoted\\\"\""))
        << json;  // JSON keeps the text as typed
    EXPECT_TRUE(contains(json, "\"written_by\": \"command\""));
    EXPECT_TRUE(contains(json, "\"text\": \"headset\\nadjusted\""));
}

TEST(ReportBuilder, CounterbalancingWhenBalancedAndWhenNotApplicable) {
    Dataset d = study_day_dataset();
    d.sessions[4].participant_number = 1;
    d.sessions[3].participant_number = 1;  // rows 3 and 2
    AnalysisResults r = analyse_quickly(d);
    EXPECT_TRUE(r.day.counterbalancing.balanced);
    std::string html = report_html(r, report_figures(r));
    EXPECT_FALSE(contains(html, "differ by more than one"));
    EXPECT_TRUE(contains(summary_json(r), "\"balanced\": true"));

    for (SessionRow& s : d.sessions) s.first_scene_order = "random";
    r = analyse_quickly(d);
    html = report_html(r, report_figures(r));
    EXPECT_TRUE(contains(html, "Not applicable: the protocol orders the scenes at random"));
    const std::string json = summary_json(r);
    EXPECT_TRUE(contains(json, "\"balanced\": null"));
    EXPECT_TRUE(contains(json, "\"applicable\": false"));

    r = analyse_quickly(make_dataset());  // no session information: no participants table
    html = report_html(r, report_figures(r));
    EXPECT_FALSE(contains(html, "id=\"participants\""));
    EXPECT_TRUE(contains(html, "No session has notes."));
}

TEST(ReportBuilder, RegressionNotEstimableStillGivesAReport) {
    Dataset d = make_dataset();
    std::vector<TrialRow> one;
    for (const TrialRow& t : d.trials) {
        if (t.participant == "P1") one.push_back(t);
    }
    d.trials = one;
    const AnalysisResults r = analyse_quickly(d);
    EXPECT_FALSE(r.logistic.has_value());
    EXPECT_FALSE(r.logistic_error.empty());
    const std::string html = report_html(r, report_figures(r));
    EXPECT_TRUE(contains(html, "Not estimable"));
    const std::string json = summary_json(r);
    EXPECT_TRUE(contains(json, "\"estimable\": false"));
    EXPECT_TRUE(contains(json, "\"error\": "));
    EXPECT_EQ(logistic_csv(r),
              "term,estimate,std_error,z,p,odds_ratio,ci_lower,ci_upper,n,"
              "clusters,converged,std_error_cr2,t_cr2,df_cr2,p_cr2,ci_lower_cr2,ci_upper_cr2\n");
}

TEST(ReportBuilder, EmptyDatasetGivesAReport) {
    const AnalysisResults r = analyse(Dataset{});
    const std::string html = report_html(r, report_figures(r));
    EXPECT_TRUE(contains(html, "No valid decisions"));
    EXPECT_TRUE(contains(html, "no data"));
}

TEST(ReportBuilder, CsvTables) {
    const AnalysisResults r = analyse_quickly(make_dataset());
    const std::string scenes = rates_csv(r.by_scene);
    EXPECT_EQ(scenes.substr(0, scenes.find('\n')),
              "scene,mono_plane,test_chosen,n,rate,wilson_lower,wilson_upper,cp_lower,cp_upper,"
              "binomial_p");
    EXPECT_TRUE(contains(scenes, "\nbeams,,4,8,0.5,"));
    const std::string distances = rates_csv(r.by_distance);
    EXPECT_TRUE(contains(distances, "\n,3,3,8,0.375,"));
    EXPECT_TRUE(contains(distances, "\n,8,5,8,0.625,"));
    const std::string logistic = logistic_csv(r);
    EXPECT_TRUE(contains(logistic, "\nintercept,"));
    EXPECT_TRUE(contains(logistic, "\nscene[spheres],"));
    // The distance row: CR1 columns where they always were, the CR2 columns appended.
    ASSERT_TRUE(r.logistic.has_value());
    const Coefficient& m = r.logistic->coefficients[1];
    EXPECT_TRUE(contains(logistic, "\nmono_plane_m," + number_text(m.estimate) + "," +
                                       number_text(m.std_error) + ","));
    EXPECT_TRUE(contains(logistic, ",16,4,TRUE," + number_text(m.std_error_cr2) + "," +
                                       number_text(m.t_cr2) + "," + number_text(m.df_cr2) + "," +
                                       number_text(m.p_cr2) + ","))
        << logistic;
    const std::string items = questionnaire_csv(r.questionnaire);
    EXPECT_TRUE(contains(items, "count_7\n"));
    // P1..P3 answered 2, 3, 4 to item 0.
    EXPECT_TRUE(contains(items, "\n0,I noticed differences,7,3,3,1,3,2.5,3.5,2,4,0,1,1,1,0,0,0\n"))
        << items;
}

TEST(ReportBuilder, WritesEveryFile) {
    const auto dir = std::filesystem::temp_directory_path() / "monoplane_report_builder_test";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const AnalysisResults r = analyse_quickly(make_dataset());
    const auto written = write_report(r, report_figures(r), dir);
    ASSERT_TRUE(written) << written.error().message;
    for (const char* name :
         {"report.html", "summary.json", "rates_by_scene.csv", "rates_by_distance.csv",
          "rates_by_scene_distance.csv", "rates_by_first_scene.csv", "logistic.csv",
          "psychometric.csv", "questionnaire.csv", "figures/choices.svg",
          "figures/decision_times.svg", "figures/switches.svg", "figures/psychometric_beams.svg",
          "figures/psychometric_spheres.svg"}) {
        EXPECT_TRUE(std::filesystem::is_regular_file(dir / name)) << name;
    }
    // A file where the folder should be: an error naming it.
    std::ofstream(dir / "a-file") << "x";
    const auto failed = write_report(r, {}, dir / "a-file");
    ASSERT_FALSE(failed);
    EXPECT_NE(failed.error().message.find("a-file"), std::string::npos);
    std::filesystem::remove_all(dir);
}

TEST(ReportText, CsvAndJsonEscaping) {
    EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
    EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(number_text(0.1), "0.1");
    EXPECT_EQ(number_text(-0.0), "0");
    EXPECT_EQ(number_text(std::nan("")), "");
    // report.html escapes its text as the SVG figures do.
    EXPECT_EQ(charts::xml_escaped("<a href='x'>&</a>"),
              "&lt;a href=&apos;x&apos;&gt;&amp;&lt;/a&gt;");
    JsonWriter json(kReportJson);
    json.begin_object()
        .value("text", "quote \" and \\ and \n")
        .value("nan", std::nan(""))
        .end_object();
    EXPECT_EQ(json.str(), "{\n  \"text\": \"quote \\\" and \\\\ and \\n\",\n  \"nan\": null\n}\n");
}

// Three participants in BEAMS whose reference choices follow P = 0.5 + 0.5 / (1 + (m / 8)^3)
// (counts of 20 per distance rounded from it), and P3 who chose at chance: the group's and
// P1's thresholds are estimable, P3's is not; the report carries them everywhere.
Dataset psychometric_dataset() {
    Dataset d;
    d.sources = {"psychometric.csv"};
    int index = 0;
    for (const std::string code : {"P1", "P2", "P3"}) {
        for (const double m : {2.0, 4.0, 6.0, 8.0, 11.0, 16.0, 32.0}) {
            const double p = code == "P3" ? 0.5 : 0.5 + 0.5 / (1.0 + std::pow(m / 8.0, 3.0));
            const int reference = static_cast<int>(std::lround(20 * p));
            for (int t = 0; t < 20; ++t) {
                d.trials.push_back(
                    trial("psychometric.csv", 1, code, index++, "beams", m, t >= reference));
            }
        }
    }
    for (auto& t : d.trials) t.reference_mode = "stereo";
    derive_session_fields(d.trials);
    return d;
}

TEST(ReportBuilder, PsychometricFitsInJsonCsvAndHtml) {
    ReportOptions options;
    options.psychometric.bootstrap_replicates = 100;
    const AnalysisResults r = analyse(psychometric_dataset(), options);
    ASSERT_EQ(r.psychometric.size(), 4u);  // all, P1, P2, P3
    const PsychometricFit& group = r.psychometric[0];
    ASSERT_EQ(group.participant, "all");
    ASSERT_TRUE(group.estimable) << group.reason;
    EXPECT_EQ(group.n, 420);
    ASSERT_TRUE(r.psychometric[1].estimable) << r.psychometric[1].reason;
    // P1's counts are the curve rounded: its threshold is close to 8 m.
    EXPECT_NEAR(r.psychometric[1].parameters.threshold, 8.0, 0.8);
    EXPECT_FALSE(r.psychometric[3].estimable);

    const std::string json = summary_json(r);
    EXPECT_TRUE(contains(json, "\"psychometric\": ["));
    EXPECT_TRUE(contains(json, "\"participant\": \"all\""));
    EXPECT_TRUE(contains(json, "\"threshold_m\": " + number_text(group.parameters.threshold)));
    EXPECT_TRUE(contains(json, "\"slope\": " + number_text(group.parameters.slope)));
    EXPECT_TRUE(contains(json, "\"threshold_ci\": ["));
    EXPECT_TRUE(contains(json, "\"interval_method\": \"participant bootstrap\""));
    EXPECT_TRUE(contains(json, "\"estimable\": false"));  // P3
    EXPECT_TRUE(contains(json, "\"threshold_m\": null"));
    EXPECT_TRUE(contains(json, "\"m\": 32"));

    const std::string csv = psychometric_csv(r);
    EXPECT_EQ(csv.substr(0, csv.find('\n')),
              "participant,scene,n,participants,estimable,threshold_m,threshold_ci_lower,"
              "threshold_ci_upper,slope,lapse,log_likelihood,interval_method,reason");
    EXPECT_TRUE(
        contains(csv, "\nall,beams,420,3,TRUE," + number_text(group.parameters.threshold) + ","));
    EXPECT_TRUE(contains(csv, "\nP3,beams,140,1,FALSE,,,,,,,,"));

    const std::vector<Figure> figures = report_figures(r);
    ASSERT_EQ(figures.back().name, "psychometric_beams");
    EXPECT_TRUE(contains(figures.back().svg, "Psychometric function, BEAMS"));
    EXPECT_TRUE(contains(figures.back().svg, "2 of 3 participants"));
    const std::string html = report_html(r, figures);
    EXPECT_TRUE(contains(html, "<figure id=\"figure-psychometric_beams\">"));
    EXPECT_TRUE(contains(html, "<a href=\"#psychometric\">"));
    EXPECT_TRUE(contains(html, "not estimable: the fitted threshold"));
}

TEST(ReportPower, GridPointsAndOutputs) {
    EXPECT_EQ(participant_grid(4), (std::vector<int>{2, 4}));
    EXPECT_EQ(participant_grid(9), (std::vector<int>{2, 4, 6, 8, 9}));
    EXPECT_EQ(participant_grid(1), (std::vector<int>{1}));
    const std::vector<int> big = participant_grid(47);
    EXPECT_EQ(big.front(), 2);
    EXPECT_EQ(big.back(), 47);
    EXPECT_LE(big.size(), 11u);
    PowerStudy study;
    study.protocol = "demo";
    study.observer = "default";
    study.hmd = "vive";
    study.distance_term = "mono_plane_m";
    study.runs = 20;
    study.points = {power_point(2, 20, 3, 1, 2), power_point(4, 20, 10, 0, 8)};
    EXPECT_DOUBLE_EQ(study.points[1].power, 0.5);
    EXPECT_LT(study.points[1].wilson.lower, 0.5);
    EXPECT_GT(study.points[1].wilson.upper, 0.5);
    EXPECT_DOUBLE_EQ(study.points[1].power_cr2, 0.4);
    // Wilson 95 % for 8 of 20 (z = 1.959964): (0.4 + z^2/40 -+ z sqrt(0.012 + z^2/1600)) /
    // (1 + z^2/20) = [0.218807, 0.613418].
    EXPECT_NEAR(study.points[1].wilson_cr2.lower, 0.218807, 1e-6);
    EXPECT_NEAR(study.points[1].wilson_cr2.upper, 0.613418, 1e-6);
    const std::string csv = power_csv(study);
    EXPECT_TRUE(contains(csv,
                         "participants,runs,detected,not_estimable,power,ci_lower,ci_upper,"
                         "detected_cr2,power_cr2,ci_lower_cr2,ci_upper_cr2\n"
                         "2,20,3,1,0.15,"));
    EXPECT_TRUE(contains(csv, ",2,0.1,"));
    const std::string json = power_json(study);
    EXPECT_TRUE(contains(json, "\"not_estimable\": 1"));
    EXPECT_TRUE(contains(json, "\"power\": 0.5"));
    EXPECT_TRUE(contains(json, "\"detected_cr2\": 8"));
    EXPECT_TRUE(contains(json, "\"power_cr2\": 0.4"));
    const std::string svg = power_svg(study);
    EXPECT_TRUE(contains(svg, "<svg"));
    EXPECT_TRUE(contains(svg, "0.8"));
}

}  // namespace
}  // namespace monoplane::analysis::report
