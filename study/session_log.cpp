#include "study/session_log.h"

#include <algorithm>
#include <cmath>

#include "common/name_table.h"

namespace monoplane::study {
namespace {

// Stored in files: never change one (docs/data.md).
constexpr NameTable<SessionStatus> kSessionStatusNames = {
    {SessionStatus::Running, "running"},
    {SessionStatus::Paused, "paused"},
    {SessionStatus::Completed, "completed"},
    {SessionStatus::Aborted, "aborted"},
};

}  // namespace

std::string_view session_status_name(SessionStatus status) {
    return find_name(kSessionStatusNames, status, "unknown");
}

std::optional<SessionStatus> parse_session_status(std::string_view name) {
    return parse_name(kSessionStatusNames, name);
}

Result<void> MemorySessionLog::append_event(std::int64_t, const TrialEvent& event) {
    events_.push_back(event);
    return Ok{};
}

Result<void> MemorySessionLog::record_outcome(std::int64_t, int trial_index,
                                              const TrialOutcome& outcome) {
    if (!outcomes_.emplace(trial_index, outcome).second) {
        return Error{"trial " + std::to_string(trial_index) +
                     " is already decided; a recorded decision is never overwritten"};
    }
    return Ok{};
}

Result<void> MemorySessionLog::set_status(std::int64_t, SessionStatus status) {
    status_ = status;
    return Ok{};
}

Result<void> MemorySessionLog::record_answer(std::int64_t, int item, const std::string&,
                                             int answer) {
    answers_[item] = answer;  // asked again: the latest answer counts, as in the database
    return Ok{};
}

Result<void> MemorySessionLog::record_stimulus(std::int64_t, const ScheduledTrial& trial) {
    const std::string name = "trial " + std::to_string(trial.index);
    if (!trial.adaptive) return Error{name + " is not a staircase's trial; its m is scheduled"};
    if (!(std::isfinite(trial.mono_plane) && trial.mono_plane > 0.0)) {
        return Error{name + ": the chosen mono plane is not a positive distance"};
    }
    if (!adaptive_trials_.emplace(trial.index, trial).second) {
        return Error{name + " has its mono plane already; a chosen m is never changed"};
    }
    return Ok{};
}

Result<void> MemorySessionLog::add_note(std::int64_t, const SessionNote& note) {
    if (note.text.find_first_not_of(" \t\r\n") == std::string::npos) {
        return Error{"a note must not be empty"};
    }
    notes_.push_back(note);
    return Ok{};
}

Result<void> MemorySessionLog::record_press(std::int64_t, const ResponsePress& press) {
    MONOPLANE_TRY(check_press(press));
    presses_.push_back(press);
    return Ok{};
}

Result<RunStart> MemorySessionLog::begin_run(std::int64_t, const RunInfo& info) {
    std::optional<std::int64_t> last_ns;
    std::int64_t first_frame = 0;
    for (const TrialEvent& e : events_) {
        last_ns = std::max(last_ns.value_or(e.time_ns), e.time_ns);
        first_frame = std::max(first_frame, e.frame + 1);
    }
    const RunStart start = plan_run(++runs_, last_ns, first_frame, info.clock_start_ns);
    TrialEvent started;
    started.kind = EventKind::RunStarted;
    started.trial_index = -1;
    started.time_ns = start.start_ns;
    events_.push_back(started);
    return start;
}

std::string_view note_source_name(NoteSource source) {
    switch (source) {
        case NoteSource::Software:
            return "software";
        case NoteSource::Window:
            return "window";
        case NoteSource::Command:
            return "command";
    }
    return "invalid";
}

}  // namespace monoplane::study
