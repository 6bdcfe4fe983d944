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
    }
    return "unknown";  // only for a value outside the enum, which is a programming error
}

std::string describe(const TrialEvent& e) {
    return "trial " + std::to_string(e.trial_index) + " " + std::string(event_kind_name(e.kind)) +
           " label " + std::to_string(e.label) + " t " + std::to_string(e.time_ns) + " frame " +
           std::to_string(e.frame);
}

}  // namespace monoplane::study
