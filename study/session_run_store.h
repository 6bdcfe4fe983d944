// Private to the study store: the session_runs table (schema version 8; docs/data.md). Each run
// of a session (its start and every resume) gets its row and a run_started event in one
// transaction, with the offset that puts its clock on the session's time axis (session_runs.h).
#pragma once

#include <cstdint>
#include <vector>

#include "common/result.h"
#include "study/session_runs.h"
#include "study/store_sqlite.h"

namespace monoplane::study {

// The next run of the session, inside the caller's open transaction: numbered after the stored
// runs (a session with events but no run rows ran before schema 8: that was run 1), its first
// frame after every frame the frame log or an event names, its clock placed after the latest time
// stored (plan_run). `who`: the run's started_utc, host, pid and runtime (empty: the session's).
Result<RunStart> write_run(const sqlite::Connection& db, std::int64_t session_id,
                           const RunInfo& info, const RunRecord& who);

// The session's runs, by run number.
Result<std::vector<RunRecord>> read_runs(const sqlite::Connection& db, std::int64_t session_id);

}  // namespace monoplane::study
