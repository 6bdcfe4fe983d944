// StudyStore::begin_session: a participant's session in one transaction with its schedule, its
// scene files and, where an earlier session is given up or the protocol changed, the record of
// that. Everything is checked before the transaction, and what plan_session saw is read again
// inside it.
#include "study/study_store.h"

#include <functional>

#include "common/utc_time.h"
#include "study/participant_code.h"
#include "study/planned_trial_store.h"
#include "study/scene_file_store.h"
#include "study/session_admission.h"
#include "study/session_uuid.h"
#include "study/store_impl.h"
#include "study/store_participants.h"
#include "study/store_validation.h"
#include "study/store_values.h"

namespace monoplane::study {
namespace {

using sqlite::Connection;
using sqlite::Statement;
using sqlite::Transaction;

Result<std::int64_t> insert_session(const Connection& db, std::int64_t participant_id,
                                    const SessionInfo& info, const Schedule& schedule) {
    Result<Statement> session = Statement::prepare(
        db,
        "INSERT INTO sessions (participant_id, protocol_name, protocol_hash, protocol_text, "
        "seed, block_order, software_version, hmd, runtime, device, observer, started_utc, "
        "status, render_anti_aliasing, render_ssao, render_detail, procedure, session_number, "
        "session_uuid) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    MONOPLANE_TRY(session);
    Statement& s = session.value();
    s.bind(1, participant_id)
        .bind(2, info.protocol_name)
        .bind(3, stored_hash_text(info.protocol_hash));
    s.bind(4, info.protocol_text).bind(5, std::to_string(schedule.seed));
    s.bind(6, join_scenes(schedule.block_order)).bind(7, info.software_version);
    s.bind(8, info.hmd).bind(9, info.runtime).bind(10, info.device).bind(11, info.observer);
    s.bind(12, info.started_utc.empty() ? utc_now_iso8601() : info.started_utc);
    s.bind(13, session_status_name(info.status));
    s.bind(14, info.render.anti_aliasing).bind(15, info.render.ssao);
    if (info.render.detail.empty())
        s.bind_null(16);
    else
        s.bind(16, info.render.detail);
    s.bind(17, procedure_name(schedule_procedure(schedule))).bind(18, info.session_number);
    s.bind(19, info.session_uuid.empty() ? random_session_uuid() : info.session_uuid);
    MONOPLANE_TRY(s.run("adding " + numbered_session(info.session_number) + " of participant '" +
                        info.participant_code + "'"));
    return sqlite3_last_insert_rowid(db.get());
}

Result<void> insert_trials(const Connection& db, std::int64_t session_id,
                           const Schedule& schedule) {
    Result<Statement> trial = Statement::prepare(
        db,
        "INSERT INTO trials (session_id, trial_index, practice, block, scene, mono_plane, "
        "label1_alternative, label1_mode, label2_mode, repetition) "
        "VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
    MONOPLANE_TRY(trial);
    for (const ScheduledTrial& t : schedule.trials) {
        if (t.adaptive) continue;  // a plan until it starts (write_planned_trials)
        Statement& s = trial.value();
        s.reset();
        s.bind(1, session_id).bind(2, t.index).bind(3, t.practice ? 1 : 0).bind(4, t.block);
        s.bind(5, t.scene).bind(6, t.mono_plane).bind(7, t.label1_alternative);
        s.bind(8, render_mode_name(t.label1_mode)).bind(9, render_mode_name(t.label2_mode));
        s.bind(10, t.repetition);
        MONOPLANE_TRY(s.run("storing the schedule"));
    }
    return Ok{};
}

// Ends an interrupted session for good (`study run --abandon`): status aborted, an end time, and
// the reason as an event at the session's last known time (its time axis goes on there).
Result<void> abandon_session(const Connection& db, std::int64_t session_id,
                             const std::string& reason) {
    Result<Statement> end = Statement::prepare(
        db, "UPDATE sessions SET status = 'aborted', ended_utc = ? WHERE id = ?");
    MONOPLANE_TRY(end);
    end.value().bind(1, utc_now_iso8601()).bind(2, session_id);
    MONOPLANE_TRY(
        end.value().run("ending session " + std::to_string(session_id) + " as abandoned"));
    Result<Statement> event = Statement::prepare(
        db,
        "INSERT INTO events (session_id, trial_index, kind, label, time_ns, frame, detail) "
        "SELECT ?1, NULL, 'session_abandoned', 0, coalesce(max(time_ns), 0), -1, ?2 FROM events "
        "WHERE session_id = ?1");
    MONOPLANE_TRY(event);
    event.value().bind(1, session_id).bind(2, reason);
    return event.value().run("recording why session " + std::to_string(session_id) +
                             " was abandoned");
}

// The new session's record of a change of protocol (admit_session), at its start.
Result<void> record_protocol_event(const Connection& db, std::int64_t session_id,
                                   const TrialEvent& e) {
    Result<Statement> stmt = Statement::prepare(
        db,
        "INSERT INTO events (session_id, trial_index, kind, label, time_ns, frame, detail) "
        "VALUES (?, NULL, ?, 0, 0, -1, ?)");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id).bind(2, event_kind_name(e.kind)).bind(3, e.detail);
    return stmt.value().run("recording the change of protocol");
}

}  // namespace

Result<std::int64_t> StudyStore::begin_session(
    const SessionInfo& info, const Schedule& schedule,
    const std::function<Result<void>(std::int64_t)>& before_commit) {
    const Connection& db = impl_->db;
    MONOPLANE_TRY(check_participant_code(info.participant_code));
    if (info.session_number < 1)
        return Error{"session number " + std::to_string(info.session_number) +
                     " for participant '" + info.participant_code +
                     "': sessions are numbered from 1"};
    if (info.session_number != schedule.session_number)
        return Error{"the schedule was made for " + numbered_session(schedule.session_number) +
                     " but participant '" + info.participant_code + "' is to begin " +
                     numbered_session(info.session_number) + "; make the schedule again."};
    if (Result<void> valid = validate_schedule(schedule); !valid)
        return Error{"cannot store the schedule: " + valid.error().message};
    if (Result<void> valid = validate_scene_files(info.scene_files, schedule); !valid)
        return Error{"cannot store the scene files: " + valid.error().message};
    if (Result<void> valid = validate_variables(info.variables); !valid)
        return Error{"cannot store the participant's variables: " + valid.error().message};

    Result<Transaction> tx = Transaction::begin(db, "starting a session");
    MONOPLANE_TRY(tx);
    // Read again under the write lock: what plan_session saw may have changed since. First, so
    // that a participant whose session another process just began hears that it is running.
    Result<std::vector<EarlierSession>> earlier = earlier_sessions(info.participant_code);
    MONOPLANE_TRY(earlier);
    Result<Admission> admission = admit_session(
        AdmissionContext{.database = impl_->file.string(),
                         .participant_code = info.participant_code},
        *earlier,
        ProtocolVersion{
            .name = info.protocol_name, .text = info.protocol_text, .hash = info.protocol_hash},
        info.decisions);
    MONOPLANE_TRY(admission);
    Result<std::int64_t> participant_id = admit_participant(db, info, schedule);
    MONOPLANE_TRY(participant_id);
    if (admission->abandon_id)
        MONOPLANE_TRY(abandon_session(db, *admission->abandon_id, info.decisions.abandon_reason));
    Result<std::int64_t> session_id = insert_session(db, *participant_id, info, schedule);
    MONOPLANE_TRY(session_id);
    if (admission->protocol_event)
        MONOPLANE_TRY(record_protocol_event(db, *session_id, *admission->protocol_event));
    MONOPLANE_TRY(insert_trials(db, *session_id, schedule));
    MONOPLANE_TRY(write_planned_trials(db, *session_id, schedule));
    MONOPLANE_TRY(write_scene_files(db, *session_id, info.scene_files));
    if (before_commit) MONOPLANE_TRY(before_commit(*session_id));
    MONOPLANE_TRY(tx.value().commit("starting a session"));
    return *session_id;
}

}  // namespace monoplane::study
