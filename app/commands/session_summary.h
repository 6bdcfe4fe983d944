// What one session came to, as the experimenter sees it once it ends (`study run|resume` print
// it; the launcher shows it): data trials decided of planned, the duration, the share of missed
// frames and the trials `analyze` flags for them, and the session's notes. In the app because it
// joins the study database (study/) with the analysis's frame-timing rule (analysis/), which
// neither library may include of the other (docs/architecture.md).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "analysis/frame_timing.h"
#include "common/result.h"
#include "study/session_log.h"
#include "study/session_note.h"
#include "study/study_store.h"

namespace monoplane::app {

// Where a session's duration was measured to.
enum class DurationBasis {
    Ended,       // started_utc to ended_utc (wall clock, whole seconds)
    LastLogged,  // not ended: the session's logged clock, first to last event or frame
    Unknown,     // not ended and nothing logged, or a stored time that does not parse
};

struct SessionSummary {
    std::int64_t session_id = 0;
    std::string participant_code;
    int session_number = 1;
    study::SessionStatus status = study::SessionStatus::Running;
    // Data trials, as `study list` counts them (a staircase's planned: its most); practice apart.
    int trials_decided = 0;
    int trials_planned = 0;
    int practice_decided = 0;
    int practice_planned = 0;
    DurationBasis duration_basis = DurationBasis::Unknown;
    double duration_s = 0.0;  // 0 when the basis is Unknown
    // The frame log (headset sessions only; a headless session has none: frame_log false).
    bool frame_log = false;
    int frames = 0;         // every logged (displayed) frame, screens between trials included
    int frames_missed = 0;  // of those, the ones whose display slot went without a new frame
    double missed_share = 0.0;
    double missed_frame_threshold = 0.05;  // the protocol's, as the session ran it
    // Data trials with a logged frame, and those among them whose missed share exceeds the
    // threshold (analysis::summarize_frame_timing, the rule of `analyze`'s report).
    int trials_with_frames = 0;
    std::vector<analysis::TrialFrameTiming> flagged;
    std::vector<study::SessionNote> notes;
};

// Summarises session `session_id` of `store` as the store holds it now. May be called at any
// time, also while the session runs (it then describes the part logged so far). Errors: an
// unknown session or an unreadable database, with the database named.
Result<SessionSummary> summarize_session(const study::StudyStore& store, std::int64_t session_id);

// The summary as lines of text without newlines, for a terminal or a window:
//   session 3 (participant P01, session 1) completed
//   data trials: 6 of 6 decided; practice: 1 of 1
//   duration: 2 min 5 s (started to ended)
//   missed frames: 12 of 1500 (0.8 %); 1 of 6 trials flagged above 5 %: trial 4 (9.1 %)
//   notes: 1
//     2024-05-01T10:00:00Z, trial 2, window: headset slipped
// "frames: no frame log (headless session)" when there is none. Pure.
std::vector<std::string> session_summary_lines(const SessionSummary& summary);

}  // namespace monoplane::app
