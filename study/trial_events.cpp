#include "study/trial_events.h"

namespace monoplane::study {

// These names are stored in databases and exports: never change one.
std::string_view event_kind_name(EventKind kind) {
    switch (kind) {
        case EventKind::Shown:
            return "shown";
        case EventKind::Switched:
            return "switched";
        case EventKind::Confirmed:
            return "confirmed";
        case EventKind::Refused:
            return "refused";
        case EventKind::Paused:
            return "paused";
        case EventKind::Resumed:
            return "resumed";
        case EventKind::Aborted:
            return "aborted";
        case EventKind::InstructionsShown:
            return "instructions_shown";
        case EventKind::InstructionsConfirmed:
            return "instructions_confirmed";
        case EventKind::ReadyShown:
            return "ready_shown";
        case EventKind::ReadyConfirmed:
            return "ready_confirmed";
        case EventKind::BreakStarted:
            return "break_started";
        case EventKind::BreakEnded:
            return "break_ended";
        case EventKind::EndShown:
            return "end_shown";
    }
    return "unknown";  // only for a value outside the enum, which is a programming error
}

std::optional<EventKind> parse_event_kind(std::string_view name) {
    for (int k = 0; k <= static_cast<int>(EventKind::EndShown); ++k) {
        if (event_kind_name(static_cast<EventKind>(k)) == name) return static_cast<EventKind>(k);
    }
    return std::nullopt;
}

bool is_screen_event(EventKind kind) {
    return kind >= EventKind::InstructionsShown;
}

std::string describe(const TrialEvent& e) {
    if (is_screen_event(e.kind)) {
        return "screen " + std::string(event_kind_name(e.kind)) + " page " +
               std::to_string(e.page) + " t " + std::to_string(e.time_ns) + " frame " +
               std::to_string(e.frame);
    }
    return "trial " + std::to_string(e.trial_index) + " " + std::string(event_kind_name(e.kind)) +
           " label " + std::to_string(e.label) + " t " + std::to_string(e.time_ns) + " frame " +
           std::to_string(e.frame);
}

}  // namespace monoplane::study
