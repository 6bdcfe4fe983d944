// What happens in a trial, as logged: each event carries the monotonic time and the index of the
// frame at which it became visible (or, for input, the time it arrived).
#pragma once

#include <cstdint>
#include <optional>
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
    // The participant's screens (protocol [[instructions]], [ready], [breaks], [end]): not
    // part of a trial (trial_index -1, stored as NULL), `page` says which instruction page.
    InstructionsShown,      // an instruction page became visible (again, after back)
    InstructionsConfirmed,  // the participant confirmed a page (the last one: instructions read)
    ReadyShown,             // the ready screen became visible (after practice)
    ReadyConfirmed,
    BreakStarted,  // a break screen became visible; its countdown starts
    BreakEnded,    // the participant confirmed after the countdown
    EndShown,      // the end screen became visible
    // Decisions about the whole session (trial_index -1, stored as NULL), with the reason the
    // experimenter gave in `detail`:
    SessionAbandoned,     // an interrupted session ended for good (`study run --abandon`)
    ProtocolChanged,      // this session's design differs from the participant's earlier ones
    ProtocolTextChanged,  // only the protocol's text (comments, instructions) differs
    RunStarted,           // a run of the session began: its start, or a resume (no detail)
};

// True for the kinds above that belong to a screen, not to a trial.
bool is_screen_event(EventKind kind);
// True for the decisions about the whole session (SessionAbandoned and after).
bool is_session_event(EventKind kind);
// True for the kinds that belong to a trial (and name it); the others have trial index -1.
bool is_trial_event(EventKind kind);
// True for the kinds that carry a reason in `detail`.
bool has_detail(EventKind kind);

std::string_view event_kind_name(EventKind kind);
// The kind a stored name stands for; none for a name no version wrote.
std::optional<EventKind> parse_event_kind(std::string_view name);

struct TrialEvent {
    EventKind kind = EventKind::Shown;
    int trial_index = 0;       // -1 for screen events
    int label = 0;             // 1 or 2 where it applies, else 0
    std::int64_t time_ns = 0;  // monotonic clock
    std::int64_t frame = -1;   // frame index at which the change became visible; -1: none
    int page = -1;             // instruction events: the page, 0-based; else -1
    std::string detail = {};   // has_detail kinds: the reason given; else empty
};

// One line for logs and traces: "trial 3 switched label 2 t 123 frame 11" (the crash test
// parses it; keep the form); a screen event reads "screen instructions_shown page 0 t 123
// frame 11".
std::string describe(const TrialEvent& event);

}  // namespace monoplane::study
