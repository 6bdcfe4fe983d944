#include "study/study_store.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <ctime>
#include <functional>
#include <set>
#include <system_error>

#include "study/frame_queue.h"
#include "study/planned_trial_store.h"
#include "study/scene_file_store.h"
#include "study/session_hold.h"
#include "study/session_run_store.h"
#include "study/session_uuid.h"
#include "study/store_impl.h"
#include "study/store_schema.h"
#include "study/store_sqlite.h"

namespace monoplane::study {
namespace {

using sqlite::Connection;
using sqlite::query_int;
using sqlite::Statement;
using sqlite::Transaction;

// The database's names for the enums. Stored in files: never change one (docs/data.md).
constexpr std::array<std::string_view, 4> kStatusNames = {"running", "paused", "completed",
                                                          "aborted"};

std::optional<SessionStatus> parse_status(std::string_view name) {
    for (std::size_t i = 0; i < kStatusNames.size(); ++i)
        if (kStatusNames[i] == name) return static_cast<SessionStatus>(i);
    return std::nullopt;
}

std::string utc_now_iso8601() {
    const std::time_t now = std::time(nullptr);
    std::tm tm{};
    gmtime_r(&now, &tm);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &tm);
    return text;
}

// 64-bit unsigned values are stored as text (SQLite integers are signed): the seed in decimal
// as the user types it, the protocol hash in 16 hex digits.
std::string hash_text(std::uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

std::optional<std::uint64_t> parse_u64(std::string_view text, int base) {
    std::uint64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value, base);
    if (ec != std::errc() || end != text.data() + text.size() || text.empty()) return std::nullopt;
    return value;
}

// Pseudonyms only (the store holds no names): a short code a name cannot hide in.
bool valid_participant_code(std::string_view code) {
    if (code.empty() || code.size() > 64) return false;
    for (char c : code) {
        const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                        (c >= '0' && c <= '9') || c == '_' || c == '-';
        if (!ok) return false;
    }
    return true;
}

// Participant variable names as protocols declare them (protocol_study_day.h): they become
// export columns var_<name>.
bool valid_variable_name(std::string_view name) {
    if (name.empty() || name.size() > 32 || name[0] < 'a' || name[0] > 'z') return false;
    return std::ranges::all_of(
        name, [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '_'; });
}

// Refuses values check_variables could not have returned, before anything is written.
Result<void> validate_variables(const std::vector<VariableValue>& values) {
    std::set<std::string> seen;
    for (const VariableValue& v : values) {
        if (!valid_variable_name(v.name))
            return Error{"participant variable name '" + v.name +
                         "' is not a letter a-z followed by up to 31 of a-z, 0-9 and '_'"};
        if (!seen.insert(v.name).second)
            return Error{"participant variable '" + v.name + "' is given twice"};
    }
    return Ok{};
}

std::optional<VariableType> parse_variable_type(std::string_view name) {
    for (VariableType type :
         {VariableType::Integer, VariableType::Number, VariableType::Choice, VariableType::Text})
        if (variable_type_name(type) == name) return type;
    return std::nullopt;
}

// Characters as the person typing them counts them: UTF-8 code points, not bytes.
std::size_t code_points(std::string_view text) {
    return static_cast<std::size_t>(std::ranges::count_if(
        text, [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

// Refuses the schedule before anything is written: a bad one would be stored for good.
Result<void> validate_schedule(const Schedule& schedule) {
    if (schedule.trials.empty()) return Error{"the schedule has no trials"};
    if (schedule.participant_index < 0)
        return Error{"the schedule's participant number is negative"};
    if (schedule.session_number < 1) return Error{"the schedule's session number is below 1"};
    for (const std::string& scene : schedule.block_order)
        if (scene.empty() || scene.find(',') != std::string::npos)
            return Error{"scene name '" + scene + "' in the block order is empty or has a comma"};
    for (std::size_t i = 0; i < schedule.trials.size(); ++i) {
        const ScheduledTrial& t = schedule.trials[i];
        const std::string where = "scheduled trial " + std::to_string(i) + ": ";
        if (t.index != static_cast<int>(i))
            return Error{where + "index " + std::to_string(t.index) + " is not its position"};
        if (t.practice != (t.block == -1))
            return Error{where + "practice trials have block -1 and data trials a block >= 0"};
        if (t.block < -1) return Error{where + "block is below -1"};
        if (t.scene.empty()) return Error{where + "no scene"};
        if (t.adaptive && (t.practice || !std::isnan(t.mono_plane)))
            return Error{where + "a staircase's trial is a data trial whose m is not chosen yet"};
        if (!t.adaptive && !std::isfinite(t.mono_plane))
            return Error{where + "mono plane is not finite"};
        if (t.label1_alternative != 0 && t.label1_alternative != 1)
            return Error{where + "label1_alternative must be 0 or 1"};
        if (t.repetition < 1) return Error{where + "repetition is below 1"};
    }
    return Ok{};
}

std::string join_scenes(const std::vector<std::string>& scenes) {
    std::string text;
    for (const std::string& scene : scenes) text += (text.empty() ? "" : ",") + scene;
    return text;
}

std::vector<std::string> split_scenes(const std::string& text) {
    std::vector<std::string> scenes;
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t comma = std::min(text.find(',', start), text.size());
        scenes.push_back(text.substr(start, comma - start));
        start = comma + 1;
    }
    return scenes;
}

}  // namespace

std::string_view session_status_name(SessionStatus status) {
    return kStatusNames.at(static_cast<std::size_t>(status));
}

namespace {

// What the database knows of a participant, with the row id the session rows refer to.
struct StoredParticipant {
    std::int64_t id = 0;
    ParticipantRecord record;
};

Result<std::vector<VariableValue>> read_variables(const Connection& db,
                                                  std::int64_t participant_id) {
    // By rowid: in the order begin_session wrote them, the protocol's declaration order.
    Result<Statement> stmt = Statement::prepare(
        db,
        "SELECT name, type, value FROM participant_variables WHERE participant_id = ? "
        "ORDER BY rowid");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, participant_id);
    std::vector<VariableValue> values;
    for (;;) {
        Result<bool> row = stmt.value().step("reading participant variables");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const std::optional<VariableType> type = parse_variable_type(stmt->text(1));
        if (!type)
            return Error{"study database '" + db.path() + "' holds an unknown variable type '" +
                         stmt->text(1) + "' (written by a newer monoplane?)"};
        values.push_back(
            VariableValue{.name = stmt->text(0), .type = *type, .value = stmt->text(2)});
    }
    return values;
}

Result<void> write_variables(const Connection& db, std::int64_t participant_id,
                             const std::vector<VariableValue>& values) {
    Result<Statement> insert =
        Statement::prepare(db,
                           "INSERT INTO participant_variables (participant_id, name, type, value) "
                           "VALUES (?, ?, ?, ?)");
    MONOPLANE_TRY(insert);
    for (const VariableValue& v : values) {
        insert.value().reset();
        insert.value()
            .bind(1, participant_id)
            .bind(2, v.name)
            .bind(3, variable_type_name(v.type))
            .bind(4, v.value);
        MONOPLANE_TRY(insert.value().run("storing participant variable '" + v.name + "'"));
    }
    return Ok{};
}

Result<std::optional<StoredParticipant>> find_participant(const Connection& db,
                                                          const std::string& code) {
    Result<Statement> stmt = Statement::prepare(
        db,
        "SELECT p.id, p.participant_index, p.participant_number, s.session_number, s.id "
        "FROM participants p LEFT JOIN sessions s ON s.participant_id = p.id "
        "WHERE p.code = ? ORDER BY s.session_number");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, code);
    std::optional<StoredParticipant> found;
    for (;;) {
        Result<bool> row = stmt.value().step("looking up participant '" + code + "'");
        MONOPLANE_TRY(row);
        if (!*row) break;
        if (!found) {
            found.emplace();
            found->id = stmt->int64(0);
            found->record.code = code;
            found->record.participant_index = stmt->int32(1);
            found->record.participant_number = stmt->int32(2);
        }
        if (!stmt->is_null(4)) found->record.sessions.emplace_back(stmt->int32(3), stmt->int64(4));
    }
    if (!found) return found;
    Result<std::vector<VariableValue>> variables = read_variables(db, found->id);
    MONOPLANE_TRY(variables);
    found->record.variables = std::move(variables).value();
    return found;
}

std::string numbered(int session_number) {
    return "session " + std::to_string(session_number);
}

// A known participant's next session: its number follows theirs, their variables and Latin-square
// row stay what their first session recorded.
Result<void> check_returning(const Connection& db, const ParticipantRecord& p,
                             const SessionInfo& info, const Schedule& schedule) {
    const std::string who = "participant '" + p.code + "'";
    const int next = p.next_session_number();
    if (info.session_number < next)
        return Error{who + " already has " + numbered(info.session_number) + " in '" + db.path() +
                     "'; use `monoplane study resume --db " + db.path() + " --participant " +
                     p.code + " --session " + std::to_string(info.session_number) +
                     "` to continue it, or begin their next session, " + numbered(next) + "."};
    if (info.session_number > next)
        return Error{who + " has " + std::to_string(next - 1) + " session(s) in '" + db.path() +
                     "'; their next is " + numbered(next) + ", not " +
                     numbered(info.session_number) + " (sessions are numbered without gaps)."};
    if (!info.variables.empty() && info.variables != p.variables)
        return Error{who + "'s variables were recorded at their first session in '" + db.path() +
                     "' and do not change; give none, or the same values, for " +
                     numbered(info.session_number) + "."};
    if (schedule.participant_index != p.participant_number)
        return Error{"the schedule was made for participant number " +
                     std::to_string(schedule.participant_index + 1) + " but " + who + " in '" +
                     db.path() + "' is participant number " +
                     std::to_string(p.participant_number + 1) +
                     " since their first session; make the schedule again."};
    return Ok{};
}

// A new participant: a study-wide number no one else in the file has. Their first session here
// is usually session 1; a later number continues a participant whose earlier sessions ran on
// another PC (`study run --session N`, with the participant number they have there).
Result<void> check_new(const Connection& db, const SessionInfo& info, const Schedule& schedule) {
    const std::string who = "participant '" + info.participant_code + "'";
    // The schedule's Latin-square row is the number recorded: any other would misstate the
    // counterbalancing. 0 in info is the default (not given).
    if (info.participant_number != 0 && info.participant_number != schedule.participant_index)
        return Error{"the schedule was made for participant number " +
                     std::to_string(schedule.participant_index + 1) + " but " + who +
                     " is to be participant number " + std::to_string(info.participant_number + 1) +
                     "; make the schedule again."};
    Result<Statement> taken =
        Statement::prepare(db, "SELECT code FROM participants WHERE participant_number = ?");
    MONOPLANE_TRY(taken);
    taken.value().bind(1, schedule.participant_index);
    Result<bool> found = taken.value().step("looking up participant numbers");
    MONOPLANE_TRY(found);
    if (*found)
        return Error{"participant number " + std::to_string(schedule.participant_index + 1) +
                     " is taken by participant '" + taken->text(0) + "' in '" + db.path() +
                     "'; give " + who + " a free one."};
    return Ok{};
}

// The participant row a session belongs to: the known one, or a new one with its number and
// variables. Inside begin_session's transaction.
Result<std::int64_t> admit_participant(const Connection& db, const SessionInfo& info,
                                       const Schedule& schedule) {
    Result<std::optional<StoredParticipant>> known = find_participant(db, info.participant_code);
    MONOPLANE_TRY(known);
    if (*known) {
        MONOPLANE_TRY(check_returning(db, (*known)->record, info, schedule));
        return (*known)->id;
    }
    MONOPLANE_TRY(check_new(db, info, schedule));
    // The index is the participant's order in this file (unique there); the number is theirs in
    // the whole study.
    Result<std::int64_t> index =
        query_int(db, "SELECT count(*) FROM participants", "counting participants");
    MONOPLANE_TRY(index);
    Result<Statement> insert = Statement::prepare(
        db,
        "INSERT INTO participants (code, participant_index, participant_number, created_utc) "
        "VALUES (?, ?, ?, ?)");
    MONOPLANE_TRY(insert);
    insert.value()
        .bind(1, info.participant_code)
        .bind(2, *index)
        .bind(3, schedule.participant_index)
        .bind(4, utc_now_iso8601());
    MONOPLANE_TRY(insert.value().run("adding participant '" + info.participant_code + "'"));
    const std::int64_t id = sqlite3_last_insert_rowid(db.get());
    MONOPLANE_TRY(write_variables(db, id, info.variables));
    return id;
}

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
    s.bind(1, participant_id).bind(2, info.protocol_name).bind(3, hash_text(info.protocol_hash));
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
    MONOPLANE_TRY(s.run("adding " + numbered(info.session_number) + " of participant '" +
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

}  // namespace

namespace {

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
    if (!valid_participant_code(info.participant_code))
        return Error{"participant code '" + info.participant_code +
                     "' is invalid: use 1 to 64 letters, digits, '_' or '-' — a pseudonym such "
                     "as P07, never a name."};
    if (info.session_number < 1)
        return Error{"session number " + std::to_string(info.session_number) +
                     " for participant '" + info.participant_code +
                     "': sessions are numbered from 1"};
    if (info.session_number != schedule.session_number)
        return Error{"the schedule was made for " + numbered(schedule.session_number) +
                     " but participant '" + info.participant_code + "' is to begin " +
                     numbered(info.session_number) + "; make the schedule again."};
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

namespace {

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
    const std::optional<std::uint64_t> seed = parse_u64(head->text(0), 10);
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

namespace {

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
    const std::optional<std::uint64_t> hash = parse_u64(stmt->text(4), 16);
    const std::optional<std::uint64_t> seed = parse_u64(stmt->text(6), 10);
    const std::optional<SessionStatus> status = parse_status(stmt->text(13));
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
    Result<std::vector<VariableValue>> variables = read_variables(db, stmt->int64(21));
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

namespace {

bool is_instruction_event(EventKind kind) {
    return kind == EventKind::InstructionsShown || kind == EventKind::InstructionsConfirmed;
}

// Refuses an event the events table's CHECKs would refuse, with words a developer can act on.
Result<void> validate_event(const TrialEvent& event) {
    const auto kind = static_cast<std::size_t>(event.kind);
    if (kind > static_cast<std::size_t>(EventKind::RunStarted))
        return Error{"unknown event kind " + std::to_string(kind)};
    const std::string name(event_kind_name(event.kind));
    if (event.label < 0 || event.label > 2)
        return Error{"event label " + std::to_string(event.label) + " is not 0, 1 or 2"};
    if (event.frame < -1)
        return Error{"event frame " + std::to_string(event.frame) + " is below -1"};
    if (!is_trial_event(event.kind) && event.trial_index != -1)
        return Error{"a '" + name + "' event belongs to a screen or the session, not to trial " +
                     std::to_string(event.trial_index) + ": its trial index is -1"};
    if (has_detail(event.kind) && event.detail.find_first_not_of(" \t\n") == std::string::npos)
        return Error{"a '" + name + "' event needs its reason"};
    if (!has_detail(event.kind) && !event.detail.empty())
        return Error{"a '" + name + "' event has no reason to record"};
    if (is_trial_event(event.kind) && event.trial_index < 0)
        return Error{"a '" + name + "' event needs its trial (index " +
                     std::to_string(event.trial_index) + " given)"};
    if (is_instruction_event(event.kind) && event.page < 0)
        return Error{"a '" + name + "' event needs its instruction page (0-based; " +
                     std::to_string(event.page) + " given)"};
    if (!is_instruction_event(event.kind) && event.page != -1)
        return Error{"a '" + name + "' event has no instruction page (-1), not page " +
                     std::to_string(event.page)};
    return Ok{};
}

}  // namespace

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

namespace {

// Per session: data trials decided, and data trials planned (the trials rows that are not
// practice, plus a staircase's slots not started yet: its most).
// A session's data trials decided, and planned (a staircase's slots not started yet counted):
// what the roster and the rule of one live session (kEarlierSessionsQuery) show.
constexpr std::string_view kTrialCounts =
    "(SELECT count(*) FROM trials t WHERE t.session_id = s.id AND t.practice = 0 AND "
    "t.decided = 1), "
    "(SELECT count(*) FROM trials t WHERE t.session_id = s.id AND t.practice = 0) + "
    "(SELECT count(*) FROM planned_trials pt WHERE pt.session_id = s.id AND NOT EXISTS "
    "(SELECT 1 FROM trials t WHERE t.session_id = pt.session_id AND "
    "t.trial_index = pt.trial_index))";

const std::string kRosterQuery =
    "SELECT p.code, p.participant_number, s.session_number, s.id, s.status, " +
    std::string(kTrialCounts) +
    ", s.started_utc, s.ended_utc, s.device, s.runtime, s.protocol_hash, s.protocol_name, "
    "s.session_uuid, (SELECT e.detail FROM events e WHERE e.session_id = s.id AND "
    "e.kind = 'session_abandoned' ORDER BY e.id DESC LIMIT 1) "
    "FROM sessions s JOIN participants p ON p.id = s.participant_id "
    "ORDER BY p.code, s.session_number";

}  // namespace

namespace {

// Where a query's row has a session's id, status and protocol hash.
struct SessionColumns {
    int id = 0;
    int status = 0;
    int hash = 0;
};

struct StatusAndHash {
    SessionStatus status = SessionStatus::Running;
    std::uint64_t hash = 0;
};

// The row's status and protocol hash, or an error naming the session whose row holds bad ones.
Result<StatusAndHash> status_and_hash(const Connection& db, const Statement& s,
                                      SessionColumns columns) {
    const std::optional<SessionStatus> status = parse_status(s.text(columns.status));
    const std::optional<std::uint64_t> hash = parse_u64(s.text(columns.hash), 16);
    if (!status || !hash)
        return Error{"study database '" + db.path() + "' holds a bad status or hash in session " +
                     std::to_string(s.int64(columns.id))};
    return StatusAndHash{*status, *hash};
}

}  // namespace

Result<std::vector<RosterRow>> StudyStore::roster() const {
    const Connection& db = impl_->db;
    Result<Statement> stmt = Statement::prepare(db, kRosterQuery);
    MONOPLANE_TRY(stmt);
    std::vector<RosterRow> rows;
    for (;;) {
        Result<bool> row = stmt.value().step("reading the roster");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const Statement& s = stmt.value();
        Result<StatusAndHash> checked = status_and_hash(db, s, {.id = 3, .status = 4, .hash = 11});
        MONOPLANE_TRY(checked);
        const std::optional<SessionStatus> status = checked->status;
        const std::optional<std::uint64_t> hash = checked->hash;
        rows.push_back(RosterRow{.participant_code = s.text(0),
                                 .participant_number = s.int32(1),
                                 .session_number = s.int32(2),
                                 .session_id = s.int64(3),
                                 .status = *status,
                                 .trials_decided = s.int32(5),
                                 .trials_planned = s.int32(6),
                                 .started_utc = s.text(7),
                                 .ended_utc = s.is_null(8) ? "" : s.text(8),
                                 .device = s.text(9),
                                 .runtime = s.text(10),
                                 .protocol_hash = *hash,
                                 .protocol_name = s.text(12),
                                 .session_uuid = s.text(13),
                                 .abandoned_reason = s.is_null(14)
                                                         ? std::nullopt
                                                         : std::optional<std::string>(s.text(14))});
    }
    return rows;
}

namespace {

// A participant's sessions with the counts the roster shows (kRosterQuery's planned count).
const std::string kEarlierSessionsQuery =
    "SELECT s.id, s.session_number, s.status, EXISTS (SELECT 1 FROM events e WHERE "
    "e.session_id = s.id AND e.kind = 'session_abandoned'), " +
    std::string(kTrialCounts) +
    ", s.protocol_text, s.protocol_hash "
    "FROM sessions s JOIN participants p ON p.id = s.participant_id WHERE p.code = ? "
    "ORDER BY s.session_number";

}  // namespace

Result<std::vector<EarlierSession>> StudyStore::earlier_sessions(const std::string& code) const {
    const Connection& db = impl_->db;
    Result<Statement> stmt = Statement::prepare(db, kEarlierSessionsQuery);
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, code);
    std::vector<EarlierSession> sessions;
    for (;;) {
        Result<bool> row = stmt.value().step("reading participant '" + code + "''s sessions");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const Statement& s = stmt.value();
        Result<StatusAndHash> checked = status_and_hash(db, s, {.id = 0, .status = 2, .hash = 7});
        MONOPLANE_TRY(checked);
        const std::optional<SessionStatus> status = checked->status;
        const std::optional<std::uint64_t> hash = checked->hash;
        EarlierSession earlier{.id = s.int64(0),
                               .session_number = s.int32(1),
                               .status = *status,
                               .abandoned = s.int64(3) != 0,
                               .holder = std::nullopt,
                               .trials_decided = s.int32(4),
                               .trials_planned = s.int32(5),
                               .protocol_text = s.text(6),
                               .protocol_hash = *hash};
        if (*status == SessionStatus::Running || *status == SessionStatus::Paused) {
            Result<std::optional<SessionHolder>> holder =
                SessionHold::holder(impl_->file, earlier.id);
            MONOPLANE_TRY(holder);
            earlier.holder = *holder;
        }
        sessions.push_back(std::move(earlier));
    }
    return sessions;
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
