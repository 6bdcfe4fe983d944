// A private copy of a study database, for the commands that only read it. Opening the file itself
// read-only is not enough: SQLite then creates -wal and -shm files beside it (and leaves them),
// cannot open a WAL database in a folder the reader may not write, and the store would migrate an
// older schema in place. A copy in a private temporary folder can be opened, recovered and
// migrated freely while the original keeps every byte.
#pragma once

#include <filesystem>

#include "common/result.h"

namespace monoplane::study {

class StoreSnapshot {
  public:
    // Copies `original` and its write-ahead log (if there is one; the -shm index is rebuilt from
    // it) into a new folder under the temporary directory. A live session may be writing: the
    // copy is retried when a checkpoint or a new log ran during it (the file's size or time, or
    // the log's salt, changed), so the copy is one committed state. Needs read access only.
    // Any time; the copy is removed with the object.
    static Result<StoreSnapshot> take(const std::filesystem::path& original);

    StoreSnapshot(StoreSnapshot&& other) noexcept;
    StoreSnapshot& operator=(StoreSnapshot&& other) noexcept;
    StoreSnapshot(const StoreSnapshot&) = delete;
    StoreSnapshot& operator=(const StoreSnapshot&) = delete;
    ~StoreSnapshot();

    // The copy of the database (its log beside it, as "<copy>-wal").
    const std::filesystem::path& copy() const { return copy_; }

  private:
    StoreSnapshot(std::filesystem::path folder, std::filesystem::path copy)
        : folder_(std::move(folder)), copy_(std::move(copy)) {}
    std::filesystem::path folder_;
    std::filesystem::path copy_;
};

}  // namespace monoplane::study
