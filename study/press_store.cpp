// StudyStore's presses (table `presses`, schema version 9): each press of the participant's
// answer channels, durable when record_press returns.
#include "study/store_impl.h"

namespace monoplane::study {

using sqlite::Statement;
using sqlite::Transaction;

Result<void> StudyStore::record_press(std::int64_t session_id, const ResponsePress& press) {
    MONOPLANE_TRY(check_press(press));
    // With the queued frames, as every durable write: a press is as safe as a decision.
    Result<Transaction> tx = Transaction::begin(impl_->db, "logging a press");
    MONOPLANE_TRY(tx);
    MONOPLANE_TRY(impl_->require_session(session_id));
    MONOPLANE_TRY(impl_->write_queued_frames());
    Result<Statement> stmt = Statement::prepare(
        impl_->db,
        "INSERT INTO presses (session_id, trial_index, source, action, key, screen, time_ns) "
        "VALUES (?, ?, ?, ?, ?, ?, ?)");
    MONOPLANE_TRY(stmt);
    Statement& s = stmt.value();
    s.bind(1, session_id);
    if (press.trial_index >= 0) {
        s.bind(2, press.trial_index);
    } else {
        s.bind_null(2);
    }
    s.bind(3, press_source_name(press.source)).bind(4, press_action_name(press.action));
    if (press.key.empty()) {
        s.bind_null(5);
    } else {
        s.bind(5, std::string_view(press.key));
    }
    s.bind(6, std::string_view(press.screen)).bind(7, press.time_ns);
    MONOPLANE_TRY(s.run("logging a press"));
    return impl_->commit_written(tx.value(), "logging a press");
}

Result<std::vector<ResponsePress>> StudyStore::presses(std::int64_t session_id) const {
    MONOPLANE_TRY(impl_->require_session(session_id));
    Result<Statement> stmt = Statement::prepare(
        impl_->db,
        "SELECT source, action, coalesce(key, ''), screen, coalesce(trial_index, -1), time_ns "
        "FROM presses WHERE session_id = ? ORDER BY id");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    std::vector<ResponsePress> presses;
    for (;;) {
        Result<bool> row = stmt.value().step("reading a session's presses");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const Statement& s = stmt.value();
        const std::optional<PressSource> source = parse_press_source(s.text(0));
        const std::optional<PressAction> action = parse_press_action(s.text(1));
        if (!source || !action) {
            return Error{"a press of session " + std::to_string(session_id) + " in '" +
                         impl_->db.path() + "' has source '" + s.text(0) + "' and action '" +
                         s.text(1) + "', which this build does not know"};
        }
        presses.push_back({*source, *action, s.text(2), s.text(3), s.int32(4), s.int64(5)});
    }
    return presses;
}

}  // namespace monoplane::study
