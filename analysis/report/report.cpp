#include "analysis/report/report.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <map>
#include <set>
#include <utility>

#include "analysis/report/figures.h"
#include "analysis/report/html_format.h"
#include "analysis/report/psychometric_figure.h"
#include "analysis/report/psychometric_section.h"
#include "analysis/report/regression_section.h"
#include "analysis/report/text_output.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {
namespace {

using charts::xml_escaped;

std::string joined(const std::set<std::string>& names) {
    std::string out;
    for (const std::string& name : names) {
        if (name.empty()) continue;
        if (!out.empty()) out += "/";
        out += name;
    }
    return out;
}

ChiSquareResult chi_square(const std::vector<TrialRow>& trials, const std::string& scene) {
    ChiSquareResult result;
    result.scene = scene;
    Result<ChiSquareTest> test = chi_square_by_distance(trials, scene);
    if (test) {
        result.test = std::move(test).value();
    } else {
        result.error = test.error().message;
    }
    return result;
}

Table rate_table(const std::vector<ChoiceRate>& rates, bool with_scene, bool with_distance,
                 const std::string& test_mode) {
    Table t;
    if (with_scene) {
        t.header.push_back("scene");
        t.numeric.push_back(false);
    }
    if (with_distance) {
        t.header.push_back("m (metres)");
        t.numeric.push_back(true);
    }
    for (const char* h : {"", "n", "rate", "95&nbsp;% Wilson", "95&nbsp;% Clopper-Pearson",
                          "binomial p (vs 50&nbsp;%)"}) {
        t.header.push_back(h);
        t.numeric.push_back(true);
    }
    t.header[t.header.size() - 6] = xml_escaped(test_mode) + " chosen";
    for (const ChoiceRate& r : rates) {
        std::vector<std::string> row;
        if (with_scene) row.push_back(scene_name(r.scene));
        if (with_distance) row.push_back(metres(r.mono_plane));
        row.push_back(std::to_string(r.test_chosen));
        row.push_back(std::to_string(r.n));
        row.push_back(r.n > 0 ? percent(r.rate) : "&ndash;");
        row.push_back(r.n > 0 ? interval_percent(r.wilson) : "&ndash;");
        row.push_back(r.n > 0 ? interval_percent(r.clopper_pearson) : "&ndash;");
        row.push_back(r.n > 0 ? p_value(r.binomial_p) : "&ndash;");
        t.rows.push_back(std::move(row));
    }
    return t;
}

Table summary_table(const std::vector<GroupSummary>& groups, int decimals) {
    Table t;
    t.header = {"scene", "n", "mean", "SD", "median", "Q1", "Q3", "min", "max"};
    t.numeric = {false, true, true, true, true, true, true, true, true};
    for (const GroupSummary& g : groups) {
        const Summary& s = g.summary;
        t.rows.push_back({scene_name(g.group), std::to_string(s.n), fixed(s.mean, decimals),
                          fixed(s.sd, decimals), fixed(s.median, decimals), fixed(s.q1, decimals),
                          fixed(s.q3, decimals), fixed(s.min, decimals), fixed(s.max, decimals)});
    }
    return t;
}

const char* kCss = R"css(
body { font-family: system-ui, -apple-system, "Segoe UI", "DejaVu Sans", Helvetica, Arial, sans-serif;
       max-width: 1000px; margin: 2em auto; padding: 0 1.2em; color: #222; line-height: 1.5; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; }
h2 { font-size: 1.3em; margin-top: 2em; border-bottom: 2px solid #0072B2; padding-bottom: 0.15em; }
h3 { font-size: 1.05em; margin-top: 1.5em; }
table { border-collapse: collapse; margin: 0.5em 0 1.2em; font-size: 0.9em; }
th, td { padding: 0.25em 0.75em; border-bottom: 1px solid #ddd; text-align: left; vertical-align: top; }
th { background: #eef3f8; }
.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
tbody tr:nth-child(even) td { background: #f8f8f8; }
figure { margin: 1.2em 0; }
figure svg { max-width: 100%; height: auto; }
figcaption, .note { color: #555; font-size: 0.9em; }
.warn { background: #fff4e5; border-left: 4px solid #E69F00; padding: 0.5em 1em; }
.key { background: #eef3f8; border-left: 4px solid #0072B2; padding: 0.5em 1em; }
code { font-family: ui-monospace, "DejaVu Sans Mono", monospace; font-size: 0.92em; }
nav ul { columns: 2; }
)css";

std::string chi_row_label(const ChiSquareResult& c) {
    return scene_name(c.scene);
}

// The frame log's paragraph: how many data trials a headset recorded frame by frame, and a table
// of those that missed more display slots than the protocol's missed_frame_threshold.
std::string frame_timing_html(const FrameTimingSummary& f) {
    std::string h = "<h3>Frame timing</h3>\n";
    if (f.trials_with_log == 0) {
        return h +
               "<p>No data trial has a frame log (headless sessions and CSV input record "
               "none).</p>\n";
    }
    h += "<p>" + std::to_string(f.trials_with_log) + " data trials have a frame log; <b>" +
         std::to_string(f.flagged) +
         "</b> missed more of their display slots than the protocol allows "
         "(missed_frame_threshold). Flagged trials stay in the analysis.</p>\n";
    if (f.flagged == 0) return h;
    Table t;
    t.header = {"participant", "session", "trial", "frames", "missed", "share", "threshold"};
    t.numeric = {false, true, true, true, true, true, true};
    for (const TrialFrameTiming& trial : f.trials) {
        if (!trial.flagged) continue;
        t.rows.push_back({xml_escaped(trial.participant), std::to_string(trial.session_id),
                          std::to_string(trial.trial_index), std::to_string(trial.frames),
                          std::to_string(trial.missed), percent(trial.share),
                          percent(trial.threshold)});
    }
    return h + t.html();
}

// Data and exclusions: what each source contributed, the exclusions, the participants (with
// their variables), the session notes and the frame log.
std::string data_section_html(const AnalysisResults& r) {
    std::string h;
    h += "<h2 id=\"data\">Data and exclusions</h2>\n";
    {
        Table t;
        t.header = {"source",   "sessions",    "participants", "trials",
                    "practice", "data trials", "analysed",     "questionnaire answers"};
        t.numeric = {false, true, true, true, true, true, true, true};
        for (const SourceCounts& c : r.sources) {
            t.rows.push_back({"<code>" + xml_escaped(c.source) + "</code>",
                              std::to_string(c.sessions), std::to_string(c.participants),
                              std::to_string(c.trials), std::to_string(c.practice),
                              std::to_string(c.data_trials), std::to_string(c.analysed),
                              std::to_string(c.answers)});
        }
        h += t.html();
        h += "<p class=\"note\">Sessions stay apart by source (two databases may both hold a "
             "session 1). " +
             codes_note_html(r.day) + "</p>\n";
    }
    h += protocol_versions_html(r.inputs);
    h += dropped_copies_html(r.inputs);
    {
        const Exclusions& e = r.exclusions;
        Table t;
        t.header = {"", "trials"};
        t.numeric = {false, true};
        t.rows = {{"all trials merged", std::to_string(r.trials)},
                  {"excluded: practice", std::to_string(e.practice)},
                  {"excluded: undecided (session ended before the decision)",
                   std::to_string(e.undecided)},
                  {"excluded: invalid (not both alternatives viewed)", std::to_string(e.invalid)},
                  {"<b>analysed</b>", "<b>" + std::to_string(e.kept) + "</b>"}};
        h += t.html();
        h += "<p class=\"note\">Each trial is counted once, under the first reason that applies "
             "in the order practice, undecided, invalid. papers/000 excluded 48 of 1410 "
             "decisions as invalid.</p>\n";
    }
    h += participants_html(r.day);
    h += notes_html(r.day);
    h += frame_timing_html(r.frame_timing);
    return h;
}

// Order effects: whether the Latin square's rows are evenly filled, then the rates by first
// scene.
std::string order_section_html(const AnalysisResults& r) {
    const std::string test = xml_escaped(r.test_mode);
    std::string h;
    h += "<h2 id=\"order\">Order effects: by first scene</h2>\n";
    h += counterbalancing_html(r.day);
    h += "<h3>Rates by first scene</h3>\n";
    h += "<p>Decisions for " + test +
         " in all scenes, grouped by the scene a session began with (papers/000: 40&nbsp;% with "
         "SPHERES first, 37&nbsp;% with LANDSCAPE, 29&nbsp;% with BEAMS).</p>\n";
    {
        Table t;
        t.header = {"first scene", "sessions",         test + " chosen",           "n",
                    "rate",        "95&nbsp;% Wilson", "binomial p (vs 50&nbsp;%)"};
        t.numeric = {false, true, true, true, true, true, true};
        for (const FirstSceneRate& f : r.by_first_scene) {
            t.rows.push_back({scene_name(f.rate.scene), std::to_string(f.sessions),
                              std::to_string(f.rate.test_chosen), std::to_string(f.rate.n),
                              percent(f.rate.rate), interval_percent(f.rate.wilson),
                              p_value(f.rate.binomial_p)});
        }
        h += t.html();
    }
    return h;
}

// A scene name as part of a file name under figures/: scene names may be glTF files' paths
// ("models/room.glb"), whose '/' would name a folder. Letters, digits, '-', '_' and '.' stay.
std::string file_stem_of(const std::string& scene) {
    std::string stem = scene;
    for (char& c : stem) {
        const bool safe =
            std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_' || c == '.';
        if (!safe) c = '_';
    }
    return stem;
}

// What each source contributed, and the sessions and participants over all sources. Sources in
// the order they were read, then any source only rows name.
void count_sources(const Dataset& data, AnalysisResults& r) {
    std::vector<std::string> order = data.sources;
    for (const TrialRow& t : data.trials) {
        if (std::find(order.begin(), order.end(), t.source) == order.end()) {
            order.push_back(t.source);
        }
    }
    std::set<std::pair<std::string, std::int64_t>> all_sessions;
    std::set<std::string> all_participants;
    for (const std::string& source : order) {
        SourceCounts c;
        c.source = source;
        std::set<std::int64_t> sessions;
        std::set<std::string> participants;
        for (const TrialRow& t : data.trials) {
            if (t.source != source) continue;
            sessions.insert(t.session_id);
            participants.insert(t.participant);
            ++c.trials;
            c.practice += t.practice ? 1 : 0;
            c.analysed += is_analysable(t) ? 1 : 0;
        }
        for (const AnswerRow& a : data.answers) c.answers += a.source == source ? 1 : 0;
        c.sessions = static_cast<int>(sessions.size());
        c.participants = static_cast<int>(participants.size());
        c.data_trials = c.trials - c.practice;
        for (std::int64_t s : sessions) all_sessions.insert({source, s});
        all_participants.insert(participants.begin(), participants.end());
        r.sources.push_back(c);
    }
    r.sessions = static_cast<int>(all_sessions.size());
    r.participants = static_cast<int>(all_participants.size());
    r.trials = static_cast<int>(data.trials.size());
}

// Who was analysed, and the modes compared ("reference" and "test" when no trial names them).
void describe_analysed_trials(const std::vector<TrialRow>& kept, AnalysisResults& r) {
    std::set<std::string> references, tests, analysed_participants;
    for (const TrialRow& t : kept) {
        analysed_participants.insert(t.participant);
        references.insert(t.reference_mode);
        tests.insert(t.test_mode);
    }
    r.analysed_participants = static_cast<int>(analysed_participants.size());
    r.reference_mode = joined(references);
    r.test_mode = joined(tests);
    if (r.reference_mode.empty()) r.reference_mode = "reference";
    if (r.test_mode.empty()) r.test_mode = "test";
}

// The choice rates (overall, per scene, distance, both, and first scene with its sessions) and
// the chi-square tests of distance against decision.
void rates_and_chi_square(const std::vector<TrialRow>& kept, AnalysisResults& r) {
    r.overall = overall_rate(kept);
    r.by_scene = rates_by_scene(kept);
    r.by_distance = rates_by_distance(kept);
    r.by_scene_distance = rates_by_scene_and_distance(kept);
    std::map<std::string, std::set<std::pair<std::string, std::int64_t>>> first_scene_sessions;
    for (const TrialRow& t : kept)
        first_scene_sessions[t.first_scene].insert({t.source, t.session_id});
    for (const ChoiceRate& rate : rates_by_first_scene(kept)) {
        r.by_first_scene.push_back(
            {rate, static_cast<int>(first_scene_sessions[rate.scene].size())});
    }

    r.chi_square = chi_square(kept, "");
    for (const ChoiceRate& scene : r.by_scene) {
        r.chi_square_by_scene.push_back(chi_square(kept, scene.scene));
    }
}

}  // namespace

AnalysisResults analyse(const Dataset& data, const ReportOptions& options) {
    AnalysisResults r;
    r.title = options.title;
    r.logistic_options = options.logistic;
    count_sources(data, r);

    const std::vector<TrialRow> kept = analysable_trials(data.trials, r.exclusions);
    r.frame_timing = summarize_frame_timing(data.trials);
    r.data_trials = r.trials - r.exclusions.practice;
    describe_analysed_trials(kept, r);
    rates_and_chi_square(kept, r);

    Result<LogisticFit> fit = fit_choice_model(kept, options.logistic);
    if (fit) {
        r.logistic = std::move(fit).value();
    } else {
        r.logistic_error = fit.error().message;
    }

    r.psychometric = fit_psychometric_functions(kept, options.psychometric);

    r.decision_times = decision_times_by_scene(kept);
    r.switches = switches_by_scene(kept);
    r.questionnaire = questionnaire_summaries(data.answers);
    r.day = study_day(data);
    r.inputs = input_records(data);
    return r;
}

std::vector<Figure> report_figures(const AnalysisResults& r) {
    const std::string counts = std::to_string(r.exclusions.kept) + " valid decisions of " +
                               std::to_string(r.participants) + " participants (" +
                               std::to_string(r.sessions) + " sessions)";
    std::vector<Figure> figures;
    figures.push_back({"choices",
                       "Decisions for " + r.test_mode +
                           " per scene over the mono-plane distance m, as "
                           "papers/000 Fig. 7; the line marks 50 % (no preference).",
                       choices_svg(r.by_scene_distance, r.test_mode, r.reference_mode, counts)});
    figures.push_back({"decision_times",
                       "Decision time per scene: quartile boxes, median line, mean diamond, "
                       "whiskers from minimum to maximum.",
                       decision_times_svg(r.decision_times, counts)});
    figures.push_back({"switches", "Switches between the two alternatives per trial, per scene.",
                       switches_svg(r.switches, counts)});
    for (const PsychometricFit& f : r.psychometric) {
        if (f.participant != "all") continue;
        figures.push_back({"psychometric_" + file_stem_of(f.scene),
                           "Choices of " + r.reference_mode + " in " + upper_case(f.scene) +
                               " over the mono-plane distance m with the fitted psychometric "
                               "functions: the group's (green, with its threshold and 95 % "
                               "interval) and each participant's (grey).",
                           psychometric_svg(r.psychometric, f.scene, r.reference_mode)});
    }
    return figures;
}

namespace {

// A figure of the report by name, with its caption; empty when there is no such figure.
std::string figure_html(const std::vector<Figure>& figures, const std::string& name) {
    for (const Figure& f : figures) {
        if (f.name != name) continue;
        return "<figure id=\"figure-" + xml_escaped(f.name) + "\">\n" + inline_svg(f.svg) +
               "<figcaption>" + xml_escaped(f.caption) + " (also figures/" + xml_escaped(f.name) +
               ".svg and .png)</figcaption>\n</figure>\n";
    }
    return std::string();
}

// The document's head, the title, what was compared, and the table of contents.
std::string head_html(const AnalysisResults& r) {
    const std::string test = xml_escaped(r.test_mode);
    const std::string reference = xml_escaped(r.reference_mode);
    std::string h =
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
        "<title>" +
        xml_escaped(r.title) + "</title>\n<style>" + kCss + "</style>\n</head>\n<body>\n";
    h += "<h1>" + xml_escaped(r.title) + "</h1>\n";
    h += "<p class=\"note\">" + std::to_string(r.sources.size()) + " source(s), " +
         std::to_string(r.sessions) + " session(s), " + std::to_string(r.participants) +
         " participant(s). Two-alternative forced choice between <b>" + reference +
         "</b> (reference) and <b>" + test +
         "</b>; the statistics follow papers/000 section 6.2 (Fink et al. 2019). Tables as CSV "
         "and every number in summary.json beside this file.</p>\n";
    h += "<nav><ul><li><a href=\"#data\">Data and exclusions</a></li>"
         "<li><a href=\"#choices\">Choices</a></li>"
         "<li><a href=\"#chi-square\">Distance &times; decision (chi-square)</a></li>"
         "<li><a href=\"#regression\">Logistic regression</a></li>"
         "<li><a href=\"#psychometric\">Psychometric functions</a></li>"
         "<li><a href=\"#order\">Order effects</a></li>"
         "<li><a href=\"#times\">Decision times and switches</a></li>"
         "<li><a href=\"#questionnaire\">Questionnaire</a></li></ul></nav>\n";
    return h;
}

// Choices: the overall rate with its test, the figure, and the rates per scene and distance.
std::string choices_section_html(const AnalysisResults& r, const std::vector<Figure>& figures) {
    const std::string test = xml_escaped(r.test_mode);
    std::string h = "<h2 id=\"choices\">Choices</h2>\n";
    const ChoiceRate& o = r.overall;
    if (o.n > 0) {
        h += "<p class=\"key\">Of " + std::to_string(o.n) + " valid decisions, " +
             std::to_string(o.test_chosen) + " (" + percent(o.rate, 2) + ", 95&nbsp;% Wilson " +
             interval_percent(o.wilson) + ") chose <b>" + test +
             "</b>; exact two-sided binomial test against 50&nbsp;%: " + p_statement(o.binomial_p) +
             ".</p>\n";
    } else {
        h += "<p class=\"warn\">No valid decisions to analyse.</p>\n";
    }
    h += figure_html(figures, "choices");
    h += "<h3>Per scene</h3>\n" + rate_table(r.by_scene, true, false, r.test_mode).html();
    h += "<h3>Per distance (all scenes)</h3>\n" +
         rate_table(r.by_distance, false, true, r.test_mode).html();
    h += "<h3>Per scene &times; distance</h3>\n" +
         rate_table(r.by_scene_distance, true, true, r.test_mode).html();
    h += "<p class=\"note\">Rates pool decisions across participants and are descriptive; the "
         "binomial tests treat each decision as independent. Wilson intervals have good coverage "
         "at small n; Clopper-Pearson intervals are exact and conservative.</p>\n";
    return h;
}

// The chi-square tests, all scenes pooled and then per scene, with the reason to distrust them.
std::string chi_square_section_html(const AnalysisResults& r) {
    const std::string test = xml_escaped(r.test_mode);
    const std::string reference = xml_escaped(r.reference_mode);
    std::string h = "<h2 id=\"chi-square\">Distance &times; decision (chi-square)</h2>\n";
    h += "<p>Pearson's chi-square test of independence of the mono-plane distance and the "
         "decision (" +
         test + " or " + reference +
         "), without continuity correction, with phi and Cram&eacute;r's V as effect sizes "
         "(papers/000 reports &phi; = 0.07, p &gt; 0.05).</p>\n";
    Table t;
    t.header = {"scenes", "n", "&chi;&sup2;", "df", "p", "&phi;", "Cram&eacute;r's V", "note"};
    t.numeric = {false, true, true, true, true, true, true, false};
    std::vector<const ChiSquareResult*> all{&r.chi_square};
    for (const ChiSquareResult& c : r.chi_square_by_scene) all.push_back(&c);
    for (const ChiSquareResult* c : all) {
        if (c->test) {
            const ChiSquareTest& x = *c->test;
            t.rows.push_back({chi_row_label(*c), std::to_string(x.n), fixed(x.chi_square, 3),
                              std::to_string(x.df), p_value(x.p), fixed(x.phi, 3),
                              fixed(x.cramers_v, 3), ""});
        } else {
            t.rows.push_back({chi_row_label(*c), "&ndash;", "&ndash;", "&ndash;", "&ndash;",
                              "&ndash;", "&ndash;", "not computed: " + xml_escaped(c->error)});
        }
    }
    h += t.html();
    h += "<p class=\"warn\">The chi-square test assumes independent decisions. Every participant "
         "decided at every distance and scene, so their decisions are repeated measures and "
         "correlated: the pooled test understates the uncertainty. It is reported because the "
         "paper reports it; the regression below is the valid test.</p>\n";
    return h;
}

std::string times_section_html(const AnalysisResults& r, const std::vector<Figure>& figures) {
    std::string h = "<h2 id=\"times\">Decision times and switches</h2>\n";
    h += figure_html(figures, "decision_times");
    h += "<h3>Decision time (seconds)</h3>\n" + summary_table(r.decision_times, 2).html();
    h += figure_html(figures, "switches");
    h += "<h3>Switches per trial</h3>\n" + summary_table(r.switches, 2).html();
    return h;
}

// The questionnaire's items: their summaries and how often each answer was given.
std::string questionnaire_section_html(const AnalysisResults& r) {
    std::string h = "<h2 id=\"questionnaire\">Questionnaire</h2>\n";
    if (r.questionnaire.empty()) {
        return h +
               "<p class=\"note\">No questionnaire answers (CSV exports hold none; databases "
               "hold them when the protocol asks).</p>\n";
    }
    Table t;
    t.header = {"item", "statement", "n", "mean", "SD", "median", "IQR", "answers 1..K"};
    t.numeric = {true, false, true, true, true, true, true, false};
    for (const ItemSummary& item : r.questionnaire) {
        std::string counts;
        for (std::size_t k = 0; k < item.counts.size(); ++k) {
            if (k > 0) counts += " &middot; ";
            counts += std::to_string(item.counts[k]);
        }
        const Summary& s = item.summary;
        t.rows.push_back({std::to_string(item.item + 1), xml_escaped(item.text),
                          std::to_string(s.n), fixed(s.mean, 2), fixed(s.sd, 2), fixed(s.median, 1),
                          fixed(s.q1, 1) + "&ndash;" + fixed(s.q3, 1),
                          counts + " <span class=\"note\">(1.." +
                              std::to_string(item.scale_points) + ")</span>"});
    }
    return h + t.html();
}

}  // namespace

std::string report_html(const AnalysisResults& r, const std::vector<Figure>& figures) {
    std::string h = head_html(r);
    h += data_section_html(r);
    h += choices_section_html(r, figures);
    h += chi_square_section_html(r);
    h += regression_section_html(r);
    h += psychometric_section_html(r, figures);
    h += order_section_html(r);
    h += times_section_html(r, figures);
    h += questionnaire_section_html(r);
    h += "<p class=\"note\">Written by <code>monoplane analyze</code>; see docs/analysis.md.</p>\n";
    h += "</body>\n</html>\n";
    return h;
}

namespace {

// The frame log's verdict per trial: how many data trials have one, and which missed more of
// their display slots than the protocol allows (they stay in the analysis; the reader decides).
void frame_timing_json(JsonWriter& json, const FrameTimingSummary& f) {
    json.begin_object("frame_timing")
        .value("trials_with_log", f.trials_with_log)
        .value("flagged", f.flagged);
    json.begin_array("trials");
    for (const TrialFrameTiming& t : f.trials) {
        json.begin_object()
            .value("participant", t.participant)
            .value("session", t.session_id)
            .value("trial_index", t.trial_index)
            .value("frames", t.frames)
            .value("missed", t.missed)
            .value("missed_share", t.share)
            .value("threshold", t.threshold)
            .value("flagged", t.flagged)
            .end_object();
    }
    json.end_array();
    json.end_object();
}

// An interval as [lower, upper].
void interval_json(JsonWriter& json, std::string_view key, const Interval& interval) {
    json.begin_array(key).value("", interval.lower).value("", interval.upper).end_array();
}

void rate_json(JsonWriter& json, const ChoiceRate& r, std::string_view key = {}) {
    json.begin_object(key);
    if (!r.scene.empty()) json.value("scene", r.scene);
    if (std::isfinite(r.mono_plane)) json.value("mono_plane", r.mono_plane);
    json.value("test_chosen", r.test_chosen).value("n", r.n).value("rate", r.rate);
    interval_json(json, "wilson", r.wilson);
    interval_json(json, "clopper_pearson", r.clopper_pearson);
    json.value("binomial_p", r.binomial_p).end_object();
}

void chi_json(JsonWriter& json, const ChiSquareResult& c, std::string_view key) {
    json.begin_object(key);
    json.value("computed", c.test.has_value());
    if (c.test) {
        json.value("n", c.test->n)
            .value("chi_square", c.test->chi_square)
            .value("df", c.test->df)
            .value("p", c.test->p)
            .value("phi", c.test->phi)
            .value("cramers_v", c.test->cramers_v);
    } else {
        json.value("error", c.error);
    }
    json.end_object();
}

void summary_fields(JsonWriter& json, const Summary& s) {
    json.value("n", s.n)
        .value("mean", s.mean)
        .value("sd", s.sd)
        .value("median", s.median)
        .value("q1", s.q1)
        .value("q3", s.q3)
        .value("min", s.min)
        .value("max", s.max);
}

void groups_json(JsonWriter& json, const std::vector<GroupSummary>& groups, std::string_view key) {
    json.begin_array(key);
    for (const GroupSummary& g : groups) {
        json.begin_object().value("scene", g.group);
        summary_fields(json, g.summary);
        json.end_object();
    }
    json.end_array();
}

std::string rate_fields(const ChoiceRate& r) {
    return csv_line({r.scene, number_text(r.mono_plane), std::to_string(r.test_chosen),
                     std::to_string(r.n), number_text(r.rate), number_text(r.wilson.lower),
                     number_text(r.wilson.upper), number_text(r.clopper_pearson.lower),
                     number_text(r.clopper_pearson.upper), number_text(r.binomial_p)});
}

}  // namespace

std::string summary_json(const AnalysisResults& r) {
    JsonWriter json(kReportJson);
    json.begin_object().value("schema_version", 1).value("title", r.title);
    json.begin_array("sources");
    for (const SourceCounts& c : r.sources) {
        json.begin_object()
            .value("source", c.source)
            .value("sessions", c.sessions)
            .value("participants", c.participants)
            .value("trials", c.trials)
            .value("practice", c.practice)
            .value("data_trials", c.data_trials)
            .value("analysed", c.analysed)
            .value("answers", c.answers)
            .end_object();
    }
    json.end_array();
    json.value("sessions", r.sessions)
        .value("participants", r.participants)
        .value("analysed_participants", r.analysed_participants);
    json.begin_object("trials")
        .value("total", r.trials)
        .value("data", r.data_trials)
        .value("practice", r.exclusions.practice)
        .value("undecided", r.exclusions.undecided)
        .value("invalid", r.exclusions.invalid)
        .value("analysed", r.exclusions.kept)
        .end_object();
    frame_timing_json(json, r.frame_timing);
    json.value("reference_mode", r.reference_mode).value("test_mode", r.test_mode);
    rate_json(json, r.overall, "overall");
    for (const auto& [key, rates] :
         {std::pair<const char*, const std::vector<ChoiceRate>*>{"by_scene", &r.by_scene},
          {"by_distance", &r.by_distance},
          {"by_scene_distance", &r.by_scene_distance}}) {
        json.begin_array(key);
        for (const ChoiceRate& rate : *rates) rate_json(json, rate);
        json.end_array();
    }
    json.begin_array("by_first_scene");
    for (const FirstSceneRate& f : r.by_first_scene) {
        json.begin_object()
            .value("first_scene", f.rate.scene)
            .value("sessions", f.sessions)
            .value("test_chosen", f.rate.test_chosen)
            .value("n", f.rate.n)
            .value("rate", f.rate.rate);
        interval_json(json, "wilson", f.rate.wilson);
        json.value("binomial_p", f.rate.binomial_p).end_object();
    }
    json.end_array();
    json.begin_object("chi_square");
    chi_json(json, r.chi_square, "all");
    json.begin_object("by_scene");
    for (const ChiSquareResult& c : r.chi_square_by_scene) chi_json(json, c, c.scene);
    json.end_object();
    json.end_object();

    logistic_json(json, r);
    psychometric_json(json, r);
    study_day_json(json, r.day);
    input_records_json(json, r.inputs);

    groups_json(json, r.decision_times, "decision_time_s");
    groups_json(json, r.switches, "switches");
    json.begin_array("questionnaire");
    for (const ItemSummary& item : r.questionnaire) {
        json.begin_object()
            .value("item", item.item)
            .value("text", item.text)
            .value("scale_points", item.scale_points);
        summary_fields(json, item.summary);
        json.begin_array("counts");
        for (int count : item.counts) json.value("", count);
        json.end_array().end_object();
    }
    json.end_array();
    json.end_object();
    return json.str();
}

std::string rates_csv(const std::vector<ChoiceRate>& rates) {
    std::string out = csv_line({"scene", "mono_plane", "test_chosen", "n", "rate", "wilson_lower",
                                "wilson_upper", "cp_lower", "cp_upper", "binomial_p"});
    for (const ChoiceRate& r : rates) out += rate_fields(r);
    return out;
}

std::string questionnaire_csv(const std::vector<ItemSummary>& items) {
    int points = 0;
    for (const ItemSummary& item : items) {
        points =
            std::max(points, std::max(item.scale_points, static_cast<int>(item.counts.size())));
    }
    std::vector<std::string> header = {"item",   "text", "scale_points", "n",   "mean", "sd",
                                       "median", "q1",   "q3",           "min", "max"};
    for (int k = 1; k <= points; ++k) header.push_back("count_" + std::to_string(k));
    std::string out = csv_line(header);
    for (const ItemSummary& item : items) {
        const Summary& s = item.summary;
        std::vector<std::string> row = {
            std::to_string(item.item), item.text,           std::to_string(item.scale_points),
            std::to_string(s.n),       number_text(s.mean), number_text(s.sd),
            number_text(s.median),     number_text(s.q1),   number_text(s.q3),
            number_text(s.min),        number_text(s.max)};
        for (int k = 0; k < points; ++k) {
            row.push_back(k < static_cast<int>(item.counts.size())
                              ? std::to_string(item.counts[k])
                              : (k < item.scale_points ? "0" : ""));
        }
        out += csv_line(row);
    }
    return out;
}

Result<void> write_text_file(const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    if (!out) return Error{"cannot write '" + path.string() + "': cannot open it for writing"};
    out << text;
    out.close();
    if (!out) return Error{"cannot write '" + path.string() + "': write failed (disk full?)"};
    return Ok{};
}

Result<WrittenReport> write_report(const AnalysisResults& r, const std::vector<Figure>& figures,
                                   const std::filesystem::path& dir) {
    WrittenReport written;
    std::error_code ec;
    std::filesystem::create_directories(dir / "figures", ec);
    if (ec) return Error{"cannot create '" + (dir / "figures").string() + "': " + ec.message()};
    for (const Figure& f : figures) {
        const std::filesystem::path path = dir / "figures" / (f.name + ".svg");
        MONOPLANE_TRY(write_text_file(path, f.svg));
        written.figures.push_back(path);
    }
    const std::pair<const char*, std::string> tables[] = {
        {"rates_by_scene.csv", rates_csv(r.by_scene)},
        {"rates_by_distance.csv", rates_csv(r.by_distance)},
        {"rates_by_scene_distance.csv", rates_csv(r.by_scene_distance)},
        {"rates_by_first_scene.csv",
         [&] {
             std::vector<ChoiceRate> rates;
             for (const FirstSceneRate& f : r.by_first_scene) rates.push_back(f.rate);
             return rates_csv(rates);
         }()},
        {"logistic.csv", logistic_csv(r)},
        {"psychometric.csv", psychometric_csv(r)},
        {"questionnaire.csv", questionnaire_csv(r.questionnaire)},
    };
    for (const auto& [name, text] : tables) {
        const std::filesystem::path path = dir / name;
        MONOPLANE_TRY(write_text_file(path, text));
        written.tables.push_back(path);
    }
    written.json = dir / "summary.json";
    MONOPLANE_TRY(write_text_file(written.json, summary_json(r)));
    // Last: a report.html on disk means everything it refers to is there too.
    written.html = dir / "report.html";
    MONOPLANE_TRY(write_text_file(written.html, report_html(r, figures)));
    return written;
}

}  // namespace monoplane::analysis::report
