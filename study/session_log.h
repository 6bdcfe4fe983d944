// Where a running session writes what happens (LiveSession): the study database in a real session
// (StudyStore: each write durable when it returns), memory in a simulation (`simulate`: thousands
// of sessions for a power analysis, no file). The session engine is the same either way.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "study/response_press.h"
#include "study/session_note.h"
#include "study/session_runs.h"
#include "study/trial_events.h"
#include "study/trial_state_machine.h"

namespace monoplane::study {

enum class SessionStatus { Running, Paused, Completed, Aborted };
// The database's names for a session's status ("running", ...), read both ways: parsing gives none
// for a name the table lacks.
std::string_view session_status_name(SessionStatus status);
std::optional<SessionStatus> parse_session_status(std::string_view name);

class SessionLog {
  public:
    virtual ~SessionLog() = default;
    virtual Result<void> append_event(std::int64_t session_id, const TrialEvent& event) = 0;
    virtual Result<void> record_outcome(std::int64_t session_id, int trial_index,
                                        const TrialOutcome& outcome) = 0;
    virtual Result<void> set_status(std::int64_t session_id, SessionStatus status) = 0;
    virtual Result<void> record_answer(std::int64_t session_id, int item, const std::string& text,
                                       int answer) = 0;
    // A staircase chose an adaptive trial's mono plane as the trial starts (trial.adaptive and
    // trial.mono_plane set): written before the trial's first event, so a resumed session shows
    // the trial at the same m. Refuses a trial that is not adaptive or not planned, a second
    // choice for one trial and an m that is not a finite positive number.
    virtual Result<void> record_stimulus(std::int64_t session_id, const ScheduledTrial& trial) = 0;
    // A note for whoever reviews the session (study_store.h SessionNote), durable on return.
    virtual Result<void> add_note(std::int64_t session_id, const SessionNote& note) = 0;
    // A run of the session begins (its start, or a resume): numbered after the earlier runs,
    // its frames after every frame number stored, its clock placed by plan_run; recorded with
    // a run_started event at its start, durable on return. Once per run, before its first
    // event.
    virtual Result<RunStart> begin_run(std::int64_t session_id, const RunInfo& info) = 0;
    // A press of the participant's controller or keys (study/response_press.h), durable on
    // return, whatever it changed. Refuses a key press without its key name and a controller
    // press with one.
    virtual Result<void> record_press(std::int64_t session_id, const ResponsePress& press) = 0;
};

// One session's log in memory. Refuses a second outcome for a trial, as the database does.
class MemorySessionLog final : public SessionLog {
  public:
    Result<void> append_event(std::int64_t session_id, const TrialEvent& event) override;
    Result<void> record_outcome(std::int64_t session_id, int trial_index,
                                const TrialOutcome& outcome) override;
    Result<void> set_status(std::int64_t session_id, SessionStatus status) override;
    Result<void> record_answer(std::int64_t session_id, int item, const std::string& text,
                               int answer) override;
    Result<void> record_stimulus(std::int64_t session_id, const ScheduledTrial& trial) override;
    Result<void> add_note(std::int64_t session_id, const SessionNote& note) override;
    Result<RunStart> begin_run(std::int64_t session_id, const RunInfo& info) override;
    Result<void> record_press(std::int64_t session_id, const ResponsePress& press) override;

    const std::vector<TrialEvent>& events() const { return events_; }
    const std::vector<ResponsePress>& presses() const { return presses_; }
    const std::vector<SessionNote>& notes() const { return notes_; }
    // The adaptive trials started, with their mono planes, by trial index.
    const std::map<int, ScheduledTrial>& adaptive_trials() const { return adaptive_trials_; }
    const std::map<int, TrialOutcome>& outcomes() const { return outcomes_; }  // by trial index
    const std::map<int, int>& answers() const { return answers_; }             // by item
    SessionStatus status() const { return status_; }

  private:
    std::vector<TrialEvent> events_;
    std::vector<SessionNote> notes_;
    std::vector<ResponsePress> presses_;
    std::map<int, TrialOutcome> outcomes_;
    std::map<int, int> answers_;
    std::map<int, ScheduledTrial> adaptive_trials_;
    SessionStatus status_ = SessionStatus::Running;
    int runs_ = 0;
};

}  // namespace monoplane::study
