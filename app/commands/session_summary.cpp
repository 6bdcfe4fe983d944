#include "app/commands/session_summary.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <map>

#include "app/commands/study_rows.h"

namespace monoplane::app {

namespace {

// The store's stamps are "YYYY-MM-DDTHH:MM:SSZ" (UTC); none for anything else.
std::optional<std::int64_t> parse_utc(const std::string& text) {
    std::tm tm{};
    char zone = 0;
    if (std::sscanf(text.c_str(), "%4d-%2d-%2dT%2d:%2d:%2d%c", &tm.tm_year, &tm.tm_mon, &tm.tm_mday,
                    &tm.tm_hour, &tm.tm_min, &tm.tm_sec, &zone) != 7 ||
        zone != 'Z')
        return std::nullopt;
    tm.tm_year -= 1900;
    tm.tm_mon -= 1;
    return static_cast<std::int64_t>(timegm(&tm));
}

Error store_error(const study::StudyStore& store, const Error& error) {
    return Error{"summary of a session in " + store.path().string() + ": " + error.message};
}

// An ended session's wall-clock time; an unended one's logged clock from its first to its last
// event or frame (the clock of events and frames is not UTC, so it cannot be set against
// started_utc; across a resume the pause between runs is not counted).
Result<void> fill_duration(const study::StudyStore& store, const study::SessionInfo& info,
                           const std::vector<study::FrameRecord>& frames, SessionSummary& s) {
    if (!info.ended_utc.empty()) {
        const auto start = parse_utc(info.started_utc);
        const auto end = parse_utc(info.ended_utc);
        if (start && end) {
            s.duration_basis = DurationBasis::Ended;
            s.duration_s = static_cast<double>(*end - *start);
        }
        return Ok{};
    }
    Result<std::vector<study::TrialEvent>> events = store.events(info.id);
    if (!events) return store_error(store, events.error());
    std::int64_t first = std::numeric_limits<std::int64_t>::max();
    std::int64_t last = std::numeric_limits<std::int64_t>::min();
    for (const study::TrialEvent& e : *events) {
        first = std::min(first, e.time_ns);
        last = std::max(last, e.time_ns);
    }
    for (const study::FrameRecord& f : frames) {
        first = std::min(first, f.display_time_ns);
        last = std::max(last, f.display_time_ns);
    }
    if (first <= last) {
        s.duration_basis = DurationBasis::LastLogged;
        s.duration_s = static_cast<double>(last - first) * 1e-9;
    }
    return Ok{};
}

// The frame log's share of missed frames, and the data trials `analyze` would flag: the same
// rows and rule as its report (trial_frame_counts, analysis::summarize_frame_timing).
void fill_frame_timing(const study::StudyStore& store, const study::SessionInfo& info,
                       const std::vector<study::TrialRecord>& trials,
                       const std::vector<study::FrameRecord>& frames, SessionSummary& s) {
    s.frame_log = !frames.empty();
    s.frames = static_cast<int>(frames.size());
    for (const study::FrameRecord& f : frames) s.frames_missed += f.missed ? 1 : 0;
    s.missed_share = s.frames > 0 ? static_cast<double>(s.frames_missed) / s.frames : 0.0;
    s.missed_frame_threshold = missed_frame_threshold(info);
    const std::map<int, TrialFrameCounts> counts = trial_frame_counts(frames);
    std::vector<analysis::TrialRow> rows;
    for (const study::TrialRecord& record : trials) {
        analysis::TrialRow row = trial_row(record, info, store.path().string(), "");
        row.missed_frame_threshold = s.missed_frame_threshold;
        if (const auto found = counts.find(record.trial.index); found != counts.end()) {
            row.frames_shown = found->second.shown;
            row.frames_missed = found->second.missed;
        }
        rows.push_back(std::move(row));
    }
    const analysis::FrameTimingSummary timing = analysis::summarize_frame_timing(rows);
    s.trials_with_frames = timing.trials_with_log;
    for (const analysis::TrialFrameTiming& t : timing.trials)
        if (t.flagged) s.flagged.push_back(t);
}

std::string percent(double share) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f %%", share * 100.0);
    return text;
}

std::string duration_text(const SessionSummary& s) {
    if (s.duration_basis == DurationBasis::Unknown) return "duration: not known (nothing logged)";
    const auto total = static_cast<long long>(std::llround(s.duration_s));
    std::string text = "duration: ";
    if (total >= 3600) text += std::to_string(total / 3600) + " h ";
    if (total >= 60) text += std::to_string(total / 60 % 60) + " min ";
    text += std::to_string(total % 60) + " s";
    return text + (s.duration_basis == DurationBasis::Ended
                       ? " (started to ended)"
                       : " (not ended: first to last logged event or frame)");
}

std::string frames_text(const SessionSummary& s) {
    if (!s.frame_log) return "missed frames: no frame log (headless session)";
    std::string text = "missed frames: " + std::to_string(s.frames_missed) + " of " +
                       std::to_string(s.frames) + " (" + percent(s.missed_share) + "); " +
                       std::to_string(s.flagged.size()) + " of " +
                       std::to_string(s.trials_with_frames) + " trials flagged above " +
                       percent(s.missed_frame_threshold);
    for (std::size_t i = 0; i < s.flagged.size(); ++i) {
        text += (i == 0 ? ": " : ", ") + std::string("trial ") +
                std::to_string(s.flagged[i].trial_index) + " (" + percent(s.flagged[i].share) + ")";
    }
    return text;
}

}  // namespace

