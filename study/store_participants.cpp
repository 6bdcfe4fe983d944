#include "study/store_participants.h"

#include "common/utc_time.h"
#include "study/protocol_study_day.h"

namespace monoplane::study {

using sqlite::Connection;
using sqlite::query_int;
using sqlite::Statement;

namespace {

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

// A known participant's next session: its number follows theirs, their variables and Latin-square
// row stay what their first session recorded.
Result<void> check_returning(const Connection& db, const ParticipantRecord& p,
                             const SessionInfo& info, const Schedule& schedule) {
    const std::string who = "participant '" + p.code + "'";
    const int next = p.next_session_number();
    if (info.session_number < next)
        return Error{
            who + " already has " + numbered_session(info.session_number) + " in '" + db.path() +
            "'; use `monoplane study resume --db " + db.path() + " --participant " + p.code +
            " --session " + std::to_string(info.session_number) +
            "` to continue it, or begin their next session, " + numbered_session(next) + "."};
    if (info.session_number > next)
        return Error{who + " has " + std::to_string(next - 1) + " session(s) in '" + db.path() +
                     "'; their next is " + numbered_session(next) + ", not " +
                     numbered_session(info.session_number) +
                     " (sessions are numbered without gaps)."};
    if (!info.variables.empty() && info.variables != p.variables)
        return Error{who + "'s variables were recorded at their first session in '" + db.path() +
                     "' and do not change; give none, or the same values, for " +
                     numbered_session(info.session_number) + "."};
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

}  // namespace

Result<std::vector<VariableValue>> read_participant_variables(const Connection& db,
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
    Result<std::vector<VariableValue>> variables = read_participant_variables(db, found->id);
    MONOPLANE_TRY(variables);
    found->record.variables = std::move(variables).value();
    return found;
}

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

}  // namespace monoplane::study
