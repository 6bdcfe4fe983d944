// `--headset none`: a session run by the same engine as a headset session (LiveSession, with the
// simulated observer at its controls through ObserverInput, exactly as `--headset simulated`
// drives it) on a virtual display that presents a frame every 1/frame_rate_hz seconds of virtual
// time, as fast as the machine goes. So the refusal, switch and confirmation rules, the neutral
// screen, the protocol's screens (instructions, ready, breaks with their countdown, end: the
// observer reads and waits on the virtual clock too) and the questionnaire exist once
// (LiveSession and TrialStateMachine), and the crash tests of the headless path exercise the
// path participants use. Every event and outcome is written before the next frame is presented;
// a resumed session restarts at the screen where it stood or the first undecided trial.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "common/result.h"
#include "study/observer.h"
#include "study/protocol.h"
#include "study/schedule.h"
#include "study/session_log.h"
#include "study/study_store.h"

namespace monoplane::study {

struct RunOptions {
    double frame_rate_hz = 90.0;  // the virtual display's rate (headset none)
    // The neutral screen between trials and before the first (LiveOptions::neutral_ns).
    std::int64_t neutral_ns = 1'000'000'000;
    // Wall-clock sleep per event, so a test can kill the process at a random moment mid-session;
    // 0 runs as fast as possible (a 30-trial session in well under a second).
    std::int64_t pace_ns = 0;
    // Called after each durable write with a one-line description (tests, progress).
    std::function<void(const std::string&)> on_committed;
    // The largest projection error (pixels) of a trial's hybrid condition, for the observer.
    std::function<double(const ScheduledTrial&)> trial_error_px;
};

// Runs the stored session from where it stood through the questionnaire (and the end screen);
// returns the final status (Completed). The observer answers for the participant. Errors: a failed
// write, or a session that does not finish within a day of virtual time.
Result<SessionStatus> run_session(StudyStore& store, std::int64_t session_id,
                                  const Protocol& protocol, Observer& observer,
                                  const RunOptions& options);

// The same engine and observer over a schedule not in any database: the whole schedule into
// `log` (a MemorySessionLog for `simulate`'s power analysis). Errors as run_session's.
Result<void> run_simulated_session(SessionLog& log, const Protocol& protocol, Schedule schedule,
                                   Observer& observer, const RunOptions& options);

}  // namespace monoplane::study
