// analyse(): every statistic of the report over a data set, gathered into AnalysisResults.
#include "analysis/report/report.h"

#include <algorithm>
#include <cstdint>
#include <map>
#include <set>
#include <utility>

namespace monoplane::analysis::report {
namespace {

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
    r.gaze =
        analyse_gaze(data, kept, options.logistic.scene_terms, options.gaze_eye, options.gaze_hmd);
    return r;
}

}  // namespace monoplane::analysis::report
