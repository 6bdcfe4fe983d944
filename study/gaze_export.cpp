// Eye gaze in the exports (docs/data.md, "Gaze"): `study export --format gaze-csv`, one row per
// frame with a gaze sample of every session that recorded gaze, with the sample's angles and the
// gaze point; and the per-trial gaze summaries the trial export (csv, json) carries. Gaze is
// personal data: only the sessions whose frames hold it are read for it (the roster's flag).
#include <map>
#include <optional>
#include <ostream>
#include <set>
#include <string>

#include "study/export.h"
#include "study/gaze_angles.h"

namespace monoplane::study {
namespace {

// The sessions of `data` whose frames hold gaze samples.
Result<std::set<std::int64_t>> sessions_with_gaze(const StudyStore& store, const ExportData& data) {
    Result<std::vector<RosterRow>> roster = store.roster();
    MONOPLANE_TRY(roster);
    std::set<std::int64_t> ids;
    for (const RosterRow& row : *roster)
        if (row.gaze && data.sessions.contains(row.session_id)) ids.insert(row.session_id);
    return ids;
}

std::string na_or_number(const std::optional<double>& value) {
    return value ? number_text(*value) : "NA";
}

std::string na_or_bool(const std::optional<bool>& value) {
    return value ? (*value ? "TRUE" : "FALSE") : "NA";
}

// The exported trials by session id and trial index.
using TrialsByIndex = std::map<std::pair<std::int64_t, int>, const ScheduledTrial*>;

// The alternative a frame showed: its trial's render mode for the label on screen, as the trial
// export names it; none on other screens.
std::optional<std::string> shown_mode(const TrialsByIndex& trials, std::int64_t session_id,
                                      const FrameRecord& frame) {
    if (!frame.trial_index || (frame.shown != "label1" && frame.shown != "label2"))
        return std::nullopt;
    const auto found = trials.find({session_id, *frame.trial_index});
    if (found == trials.end()) return std::nullopt;
    const ScheduledTrial& trial = *found->second;
    return std::string(
        render_mode_name(frame.shown == "label1" ? trial.label1_mode : trial.label2_mode));
}

// The gaze columns of one sample, from gaze_valid on (without the session id).
std::string gaze_cells(const GazeRecord& gaze, const std::optional<GazePointRecord>& point) {
    std::string cells = gaze.valid ? "TRUE" : "FALSE";
    // An invalid sample's direction means nothing (the store keeps none).
    const auto if_valid = [&](double value) {
        return gaze.valid ? number_text(value) : std::string("NA");
    };
    for (double component : gaze.direction) cells += ',' + if_valid(component);
    cells += ',' + if_valid(gaze_yaw_deg(gaze.direction));
    cells += ',' + if_valid(gaze_pitch_deg(gaze.direction));
    cells += ',' + if_valid(gaze_eccentricity_deg(gaze.direction));
    cells += ',' + na_or_number(point ? std::optional(point->error_arcmin) : std::nullopt);
    cells += ',' + na_or_number(point ? point->depth_m : std::nullopt);
    cells += ',' + na_or_bool(point ? std::optional(!point->depth_m) : std::nullopt);
    cells += ',' + na_or_number(point ? std::optional(point->mono_plane_m) : std::nullopt);
    cells += ',' + na_or_bool(point ? std::optional(point->beyond_mono_plane()) : std::nullopt);
    return cells;
}

}  // namespace

const std::vector<std::string_view>& gaze_export_columns() {
    static const std::vector<std::string_view> columns = {"participant",
                                                          "session",
                                                          "frame",
                                                          "trial_index",
                                                          "shown",
                                                          "display_time_s",
                                                          "shown_mode",
                                                          "gaze_valid",
                                                          "gaze_dir_x",
                                                          "gaze_dir_y",
                                                          "gaze_dir_z",
                                                          "gaze_yaw_deg",
                                                          "gaze_pitch_deg",
                                                          "gaze_eccentricity_deg",
                                                          "gaze_error_arcmin",
                                                          "gaze_depth_m",
                                                          "gaze_at_sky",
                                                          "gaze_mono_plane_m",
                                                          "gaze_beyond_m",
                                                          "session_id"};
    return columns;
}

Result<void> add_gaze_frames(const StudyStore& store, ExportData& data) {
    Result<std::set<std::int64_t>> ids = sessions_with_gaze(store, data);
    MONOPLANE_TRY(ids);
    for (std::int64_t id : *ids) {
        Result<std::vector<FrameRecord>> frames = store.frames(id);
        MONOPLANE_TRY(frames);
        data.frames.emplace(id, std::move(frames).value());
    }
    return Ok{};
}

Result<void> add_trial_gaze(const StudyStore& store, ExportData& data) {
    Result<std::set<std::int64_t>> ids = sessions_with_gaze(store, data);
    MONOPLANE_TRY(ids);
    for (std::int64_t id : *ids) {
        // One session's frames at a time: only their summary is kept.
        Result<std::vector<FrameRecord>> frames = store.frames(id);
        MONOPLANE_TRY(frames);
        std::map<int, TrialGaze>& trials = data.trial_gaze[id];
        for (TrialGaze& trial : summarize_trial_gaze(*frames))
            trials.emplace(trial.trial_index, std::move(trial));
    }
    return Ok{};
}

void write_gaze_csv(const ExportData& data, std::ostream& out) {
    out << csv_header(gaze_export_columns()) << '\n';
    TrialsByIndex trials;
    for (const TrialRecord& record : data.trials)
        trials.emplace(std::pair(record.session_id, record.trial.index), &record.trial);
    for (const auto& [session_id, frames] : data.frames) {
        const SessionInfo& session = data.sessions.at(session_id);
        const std::string identity =
            csv_text(session.participant_code) + ',' + std::to_string(session.session_number) + ',';
        for (const FrameRecord& f : frames) {
            if (!f.gaze) continue;  // gaze not recorded for this frame
            std::string line = identity + std::to_string(f.frame) + ',';
            line += (f.trial_index ? std::to_string(*f.trial_index) : "NA") + ',';
            line += csv_text(f.shown) + ',' + seconds_text(f.display_time_ns) + ',';
            const std::optional<std::string> mode = shown_mode(trials, session_id, f);
            line += (mode ? csv_text(*mode) : "NA") + ',';
            line += gaze_cells(*f.gaze, f.gaze_point) + ',' + std::to_string(session_id);
            out << line << '\n';
        }
    }
}

}  // namespace monoplane::study