Result<SessionSummary> summarize_session(const study::StudyStore& store, std::int64_t session_id) {
    Result<study::SessionInfo> info = store.session(session_id);
    if (!info) return store_error(store, info.error());
    Result<std::vector<study::RosterRow>> roster = store.roster();
    if (!roster) return store_error(store, roster.error());
    Result<std::vector<study::TrialRecord>> trials = store.trials(session_id);
    if (!trials) return store_error(store, trials.error());
    Result<std::vector<study::FrameRecord>> frames = store.frames(session_id);
    if (!frames) return store_error(store, frames.error());

    SessionSummary s;
    s.session_id = session_id;
    s.participant_code = info->participant_code;
    s.session_number = info->session_number;
    s.status = info->status;
    // The data trials as `study list` counts them, so the two never disagree.
    for (const study::RosterRow& row : *roster) {
        if (row.session_id != session_id) continue;
        s.trials_decided = row.trials_decided;
        s.trials_planned = row.trials_planned;
    }
    for (const study::TrialRecord& t : *trials) {
        if (!t.trial.practice) continue;
        ++s.practice_planned;
        s.practice_decided += t.decided ? 1 : 0;
    }
    MONOPLANE_TRY(fill_duration(store, *info, *frames, s));
    fill_frame_timing(store, *info, *trials, *frames, s);
    s.notes = info->notes;
    return s;
}

std::vector<std::string> session_summary_lines(const SessionSummary& s) {
    std::vector<std::string> lines;
    lines.push_back("session " + std::to_string(s.session_id) + " (participant " +
                    s.participant_code + ", session " + std::to_string(s.session_number) + ") " +
                    std::string(study::session_status_name(s.status)));
    std::string trials = "data trials: " + std::to_string(s.trials_decided) + " of " +
                         std::to_string(s.trials_planned) + " decided";
    if (s.practice_planned > 0) {
        trials += "; practice: " + std::to_string(s.practice_decided) + " of " +
                  std::to_string(s.practice_planned);
    }
    lines.push_back(trials);
    lines.push_back(duration_text(s));
    lines.push_back(frames_text(s));
    lines.push_back("notes: " + std::to_string(s.notes.size()));
    for (const study::SessionNote& note : s.notes) {
        std::string line = "  " + note.noted_utc;
        if (note.trial_index) line += ", trial " + std::to_string(*note.trial_index);
        line += ", " + std::string(study::note_source_name(note.source)) + ": " + note.text;
        lines.push_back(line);
    }
    return lines;
}

}  // namespace monoplane::app
