#include "study/trial_events.h"

#include <cstddef>

#include "common/name_table.h"

namespace monoplane::study {

namespace {

// These names are stored in databases and exports: never change one. The events table's CHECK
// (study/store_schema.cpp) lists them too, as the schema was created; a new kind needs a
// migration there.
constexpr NameTable<EventKind> kEventKindNames = {
    {EventKind::Shown, "shown"},
    {EventKind::Switched, "switched"},
    {EventKind::Confirmed, "confirmed"},
    {EventKind::Refused, "refused"},
    {EventKind::Paused, "paused"},
    {EventKind::Resumed, "resumed"},
    {EventKind::Aborted, "aborted"},
    {EventKind::InstructionsShown, "instructions_shown"},
    {EventKind::InstructionsConfirmed, "instructions_confirmed"},
    {EventKind::ReadyShown, "ready_shown"},
    {EventKind::ReadyConfirmed, "ready_confirmed"},
    {EventKind::BreakStarted, "break_started"},
    {EventKind::BreakEnded, "break_ended"},
    {EventKind::EndShown, "end_shown"},
    {EventKind::SessionAbandoned, "session_abandoned"},
    {EventKind::ProtocolChanged, "protocol_changed"},
    {EventKind::ProtocolTextChanged, "protocol_text_changed"},
    {EventKind::RunStarted, "run_started"},
};
static_assert(kEventKindNames.size() == static_cast<std::size_t>(EventKind::RunStarted) + 1,
              "every EventKind needs its stored name");

}  // namespace

std::string_view event_kind_name(EventKind kind) {
    // "unknown" only for a value outside the enum, which is a programming error.
    return find_name(kEventKindNames, kind, "unknown");
}

std::optional<EventKind> parse_event_kind(std::string_view name) {
    return parse_name(kEventKindNames, name);
}

bool is_screen_event(EventKind kind) {
    return kind >= EventKind::InstructionsShown && kind <= EventKind::EndShown;
}

bool is_session_event(EventKind kind) {
    return kind >= EventKind::SessionAbandoned;
}

bool is_trial_event(EventKind kind) {
    return kind <= EventKind::Aborted;
}

bool has_detail(EventKind kind) {
    return kind == EventKind::SessionAbandoned || kind == EventKind::ProtocolChanged ||
           kind == EventKind::ProtocolTextChanged;
}

std::string describe(const TrialEvent& e) {
    if (is_session_event(e.kind)) {
        return "session " + std::string(event_kind_name(e.kind)) + " t " +
               std::to_string(e.time_ns) + (e.detail.empty() ? "" : " reason " + e.detail);
    }
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
