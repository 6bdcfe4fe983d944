// summary.json: every number of the report under stable keys (docs/analysis.md).
#include "analysis/report/report.h"

#include <cmath>
#include <string_view>
#include <utility>

#include "analysis/report/gaze_section.h"
#include "analysis/report/inputs_section.h"
#include "analysis/report/psychometric_section.h"
#include "analysis/report/regression_section.h"
#include "analysis/report/study_day_section.h"
#include "analysis/report/text_output.h"

namespace monoplane::analysis::report {
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

// What each input file contributed.
void sources_json(JsonWriter& json, const std::vector<SourceCounts>& sources) {
    json.begin_array("sources");
    for (const SourceCounts& c : sources) {
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
}

// Each questionnaire item's summary and how often each answer was given.
void questionnaire_json(JsonWriter& json, const std::vector<ItemSummary>& items) {
    json.begin_array("questionnaire");
    for (const ItemSummary& item : items) {
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
}

}  // namespace

std::string summary_json(const AnalysisResults& r) {
    JsonWriter json(kReportJson);
    json.begin_object().value("schema_version", 1).value("title", r.title);
    sources_json(json, r.sources);
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
    gaze_json(json, r);

    groups_json(json, r.decision_times, "decision_time_s");
    groups_json(json, r.switches, "switches");
    questionnaire_json(json, r.questionnaire);
    json.end_object();
    return json.str();
}

}  // namespace monoplane::analysis::report
