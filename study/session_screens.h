// The protocol's screens around a session's trials (docs/protocols.md, "A study day"): which one
// comes before the next trial, and where a resumed session stood among them. Pure functions of
// the protocol, the schedule and the stored events, so the rules can be tested without a display
// and a resume derives its place from what was logged alone; LiveSession shows what they decide.
#pragma once

#include <cstdint>
#include <vector>

#include "study/frame_record.h"
#include "study/protocol_study_day.h"
#include "study/schedule.h"
#include "study/trial_events.h"

namespace monoplane::study {

enum class ScreenDue { None, Instructions, Ready, Break };

// What the participant has been through so far (kept by the running session, first recovered
// from the stored events on a resume).
struct ScreenProgress {
    int instructions_page = 0;     // the first instruction page not yet confirmed (all: read)
    bool ready_confirmed = false;  // the ready screen was confirmed
    bool break_taken = false;      // a break was shown since the last decision
};

// The screen shown before `next` (the trial about to start; null: no trial is left), after
// `previous` (the last data trial decided; null: none yet), with `data_decided` data trials
// decided in the session. Instructions until all pages are confirmed; the ready screen before
// the first data trial; a break between two data trials after every `every_trials` decided ones
// and/or where their blocks differ, once per gap, never before the first data trial or after
// the last.
ScreenDue screen_before_trial(const StudyDaySettings& day, const ScreenProgress& progress,
                              int data_decided, const ScheduledTrial* previous,
                              const ScheduledTrial* next);

// The indices of the data trials a break precedes when every trial of `schedule` is decided in
// order (no staircase slot skipped): the break plan the experimenter can expect.
std::vector<int> planned_breaks(const StudyDaySettings& day, const Schedule& schedule);

// Where a session stood among its screens, from its events in the order they were logged.
struct ScreenResume {
    ScreenProgress progress;  // instructions read so far, ready confirmed; break_taken: below
    int last_trial = -1;      // the trial of the last trial event (-1: none)
    // After the last trial event: a break that started and has not ended (shown again, for the
    // rest of its minimum time, its start logged again), or one that ended. Starts of one break
    // in several runs (no break_ended or trial event between them) are one break.
    bool break_open = false;
    bool break_ended = false;
    // break_open: how long it lasted as far as the log tells: the latest time logged at or after
    // its first break_started, minus that start's time (the runs share one time axis).
    std::int64_t break_elapsed_ns = 0;
};
// `frames`: the session's frame log (headset sessions log a frame's display time at least every
// 30 frames, also during a break, when no event is written): a frame at or after break_started's
// frame counts as logged time of the break too.
ScreenResume resume_screens(const std::vector<TrialEvent>& events, int instruction_pages,
                            const std::vector<FrameRecord>& frames = {});

// A break's minimum duration left after `elapsed_ns` of it: min_s minus the elapsed time,
// clamped to [0, min_s].
std::int64_t break_remaining_ns(const BreakSettings& breaks, std::int64_t elapsed_ns);

}  // namespace monoplane::study
