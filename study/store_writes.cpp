// StudyStore's writes during a session: events, outcomes, status, answers, a staircase's choice,
// notes and runs, each durable when it returns (one transaction that carries the frames queued so
// far), and the frame log's queue itself. A recorded decision is never overwritten.
#include "study/study_store.h"

#include <unistd.h>

#include <algorithm>
#include <string>

#include "common/utc_time.h"
#include "study/frame_queue.h"
#include "study/planned_trial_store.h"
#include "study/scene_file_store.h"  // write_session_note
#include "study/session_hold.h"
#include "study/session_run_store.h"
#include "study/store_impl.h"
#include "study/store_validation.h"

namespace monoplane::study {
namespace {

using sqlite::Connection;
using sqlite::Statement;
using sqlite::Transaction;

// Characters as the person typing them counts them: UTF-8 code points, not bytes.
std::size_t code_points(std::string_view text) {
    return static_cast<std::size_t>(std::ranges::count_if(
        text, [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

}  // namespace

void StudyStore::queue_frame(std::int64_t session_id, const FrameRecord& frame) {
    impl_->frames.add(session_id, frame);
}

void StudyStore::queue_frame_gpu_ms(std::int64_t session_id, std::int64_t frame, double gpu_ms,
                                    std::optional<double> mono_plane) {
    impl_->frames.add_gpu_ms(session_id, frame, gpu_ms, mono_plane);
}

Result<void> StudyStore::flush_frames() {
    if (impl_->frames.empty()) return Ok{};
    Result<Transaction> tx = Transaction::begin(impl_->db, "writing the frame log");
    MONOPLANE_TRY(tx);
    MONOPLANE_TRY(impl_->write_queued_frames());
    return impl_->commit_written(tx.value(), "writing the frame log");
}

Result<void> StudyStore::append_event(std::int64_t session_id, const TrialEvent& event) {
    MONOPLANE_TRY(validate_event(event));
    // One transaction (with the queued frames); with synchronous = FULL it is on disk when this
    // returns.
    Result<Transaction> tx = Transaction::begin(impl_->db, "appending an event");
    MONOPLANE_TRY(tx);
    MONOPLANE_TRY(impl_->write_queued_frames());
    Result<Statement> stmt = Statement::prepare(
        impl_->db,
        "INSERT INTO events (session_id, trial_index, kind, label, time_ns, frame, page, detail) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
    MONOPLANE_TRY(stmt);
    const bool screen = !is_trial_event(event.kind);
    Statement& s = stmt.value();
    s.bind(1, session_id);
    if (screen)
        s.bind_null(2);  // a screen is no trial
    else
        s.bind(2, event.trial_index);
    s.bind(3, event_kind_name(event.kind)).bind(4, event.label).bind(5, event.time_ns);
    s.bind(6, event.frame);
    if (is_instruction_event(event.kind))
        s.bind(7, event.page);
    else
        s.bind_null(7);
    if (has_detail(event.kind))
        s.bind(8, event.detail);
    else
        s.bind_null(8);
    const std::string what =
        "appending a '" + std::string(event_kind_name(event.kind)) + "' event " +
        (screen ? std::string("(no trial)") : "for trial " + std::to_string(event.trial_index)) +
        " of session " + std::to_string(session_id) + " (the session" +
        (screen ? "" : " and trial") + " must exist)";
    MONOPLANE_TRY(s.run(what));
    return impl_->commit_written(tx.value(), what);
}

Result<void> StudyStore::record_outcome(std::int64_t session_id, int trial_index,
                                        const TrialOutcome& outcome) {
    const Connection& db = impl_->db;
    const std::string trial_name =
        "trial " + std::to_string(trial_index) + " of session " + std::to_string(session_id);
    if (outcome.choice != 1 && outcome.choice != 2)
        return Error{"outcome of " + trial_name + ": choice " + std::to_string(outcome.choice) +
                     " is not label 1 or 2"};
    if (outcome.switches < 0 || outcome.time_on_label_ns[0] < 0 ||
        outcome.time_on_label_ns[1] < 0 || outcome.decision_time_ns < 0)
        return Error{"outcome of " + trial_name + ": switches and times must not be negative"};
    if (outcome.runs < 1)
        return Error{"outcome of " + trial_name + ": " + std::to_string(outcome.runs) +
                     " runs; the run that decided it is one"};

    Result<Transaction> tx = Transaction::begin(db, "recording the outcome of " + trial_name);
    MONOPLANE_TRY(tx);
    Result<Statement> trial = Statement::prepare(db,
                                                 "SELECT label1_mode, label2_mode, decided FROM "
                                                 "trials WHERE session_id = ? AND trial_index = ?");
    MONOPLANE_TRY(trial);
    trial.value().bind(1, session_id).bind(2, trial_index);
    Result<bool> found = trial.value().step("recording the outcome of " + trial_name);
    MONOPLANE_TRY(found);
    if (!*found) return Error{"no " + trial_name + " in study database '" + db.path() + "'"};
    // A decision is data: never overwritten, and consistent with the blind assignment.
    if (trial->int64(2) != 0)
        return Error{trial_name + " is already decided; a recorded decision is never overwritten"};
    const std::string label_mode = trial->text(outcome.choice == 1 ? 0 : 1);
    if (label_mode != render_mode_name(outcome.chosen_mode))
        return Error{"outcome of " + trial_name + ": chosen mode '" +
                     std::string(render_mode_name(outcome.chosen_mode)) + "' is not label " +
                     std::to_string(outcome.choice) + "'s mode '" + label_mode + "'"};

    Result<Statement> update = Statement::prepare(
        db,
        "UPDATE trials SET decided = 1, choice = ?, chosen_mode = ?, valid = ?, switches = ?, "
        "time_label1_ns = ?, time_label2_ns = ?, decision_time_ns = ?, decided_utc = ?, "
        "runs = ? WHERE session_id = ? AND trial_index = ?");
    MONOPLANE_TRY(update);
    update.value()
        .bind(1, outcome.choice)
        .bind(2, render_mode_name(outcome.chosen_mode))
        .bind(3, outcome.valid ? 1 : 0)
        .bind(4, outcome.switches)
        .bind(5, outcome.time_on_label_ns[0])
        .bind(6, outcome.time_on_label_ns[1])
        .bind(7, outcome.decision_time_ns)
        .bind(8, utc_now_iso8601())
        .bind(9, outcome.runs)
        .bind(10, session_id)
        .bind(11, trial_index);
    MONOPLANE_TRY(update.value().run("recording the outcome of " + trial_name));
    MONOPLANE_TRY(impl_->write_queued_frames());
    return impl_->commit_written(tx.value(), "recording the outcome of " + trial_name);
}

Result<void> StudyStore::set_status(std::int64_t session_id, SessionStatus status) {
    const bool ended = status == SessionStatus::Completed || status == SessionStatus::Aborted;
    Result<Transaction> tx = Transaction::begin(impl_->db, "setting a session's status");
    MONOPLANE_TRY(tx);
    MONOPLANE_TRY(impl_->write_queued_frames());
    Result<Statement> stmt =
        Statement::prepare(impl_->db, "UPDATE sessions SET status = ?, ended_utc = ? WHERE id = ?");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_status_name(status));
    if (ended)
        stmt.value().bind(2, utc_now_iso8601());
    else
        stmt.value().bind_null(2);  // resumed: no longer ended
    stmt.value().bind(3, session_id);
    MONOPLANE_TRY(stmt.value().run("setting the status of session " + std::to_string(session_id)));
    if (sqlite3_changes(impl_->db.get()) == 0) return impl_->no_session(session_id);
    return impl_->commit_written(tx.value(), "setting a session's status");
}

Result<void> StudyStore::record_answer(std::int64_t session_id, int item, const std::string& text,
                                       int answer) {
    if (item < 0) return Error{"questionnaire item " + std::to_string(item) + " is negative"};
    if (answer < 1)
        return Error{"questionnaire answer " + std::to_string(answer) + " to item " +
                     std::to_string(item) + " is below 1 (Likert answers count from 1)"};
    Result<Transaction> tx = Transaction::begin(impl_->db, "recording a questionnaire answer");
    MONOPLANE_TRY(tx);
    MONOPLANE_TRY(impl_->require_session(session_id));
    // Asked again after a resume: the latest answer counts.
    Result<Statement> stmt = Statement::prepare(
        impl_->db,
        "INSERT INTO answers (session_id, item, text, answer, answered_utc) "
        "VALUES (?, ?, ?, ?, ?) ON CONFLICT (session_id, item) DO UPDATE SET "
        "text = excluded.text, answer = excluded.answer, answered_utc = excluded.answered_utc");
    MONOPLANE_TRY(stmt);
    stmt.value()
        .bind(1, session_id)
        .bind(2, item)
        .bind(3, text)
        .bind(4, answer)
        .bind(5, utc_now_iso8601());
    MONOPLANE_TRY(stmt.value().run("recording a questionnaire answer"));
    MONOPLANE_TRY(impl_->write_queued_frames());
    return impl_->commit_written(tx.value(), "recording a questionnaire answer");
}

Result<void> StudyStore::record_stimulus(std::int64_t session_id, const ScheduledTrial& trial) {
    if (!trial.adaptive)
        return Error{"trial " + std::to_string(trial.index) +
                     " is not a staircase's trial; its m is scheduled"};
    Result<Transaction> tx = Transaction::begin(impl_->db, "recording a staircase's choice");
    MONOPLANE_TRY(tx);
    MONOPLANE_TRY(start_planned_trial(impl_->db, session_id, trial.index, trial.mono_plane));
    MONOPLANE_TRY(impl_->write_queued_frames());
    return impl_->commit_written(tx.value(), "recording a staircase's choice");
}

Result<void> StudyStore::check_note(std::int64_t session_id, const SessionNote& note) const {
    const std::string where =
        "note for session " + std::to_string(session_id) + " in '" + impl_->db.path() + "'";
    if (note.text.find_first_not_of(" \t\r\n") == std::string::npos)
        return Error{where + " is empty: a note must say something"};
    if (const std::size_t length = code_points(note.text); length > 10'000)
        return Error{where + " has " + std::to_string(length) +
                     " characters; at most 10,000 are kept: shorten it or split it in two"};
    if (note.runtime_time_ns && *note.runtime_time_ns < 0)
        return Error{where + ": the session time " + std::to_string(*note.runtime_time_ns) +
                     " ns is negative"};
    if (note.trial_index && *note.trial_index < 0)
        return Error{where + ": trial " + std::to_string(*note.trial_index) + " is negative"};
    return impl_->require_session(session_id);
}

Result<void> StudyStore::add_note(std::int64_t session_id, const SessionNote& note) {
    MONOPLANE_TRY(check_note(session_id, note));
    SessionNote stamped = note;
    if (stamped.noted_utc.empty()) stamped.noted_utc = utc_now_iso8601();
    // Durable at once, with the frames queued so far: the note is as safe as a decision.
    Result<Transaction> tx = Transaction::begin(impl_->db, "adding a session note");
    MONOPLANE_TRY(tx);
    MONOPLANE_TRY(impl_->require_session(session_id));
    MONOPLANE_TRY(write_session_note(impl_->db, session_id, stamped));
    MONOPLANE_TRY(impl_->write_queued_frames());
    return impl_->commit_written(tx.value(), "adding a session note");
}

Result<void> StudyStore::add_session_note(std::int64_t session_id, const std::string& text) {
    SessionNote note;
    note.text = text;
    note.source = NoteSource::Software;
    return add_note(session_id, note);
}

Result<RunStart> StudyStore::begin_run(std::int64_t session_id, const RunInfo& info) {
    const RunRecord who{.started_utc = utc_now_iso8601(),
                        .host = host_name(),
                        .pid = static_cast<long>(::getpid()),
                        .runtime = info.runtime};
    Result<Transaction> tx = Transaction::begin(impl_->db, "beginning a run of a session");
    MONOPLANE_TRY(tx);
    MONOPLANE_TRY(impl_->require_session(session_id));
    // The queued frames first: they are the earlier run's, and the new run's clock starts after
    // them (write_run reads the latest time stored).
    MONOPLANE_TRY(impl_->write_queued_frames());
    Result<RunStart> start = write_run(impl_->db, session_id, info, who);
    MONOPLANE_TRY(start);
    MONOPLANE_TRY(impl_->commit_written(tx.value(), "beginning a run of a session"));
    return start;
}

Result<std::vector<RunRecord>> StudyStore::runs(std::int64_t session_id) const {
    MONOPLANE_TRY(impl_->require_session(session_id));
    return read_runs(impl_->db, session_id);
}

}  // namespace monoplane::study
