// Runs a session's remaining trials: the schedule's trials in order, each through the 2AFC state
// machine, driven by an input source (a simulated observer here; a participant's controller with
// a headset), every event and outcome written to the store before the next frame is presented,
// then the questionnaire, then the session's status. Crash-safe by construction: nothing is kept
// only in memory across a frame, and a resumed session restarts at the first undecided trial.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "common/result.h"
#include "study/observer.h"
#include "study/protocol.h"
#include "study/study_store.h"

namespace monoplane::study {

struct RunOptions {
    double frame_rate_hz = 90.0;  // the virtual display's rate (headset none)
    // Wall-clock sleep per event, so a test can kill the process at a random moment mid-session;
    // 0 runs as fast as possible (a 30-trial session in well under a second).
    std::int64_t pace_ns = 0;
    // Called after each durable write with a one-line description (tests, progress).
    std::function<void(const std::string&)> on_committed;
    // The largest projection error (pixels) of a trial's hybrid condition, for the observer.
    std::function<double(const ScheduledTrial&)> trial_error_px;
};

// Runs trials first_trial.. of the stored schedule and the questionnaire; returns the final
// status (Completed). The observer answers for the participant (headset none).
Result<SessionStatus> run_session(StudyStore& store, std::int64_t session_id,
                                  const Protocol& protocol, Observer& observer,
                                  const RunOptions& options);

}  // namespace monoplane::study
