// StudyStore's reads of a session: its schedule as stored (trials begun and a staircase's slots
// not begun yet), its record, trials, events, frames and questionnaire answers, and lookups of
// participants and sessions. Rows written by a newer monoplane (an unknown mode, kind or type)
// are refused by name, never misread.
#include "study/study_store.h"

#include <cmath>
#include <string>

#include "study/frame_queue.h"
#include "study/planned_trial_store.h"
#include "study/scene_file_store.h"
#include "study/store_impl.h"
#include "study/store_participants.h"
#include "study/store_values.h"

namespace monoplane::study {
namespace {

using sqlite::Connection;
using sqlite::query_int;
using sqlite::Statement;

// The trial columns in the order read_trial() expects; the 17th says whether the row is a
// started slot of a staircase (planned_trial_store.h), the 18th is the repetition, the 19th the
// runs that showed the trial.
constexpr std::string_view kTrialColumns =
    "t.trial_index, t.practice, t.block, t.scene, t.mono_plane, t.label1_alternative, "
    "t.label1_mode, t.label2_mode, t.decided, t.choice, t.chosen_mode, t.valid, t.switches, "
    "t.time_label1_ns, t.time_label2_ns, t.decision_time_ns, EXISTS (SELECT 1 FROM "
    "planned_trials pt WHERE pt.session_id = t.session_id AND pt.trial_index = t.trial_index), "
    "t.repetition, t.runs";
constexpr int kTrialColumnCount = 19;

Result<RenderMode> read_mode(const Statement& stmt, int column, const std::string& file) {
    const std::string name = stmt.text(column);
    Result<RenderMode> mode = parse_render_mode(name);
    if (!mode)
        return Error{"study database '" + file + "' holds an unknown render mode '" + name +
                     "' (written by a newer monoplane?)"};
    return mode;
}

// Reads the kTrialColumns starting at column 0 into a trial and, when decided, its outcome.
Result<void> read_trial(const Statement& stmt, const std::string& file, ScheduledTrial& trial,
                        bool& decided, TrialOutcome& outcome) {
    trial.index = stmt.int32(0);
    trial.practice = stmt.int64(1) != 0;
    trial.block = stmt.int32(2);
    trial.scene = stmt.text(3);
    // NULL: a staircase's slot whose m is chosen when it starts.
    trial.mono_plane = stmt.is_null(4) ? std::nan("") : stmt.real(4);
    trial.label1_alternative = stmt.int32(5);
    Result<RenderMode> label1 = read_mode(stmt, 6, file);
    MONOPLANE_TRY(label1);
    Result<RenderMode> label2 = read_mode(stmt, 7, file);
    MONOPLANE_TRY(label2);
    trial.label1_mode = *label1;
    trial.label2_mode = *label2;
    trial.adaptive = stmt.int64(16) != 0;
    trial.repetition = stmt.int32(17);
    decided = stmt.int64(8) != 0;
    outcome = TrialOutcome{};
    if (!decided) return Ok{};
    outcome.choice = stmt.int32(9);
    Result<RenderMode> chosen = read_mode(stmt, 10, file);
    MONOPLANE_TRY(chosen);
    outcome.chosen_mode = *chosen;
    outcome.valid = stmt.int64(11) != 0;
    outcome.switches = stmt.int32(12);
    outcome.time_on_label_ns[0] = stmt.int64(13);
    outcome.time_on_label_ns[1] = stmt.int64(14);
    outcome.decision_time_ns = stmt.int64(15);
    outcome.runs = stmt.int32(18);
    return Ok{};
}

// A session's events in logging order: all of them, or only the decisions recorded with a
// reason (SessionInfo::recorded_decisions). One reader for both, so a row reads the same way.
Result<std::vector<TrialEvent>> read_events(const Connection& db, std::int64_t session_id,
                                            bool decisions_only) {
    Result<Statement> stmt = Statement::prepare(
        db, std::string("SELECT kind, trial_index, label, time_ns, frame, page, detail FROM events "
                        "WHERE session_id = ?") +
                (decisions_only ? " AND detail IS NOT NULL" : "") + " ORDER BY id");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    std::vector<TrialEvent> events;
    for (;;) {
        Result<bool> row = stmt.value().step("reading events");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const std::optional<EventKind> kind = parse_event_kind(stmt->text(0));
        if (!kind)
            return Error{"study database '" + db.path() + "' holds an unknown event kind '" +
                         stmt->text(0) + "'"};
        // NULL: a screen's event (no trial), an event that is not on an instruction page.
        events.push_back(TrialEvent{.kind = *kind,
                                    .trial_index = stmt->is_null(1) ? -1 : stmt->int32(1),
                                    .label = stmt->int32(2),
                                    .time_ns = stmt->int64(3),
                                    .frame = stmt->int64(4),
                                    .page = stmt->is_null(5) ? -1 : stmt->int32(5),
                                    .detail = stmt->text(6)});
    }
    return events;
}

}  // namespace

Result<Schedule> StudyStore::load_schedule(std::int64_t session_id) const {
    const Connection& db = impl_->db;
    Result<Statement> head =
        Statement::prepare(db,
                           "SELECT s.seed, p.participant_number, s.block_order, s.session_number "
                           "FROM sessions s JOIN participants p ON p.id = s.participant_id "
                           "WHERE s.id = ?");
    MONOPLANE_TRY(head);
    head.value().bind(1, session_id);
    Result<bool> found = head.value().step("loading a schedule");
    MONOPLANE_TRY(found);
    if (!*found) return impl_->no_session(session_id);

    Schedule schedule;
    const std::optional<std::uint64_t> seed = parse_stored_u64(head->text(0), 10);
    if (!seed)
        return Error{"study database '" + db.path() + "' holds a bad seed '" + head->text(0) + "'"};
    schedule.seed = *seed;
    schedule.participant_index = head->int32(1);  // the number that picked the Latin-square row
    schedule.block_order = split_scenes(head->text(2));
    schedule.session_number = head->int32(3);

    // The trials started so far and the staircases' slots not started yet.
    Result<Statement> rows =
        Statement::prepare(db, "SELECT " + std::string(kTrialColumns) +
                                   " FROM trials t WHERE t.session_id = ?1 UNION ALL " +
                                   std::string(kUnstartedPlannedTrials) + " ORDER BY 1");
    MONOPLANE_TRY(rows);
    rows.value().bind(1, session_id);
    for (;;) {
        Result<bool> row = rows.value().step("loading a schedule");
        MONOPLANE_TRY(row);
        if (!*row) break;
        ScheduledTrial trial;
        bool decided = false;
        TrialOutcome outcome;
        MONOPLANE_TRY(read_trial(*rows, db.path(), trial, decided, outcome));
        schedule.trials.push_back(std::move(trial));
    }
    return schedule;
}

Result<int> StudyStore::first_undecided_trial(std::int64_t session_id) const {
    MONOPLANE_TRY(impl_->require_session(session_id));
    // All decided: the trial count, i.e. one past the last trial. Slots not started count as
    // undecided.
    Result<Statement> stmt = Statement::prepare(
        impl_->db,
        "SELECT coalesce(min(CASE WHEN decided = 0 THEN trial_index END), count(*)) FROM "
        "(SELECT trial_index, decided FROM trials WHERE session_id = ?1 UNION ALL "
        "SELECT pt.trial_index, 0 FROM planned_trials pt WHERE pt.session_id = ?1 AND NOT EXISTS "
        "(SELECT 1 FROM trials t WHERE t.session_id = pt.session_id AND "
        "t.trial_index = pt.trial_index))");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    MONOPLANE_TRY(stmt.value().step("finding the first undecided trial"));
    return stmt->int32(0);
}

Result<SessionInfo> StudyStore::session(std::int64_t session_id) const {
    const Connection& db = impl_->db;
    Result<Statement> stmt = Statement::prepare(
        db,
        "SELECT s.id, p.code, p.participant_index, s.protocol_name, s.protocol_hash, "
        "s.protocol_text, s.seed, s.software_version, s.hmd, s.runtime, s.device, s.observer, "
        "s.started_utc, s.status, s.render_anti_aliasing, s.render_ssao, s.render_detail, "
        "s.procedure, p.participant_number, s.session_number, s.ended_utc, p.id, s.session_uuid "
        "FROM sessions s JOIN participants p ON p.id = s.participant_id WHERE s.id = ?");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    Result<bool> found = stmt.value().step("reading a session");
    MONOPLANE_TRY(found);
    if (!*found) return impl_->no_session(session_id);

    SessionInfo info;
    info.id = stmt->int64(0);
    info.participant_code = stmt->text(1);
    info.participant_index = stmt->int32(2);
    info.protocol_name = stmt->text(3);
    const std::optional<std::uint64_t> hash = parse_stored_u64(stmt->text(4), 16);
    const std::optional<std::uint64_t> seed = parse_stored_u64(stmt->text(6), 10);
    const std::optional<SessionStatus> status = parse_session_status(stmt->text(13));
    if (!hash || !seed || !status)
        return Error{"study database '" + db.path() +
                     "' holds a bad hash, seed or status in session " + std::to_string(session_id)};
    info.protocol_hash = *hash;
    info.protocol_text = stmt->text(5);
    info.seed = *seed;
    info.software_version = stmt->text(7);
    info.hmd = stmt->text(8);
    info.runtime = stmt->text(9);
    info.device = stmt->text(10);
    info.observer = stmt->text(11);
    info.started_utc = stmt->text(12);
    info.status = *status;
    info.render.anti_aliasing = stmt->text(14);
    info.render.ssao = stmt->text(15);
    info.render.detail = stmt->is_null(16) ? "" : stmt->text(16);
    Result<Procedure> procedure = parse_procedure(stmt->text(17));
    if (!procedure)
        return Error{"study database '" + db.path() + "': " + procedure.error().message};
    info.procedure = *procedure;
    info.participant_number = stmt->int32(18);
    info.session_number = stmt->int32(19);
    info.ended_utc = stmt->is_null(20) ? "" : stmt->text(20);
    info.session_uuid = stmt->text(22);
    Result<std::vector<VariableValue>> variables = read_participant_variables(db, stmt->int64(21));
    MONOPLANE_TRY(variables);
    info.variables = std::move(variables).value();
    Result<std::vector<SceneFileRecord>> files = read_scene_files(db, session_id);
    MONOPLANE_TRY(files);
    info.scene_files = std::move(files).value();
    Result<std::vector<SessionNote>> notes = read_session_notes(db, session_id);
    MONOPLANE_TRY(notes);
    info.notes = std::move(notes).value();
    Result<std::vector<TrialEvent>> decisions = read_events(db, session_id, true);
    MONOPLANE_TRY(decisions);
    info.recorded_decisions = std::move(decisions).value();
    return info;
}

Result<std::vector<FrameRecord>> StudyStore::frames(std::int64_t session_id) const {
    return read_frames(impl_->db, session_id);
}

Result<std::int64_t> StudyStore::next_frame_number(std::int64_t session_id) const {
    return study::next_frame_number(impl_->db, session_id);
}

Result<std::optional<std::int64_t>> StudyStore::latest_unfinished_session() const {
    // Aborted sessions count as unfinished: an experimenter may abort (a participant felt
    // unwell) and resume later; only a completed session is done.
    Result<Statement> stmt = Statement::prepare(
        impl_->db, "SELECT id FROM sessions WHERE status <> 'completed' ORDER BY id DESC LIMIT 1");
    MONOPLANE_TRY(stmt);
    Result<bool> row = stmt.value().step("finding an unfinished session");
    MONOPLANE_TRY(row);
    if (!*row) return std::optional<std::int64_t>();
    return std::optional<std::int64_t>(stmt->int64(0));
}

Result<int> StudyStore::participant_count() const {
    Result<std::int64_t> count =
        query_int(impl_->db, "SELECT count(*) FROM participants", "counting participants");
    MONOPLANE_TRY(count);
    return static_cast<int>(*count);
}

const std::filesystem::path& StudyStore::path() const {
    return impl_->file;
}

Result<std::optional<ParticipantRecord>> StudyStore::participant(const std::string& code) const {
    Result<std::optional<StoredParticipant>> found = find_participant(impl_->db, code);
    MONOPLANE_TRY(found);
    if (!*found) return std::optional<ParticipantRecord>();
    return std::optional<ParticipantRecord>(std::move((*found)->record));
}

Result<std::optional<std::int64_t>> StudyStore::find_session(const std::string& code,
                                                             int session_number) const {
    Result<Statement> stmt = Statement::prepare(
        impl_->db,
        "SELECT s.id FROM sessions s JOIN participants p ON p.id = s.participant_id "
        "WHERE p.code = ? AND s.session_number = ?");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, code).bind(2, session_number);
    Result<bool> row = stmt.value().step("looking up session " + std::to_string(session_number) +
                                         " of participant '" + code + "'");
    MONOPLANE_TRY(row);
    if (!*row) return std::optional<std::int64_t>();
    return std::optional<std::int64_t>(stmt->int64(0));
}

