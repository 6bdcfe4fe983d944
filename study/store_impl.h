// Private to the study store: the state behind StudyStore, shared by the file that opens it
// (store_open.cpp: creating, checking, migrating, read-only snapshots) and those that read and
// write sessions (store_begin_session.cpp, store_writes.cpp, store_reads.cpp, store_roster.cpp).
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "study/frame_queue.h"
#include "study/store_snapshot.h"
#include "study/store_sqlite.h"
#include "study/study_store.h"

namespace monoplane::study {

struct StudyStore::Impl {
    // Read-only stores read a private copy (store_snapshot.h), removed with the store. Declared
    // first so it is destroyed last, after the connection on it has closed.
    std::optional<StoreSnapshot> snapshot;
    std::filesystem::path file;  // as the caller named it (session holds lie beside it)
    sqlite::Connection db;       // on `file`, or on the snapshot's copy of it (read-only)
    FrameQueue frames;           // the frame log's rows not yet written
    bool read_only = false;
    int found_schema_version = 0;  // as the file was when opened, before any migration
    std::optional<std::filesystem::path> schema_backup;  // the copy kept before migrating

    // Inside a durable write's open transaction: the queued frames go with it.
    Result<void> write_queued_frames() const { return frames.write(db); }
    // Commits a durable write's transaction; the frames it carried leave the queue.
    Result<void> commit_written(sqlite::Transaction& tx, std::string_view what) {
        Result<void> ok = tx.commit(what);
        if (ok) frames.clear();
        return ok;
    }

    Error no_session(std::int64_t id) const {
        return Error{"no session " + std::to_string(id) + " in study database '" + db.path() + "'"};
    }

    Result<void> require_session(std::int64_t id) const {
        Result<sqlite::Statement> stmt =
            sqlite::Statement::prepare(db, "SELECT 1 FROM sessions WHERE id = ?");
        MONOPLANE_TRY(stmt);
        stmt.value().bind(1, id);
        Result<bool> row = stmt.value().step("looking up a session");
        MONOPLANE_TRY(row);
        if (!*row) return no_session(id);
        return Ok{};
    }
};

// The refusal of a write to a file the user may only read, naming what still works.
Error read_only_file(const std::string& file);

}  // namespace monoplane::study
