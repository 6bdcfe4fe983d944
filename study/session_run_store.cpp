#include "study/session_run_store.h"

#include <algorithm>
#include <optional>
#include <string>

#include "study/frame_queue.h"

namespace monoplane::study {
namespace {

using sqlite::Connection;
using sqlite::query_int;
using sqlite::Statement;

// The runs before this one. A session that logged anything but a decision about it (those have
// a detail) while no run was recorded ran under schema 7 or before: one run, as far as is known.
Result<int> runs_before(const Connection& db, std::int64_t session_id) {
    const std::string id = std::to_string(session_id);
    Result<std::int64_t> stored =
        query_int(db, "SELECT coalesce(max(run), 0) FROM session_runs WHERE session_id = " + id,
                  "counting a session's runs");
    MONOPLANE_TRY(stored);
    if (*stored > 0) return static_cast<int>(*stored);
    Result<std::int64_t> earlier = query_int(
        db,
        "SELECT EXISTS (SELECT 1 FROM events WHERE session_id = " + id +
            " AND detail IS NULL) OR EXISTS (SELECT 1 FROM frames WHERE session_id = " + id + ")",
        "looking for runs before schema version 8");
    MONOPLANE_TRY(earlier);
    return static_cast<int>(*earlier);
}

// The latest time the session stored (events and frames), or none.
Result<std::optional<std::int64_t>> last_time(const Connection& db, std::int64_t session_id) {
    Result<Statement> stmt =
        Statement::prepare(db,
                           "SELECT (SELECT max(time_ns) FROM events WHERE session_id = ?1), "
                           "(SELECT max(display_time_ns) FROM frames WHERE session_id = ?1)");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    MONOPLANE_TRY(stmt.value().step("reading the session's latest time"));
    std::optional<std::int64_t> last;
    for (int column : {0, 1})
        if (!stmt->is_null(column))
            last = std::max(last.value_or(stmt->int64(column)), stmt->int64(column));
    return last;
}

Result<std::string> session_runtime(const Connection& db, std::int64_t session_id) {
    Result<Statement> stmt = Statement::prepare(db, "SELECT runtime FROM sessions WHERE id = ?");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    Result<bool> found = stmt.value().step("reading the session's runtime");
    MONOPLANE_TRY(found);
    if (!*found)
        return Error{"no session " + std::to_string(session_id) + " in study database '" +
                     db.path() + "'"};
    return stmt->text(0);
}

}  // namespace

Result<RunStart> write_run(const Connection& db, std::int64_t session_id, const RunInfo& info,
                           const RunRecord& who) {
    Result<std::string> runtime = session_runtime(db, session_id);
    MONOPLANE_TRY(runtime);
    Result<int> before = runs_before(db, session_id);
    MONOPLANE_TRY(before);
    Result<std::optional<std::int64_t>> last = last_time(db, session_id);
    MONOPLANE_TRY(last);
    Result<std::int64_t> first_frame = next_frame_number(db, session_id);
    MONOPLANE_TRY(first_frame);
    const RunStart start = plan_run(*before + 1, *last, *first_frame, info.clock_start_ns);

    Result<Statement> row = Statement::prepare(
        db,
        "INSERT INTO session_runs (session_id, run, started_utc, host, pid, runtime, first_frame, "
        "clock_offset_ns) VALUES (?, ?, ?, ?, ?, ?, ?, ?)");
    MONOPLANE_TRY(row);
    Statement& s = row.value();
    s.bind(1, session_id).bind(2, start.run).bind(3, who.started_utc).bind(4, who.host);
    s.bind(5, static_cast<std::int64_t>(who.pid));
    s.bind(6, info.runtime.empty() ? *runtime : info.runtime);
    s.bind(7, start.first_frame).bind(8, start.clock_offset_ns);
    MONOPLANE_TRY(s.run("recording run " + std::to_string(start.run) + " of session " +
                        std::to_string(session_id)));
    // The run's start in the events, where a replay of them sees every trial's run end.
    Result<Statement> event = Statement::prepare(
        db,
        "INSERT INTO events (session_id, trial_index, kind, label, time_ns, frame) "
        "VALUES (?, NULL, 'run_started', 0, ?, -1)");
    MONOPLANE_TRY(event);
    event.value().bind(1, session_id).bind(2, start.start_ns);
    MONOPLANE_TRY(event.value().run("recording the start of run " + std::to_string(start.run)));
    return start;
}

Result<std::vector<RunRecord>> read_runs(const Connection& db, std::int64_t session_id) {
    Result<Statement> stmt = Statement::prepare(
        db,
        "SELECT run, started_utc, host, pid, runtime, first_frame, clock_offset_ns FROM "
        "session_runs WHERE session_id = ? ORDER BY run");
    MONOPLANE_TRY(stmt);
    stmt.value().bind(1, session_id);
    std::vector<RunRecord> runs;
    for (;;) {
        Result<bool> row = stmt.value().step("reading a session's runs");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const Statement& s = stmt.value();
        runs.push_back(RunRecord{.run = s.int32(0),
                                 .started_utc = s.text(1),
                                 .host = s.text(2),
                                 .pid = static_cast<long>(s.int64(3)),
                                 .runtime = s.text(4),
                                 .first_frame = s.int64(5),
                                 .clock_offset_ns = s.int64(6)});
    }
    return runs;
}

}  // namespace monoplane::study
