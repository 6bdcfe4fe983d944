// What happens in a trial, as logged: each event carries the monotonic time and the index of the
// frame at which it became visible (or, for input, the time it arrived).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace monoplane::study {

enum class EventKind {
    Shown,      // a label became visible (the first one: label 1 at trial start)
    Switched,   // the participant switched; `label` is the one now visible
    Confirmed,  // the participant confirmed the visible label: the trial's choice
    Refused,    // a confirmation refused because both labels were not yet seen
    Paused,     // by the experimenter
    Resumed,
    Aborted,  // by the experimenter: the session ends, the trial stays undecided
};

std::string_view event_kind_name(EventKind kind);

struct TrialEvent {
    EventKind kind = EventKind::Shown;
    int trial_index = 0;
    int label = 0;             // 1 or 2 where it applies, else 0
    std::int64_t time_ns = 0;  // monotonic clock
    std::int64_t frame = -1;   // frame index at which the change became visible; -1: none
};

// One line for logs and traces: "trial 3 switched label 2 t 123 frame 11" (the crash test
// parses it; keep the form).
std::string describe(const TrialEvent& event);

}  // namespace monoplane::study