Result<std::vector<TrialRecord>> StudyStore::trials(std::optional<std::int64_t> session_id) const {
    const Connection& db = impl_->db;
    if (session_id) MONOPLANE_TRY(impl_->require_session(*session_id));
    Result<Statement> stmt = Statement::prepare(
        db, "SELECT " + std::string(kTrialColumns) +
                ", t.session_id, p.code, s.session_number FROM trials t "
                "JOIN sessions s ON s.id = t.session_id "
                "JOIN participants p ON p.id = s.participant_id "
                "WHERE ?1 IS NULL OR t.session_id = ?1 ORDER BY t.session_id, t.trial_index");
    MONOPLANE_TRY(stmt);
    if (session_id)
        stmt.value().bind(1, *session_id);
    else
        stmt.value().bind_null(1);
    std::vector<TrialRecord> records;
    for (;;) {
        Result<bool> row = stmt.value().step("reading trials");
        MONOPLANE_TRY(row);
        if (!*row) break;
        TrialRecord record;
        MONOPLANE_TRY(read_trial(*stmt, db.path(), record.trial, record.decided, record.outcome));
        record.session_id = stmt->int64(kTrialColumnCount);
        record.participant_code = stmt->text(kTrialColumnCount + 1);
        record.session_number = stmt->int32(kTrialColumnCount + 2);
        records.push_back(std::move(record));
    }
    return records;
}

Result<std::vector<TrialEvent>> StudyStore::events(std::int64_t session_id) const {
    MONOPLANE_TRY(impl_->require_session(session_id));
    return read_events(impl_->db, session_id, false);
}

Result<std::vector<QuestionnaireAnswer>> StudyStore::answers(std::int64_t session_id) const {
    const Connection& db = impl_->db;
    MONOPLANE_TRY(impl_->require_session(session_id));
    Result<Statement> stmt = Statement::prepare(
        db, "SELECT item, text, answer FROM answers WHERE session_id = ? ORDER BY item");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    std::vector<QuestionnaireAnswer> answers;
    for (;;) {
        Result<bool> row = stmt.value().step("reading questionnaire answers");
        MONOPLANE_TRY(row);
        if (!*row) break;
        answers.push_back(QuestionnaireAnswer{stmt->int32(0), stmt->text(1), stmt->int32(2)});
    }
    return answers;
}

}  // namespace monoplane::study
