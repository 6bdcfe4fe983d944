// What a session's stored events (and frame log) show of each trial, run by run: how many runs
// showed it, its switches, the time each label was visible and its viewing time. A trial
// interrupted by a crash, a lost runtime or an abort is shown again from label 1 when the session
// resumes; its outcome then counts what every run showed (LiveSession gives this to the trial's
// state machine), so nothing seen before the interruption is lost from the outcome and the
// export (docs/data.md, table trials).
//
// A run of a trial begins with its `shown` event (the machine logs one per run) and ends at its
// confirmation, its abort, or the last record of it before the next `run_started` (an
// interruption): its last event, or the last frame the frame log holds of it. The time after that
// record, and the interruption itself, count nowhere: the record ends there.
#pragma once

#include <cstdint>
#include <map>
#include <vector>

#include "study/frame_record.h"
#include "study/trial_events.h"

namespace monoplane::study {

struct TrialRuns {
    int runs = 0;      // runs in which a label of the trial became visible
    int switches = 0;  // `switched` events of all of them
    std::int64_t time_on_label_ns[2] = {0, 0};
    // Each run's first visibility to its confirmation (or the end of its record), pauses
    // excluded, summed over the runs: equal to the two labels' times.
    std::int64_t viewing_ns = 0;
};

// By trial index, every trial with a `shown` event, from the session's events in the order they
// were logged and its frame log (none headless). Any time.
std::map<int, TrialRuns> trial_runs(const std::vector<TrialEvent>& events,
                                    const std::vector<FrameRecord>& frames = {});

}  // namespace monoplane::study
