#include "app/commands/study_rows.h"

#include <algorithm>
#include <map>
#include <memory>
#include <optional>
#include <system_error>

#include "rig/error_budget.h"
#include "rig/rig.h"
#include "study/export.h"
#include "study/gaze_summary.h"
#include "study/protocol_design.h"
#include "study/render_mode.h"

namespace monoplane::app {

namespace {

bool shows(const study::ScheduledTrial& trial, study::RenderMode mode) {
    return trial.label1_mode == mode || trial.label2_mode == mode;
}

// hybrid-auto never goes nearer than the trial's m nor than the budget allows for content at
// any depth: the nearer of the two is the worst the simulated observer can be shown.
double effective_plane(const hmd::HmdProfile& hmd, const study::Protocol& protocol, double m) {
    rig::RigInputs inputs = hmd::rig_inputs(hmd, m);
    inputs.near = protocol.near;
    inputs.far = protocol.far;
    const study::AutoPlaneSettings& a = protocol.auto_plane;
    const auto budget = rig::nearest_mono_plane_within(
        inputs, a.error_budget_arcmin,
        a.measure == "disparity" ? rig::ErrorMeasure::kDisparity : rig::ErrorMeasure::kEye);
    return budget ? std::max(m, budget->mono_plane) : m;
}

}  // namespace

std::function<double(const study::ScheduledTrial&)> trial_error_model(
    const hmd::HmdProfile& hmd, const study::Protocol& protocol) {
    auto cache = std::make_shared<std::map<std::pair<double, bool>, double>>();
    return [hmd, protocol, cache](const study::ScheduledTrial& trial) {
        const bool automatic = shows(trial, study::RenderMode::HybridAuto);
        const bool hybrid_shown = automatic || shows(trial, study::RenderMode::Hybrid) ||
                                  shows(trial, study::RenderMode::HybridFarfield);
        if (!hybrid_shown) return 0.0;
        const auto key = std::make_pair(trial.mono_plane, automatic);
        if (const auto found = cache->find(key); found != cache->end()) return found->second;
        const double m =
            automatic ? effective_plane(hmd, protocol, trial.mono_plane) : trial.mono_plane;
        rig::RigInputs inputs = hmd::rig_inputs(hmd, m);
        inputs.near = protocol.near;
        inputs.far = protocol.far;
        const auto rig = rig::build_rig(inputs);
        const double error = rig ? rig->max_error_px : 0.0;
        cache->emplace(key, error);
        return error;
    };
}

analysis::TrialRow trial_row(const study::TrialRecord& record, const study::SessionInfo& session,
                             const std::string& source, const std::string& reference_mode) {
    analysis::TrialRow row;
    row.source = source;
    row.session_id = record.session_id;
    row.session_uuid = session.session_uuid;
    row.participant = record.participant_code;
    row.protocol = session.protocol_name;
    row.trial_index = record.trial.index;
    row.practice = record.trial.practice;
    row.block = record.trial.block;
    row.scene = record.trial.scene;
    row.mono_plane = record.trial.mono_plane;
    row.label1_mode = std::string(study::render_mode_name(record.trial.label1_mode));
    row.label2_mode = std::string(study::render_mode_name(record.trial.label2_mode));
    row.reference_mode = reference_mode;
    row.decided = record.decided;
    if (record.decided) {
        row.valid = record.outcome.valid;
        row.chosen_mode = std::string(study::render_mode_name(record.outcome.chosen_mode));
        row.switches = record.outcome.switches;
        row.decision_time_s = static_cast<double>(record.outcome.decision_time_ns) * 1e-9;
    }
    return row;
}

std::map<int, TrialFrameCounts> trial_frame_counts(const std::vector<study::FrameRecord>& frames) {
    std::map<int, TrialFrameCounts> counts;
    for (const study::FrameRecord& f : frames) {
        if (!f.trial_index || (f.shown != "label1" && f.shown != "label2")) continue;
        TrialFrameCounts& trial = counts[*f.trial_index];
        ++trial.shown;
        trial.missed += f.missed ? 1 : 0;
    }
    return counts;
}

double missed_frame_threshold(const study::SessionInfo& session) {
    Result<study::Protocol> protocol =
        study::parse_protocol(session.protocol_text, "session " + std::to_string(session.id));
    return protocol ? protocol->missed_frame_threshold : study::Protocol{}.missed_frame_threshold;
}

analysis::DesignComparison protocol_design_comparison() {
    // Shared by the copies of the function: the analysis compares each version with each design.
    auto parsed = std::make_shared<std::map<std::string, std::optional<study::Protocol>>>();
    const auto protocol =
        [parsed](const std::string& text) -> const std::optional<study::Protocol>& {
        auto found = parsed->find(text);
        if (found == parsed->end()) {
            Result<study::Protocol> read = study::parse_protocol(text, "a session's protocol");
            found =
                parsed->emplace(text, read ? std::optional(std::move(read).value()) : std::nullopt)
                    .first;
        }
        return found->second;
    };
    return [protocol](const std::string& earlier,
                      const std::string& later) -> std::optional<std::vector<std::string>> {
        const std::optional<study::Protocol>& a = protocol(earlier);
        const std::optional<study::Protocol>& b = protocol(later);
        if (!a || !b) return std::nullopt;
        return study::design_differences(*a, *b);
    };
}

namespace {

// The session's valid gaze samples on a trial's scene, as the report's density reads them.
void add_gaze_samples(const std::string& source, const std::vector<study::FrameRecord>& frames,
                      const std::map<int, const study::TrialRecord*>& trials,
                      analysis::Dataset& dataset) {
    for (const study::FrameRecord& f : frames) {
        if (!f.gaze || !f.gaze->valid || !f.head || !f.gaze_point || !f.trial_index) continue;
        const auto trial = trials.find(*f.trial_index);
        if (trial == trials.end()) continue;
        dataset.gaze_samples.push_back(
            analysis::GazeSampleRow{.source = source,
                                    .session_id = trial->second->session_id,
                                    .participant = trial->second->participant_code,
                                    .scene = trial->second->trial.scene,
                                    .mono_plane = f.gaze_point->mono_plane_m,
                                    .head = *f.head,
                                    .direction = f.gaze->direction,
                                    .depth_m = f.gaze_point->depth_m});
    }
}

// Each trial row's gaze (after derive_session_fields() named its test alternative): the error
// at gaze over the frames of the label that showed the test alternative, and the share beyond m.
void add_trial_gaze(const std::map<std::pair<std::int64_t, int>, study::TrialGaze>& gaze,
                    std::vector<analysis::TrialRow>& trials) {
    for (analysis::TrialRow& row : trials) {
        const auto found = gaze.find({row.session_id, row.trial_index});
        if (found == gaze.end()) continue;
        const std::size_t test_label = row.label1_mode == row.test_mode ? 0 : 1;
        row.gaze_error_test_arcmin = found->second.error_mean_arcmin[test_label];
        row.gaze_share_beyond_m = found->second.share_beyond_m;
        row.gaze_fixations = static_cast<int>(found->second.fixations.size());
    }
}

}  // namespace

Result<analysis::Dataset> read_study_database(const std::filesystem::path& path,
                                              const study::StudyStore& store,
                                              const study::ExportData& data) {
    if (data.sessions.empty()) {
        return Error{"--db " + path.string() +
                     ": the database holds no sessions (run one with "
                     "`monoplane study run`)"};
    }
    analysis::Dataset dataset;
    const std::string source = path.string();
    dataset.sources.push_back(source);
    std::map<std::int64_t, std::string> reference;
    std::map<std::int64_t, int> scale_points;
    std::map<std::int64_t, double> missed_threshold;
    // Per session and trial: frames shown and missed, from the frame log (headset sessions).
    std::map<std::int64_t, std::map<int, TrialFrameCounts>> frame_counts;
    std::map<std::pair<std::int64_t, int>, study::TrialGaze> trial_gaze;
    std::map<std::int64_t, std::map<int, const study::TrialRecord*>> trials_by_index;
    for (const study::TrialRecord& record : data.trials) {
        trials_by_index[record.session_id][record.trial.index] = &record;
    }
    for (const auto& [id, session] : data.sessions) {
        // The protocol as the session ran it: its first alternative is the reference.
        Result<study::Protocol> protocol =
            study::parse_protocol(session.protocol_text, "session " + std::to_string(id));
        reference[id] = protocol ? std::string(study::render_mode_name(protocol->alternatives[0]))
                                 : std::string();
        scale_points[id] = protocol ? protocol->questionnaire.scale_points : 7;
        missed_threshold[id] = missed_frame_threshold(session);
        Result<std::vector<study::FrameRecord>> frames = store.frames(id);
        if (!frames) return Error{"--db " + path.string() + ": " + frames.error().message};
        frame_counts[id] = trial_frame_counts(*frames);
        for (study::TrialGaze& gaze : study::summarize_trial_gaze(*frames)) {
            trial_gaze[{id, gaze.trial_index}] = std::move(gaze);
        }
        add_gaze_samples(source, *frames, trials_by_index[id], dataset);
        Result<std::vector<study::QuestionnaireAnswer>> answers = store.answers(id);
        if (!answers) return Error{"--db " + path.string() + ": " + answers.error().message};
        for (const study::QuestionnaireAnswer& a : *answers) {
            dataset.answers.push_back(analysis::AnswerRow{
                source, id, session.participant_code, a.item, a.text, a.answer, scale_points[id]});
        }
    }
    for (const study::TrialRecord& record : data.trials) {
        const auto session = data.sessions.find(record.session_id);
        if (session == data.sessions.end()) continue;  // collect_export pairs them
        analysis::TrialRow row =
            trial_row(record, session->second, source, reference[record.session_id]);
        row.missed_frame_threshold = missed_threshold[record.session_id];
        const std::map<int, TrialFrameCounts>& counts = frame_counts[record.session_id];
        if (const auto found = counts.find(record.trial.index); found != counts.end()) {
            row.frames_shown = found->second.shown;
            row.frames_missed = found->second.missed;
        }
        dataset.trials.push_back(std::move(row));
    }
    analysis::derive_session_fields(dataset.trials);
    add_trial_gaze(trial_gaze, dataset.trials);
    return dataset;
}

}  // namespace monoplane::app
