// report.html: the page's style, head and sections; report_html() puts them in order.
#include "analysis/report/report.h"

#include <string>
#include <vector>

#include "analysis/report/gaze_section.h"
#include "analysis/report/html_format.h"
#include "analysis/report/inputs_section.h"
#include "analysis/report/psychometric_section.h"
#include "analysis/report/regression_section.h"
#include "analysis/report/study_day_section.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {
namespace {

using charts::xml_escaped;

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
    h += software_versions_html(r.inputs);
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
         "<li><a href=\"#order\">Order effects</a></li>" +
         std::string(r.gaze.recorded ? "<li><a href=\"#gaze\">Where participants looked</a></li>"
                                     : "") +
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

std::string figure_html(const std::vector<Figure>& figures, const std::string& name) {
    for (const Figure& f : figures) {
        if (f.name != name) continue;
        return "<figure id=\"figure-" + xml_escaped(f.name) + "\">\n" + inline_svg(f.svg) +
               "<figcaption>" + xml_escaped(f.caption) + " (also figures/" + xml_escaped(f.name) +
               ".svg and .png)</figcaption>\n</figure>\n";
    }
    return std::string();
}

std::string report_html(const AnalysisResults& r, const std::vector<Figure>& figures) {
    std::string h = head_html(r);
    h += data_section_html(r);
    h += choices_section_html(r, figures);
    h += chi_square_section_html(r);
    h += regression_section_html(r);
    h += psychometric_section_html(r, figures);
    h += order_section_html(r);
    h += gaze_section_html(r, figures);
    h += times_section_html(r, figures);
    h += questionnaire_section_html(r);
    h += "<p class=\"note\">Written by <code>monoplane analyze</code>; see docs/analysis.md.</p>\n";
    h += "</body>\n</html>\n";
    return h;
}

}  // namespace monoplane::analysis::report
