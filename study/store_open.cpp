// Opening a study database: the three ways a command may use one (study_store.h), the checks
// that refuse a file before anything is written, the schema migrations with a copy of the
// original kept, and the private snapshot the reading commands work on.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "study/session_uuid.h"
#include "study/store_impl.h"
#include "study/store_schema.h"
#include "study/study_file_check.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;
using sqlite::Connection;
using sqlite::query_int;
using sqlite::Statement;
using sqlite::Transaction;

// Refuses, before SQLite opens it, an existing file the user may not write, or one that is not
// a regular file.
Result<void> open_writable(const std::string& file) {
    const int fd = ::open(file.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) {
        const int err = errno;
        if (err == EACCES || err == EROFS || err == EPERM) return read_only_file(file);
        return Error{"cannot open study database '" + file + "': " + std::strerror(err) +
                     "; check that its directory exists and is writable by you."};
    }
    struct stat st {};
    const bool regular = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode);
    ::close(fd);
    if (!regular) return Error{"study database '" + file + "' is not a regular file"};
    return Ok{};
}

// SQLite gives the -wal and -shm files the database file's mode; this makes sure they are never
// more open than the database, whatever created them.
void restrict_sidecars(const std::string& file) {
    struct stat db {};
    if (::stat(file.c_str(), &db) != 0) return;
    for (const char* suffix : {"-wal", "-shm"}) {
        const std::string side = file + suffix;
        struct stat st {};
        if (::stat(side.c_str(), &st) == 0 && (st.st_mode & 077 & ~db.st_mode) != 0)
            ::chmod(side.c_str(), db.st_mode & 0777);
    }
}

void remove_files(const std::string& file) {
    for (const char* suffix : {"", "-wal", "-shm"}) ::unlink((file + suffix).c_str());
}

Error newer_schema(const Connection& db, std::int64_t version) {
    return Error{"study database '" + db.path() + "' has schema version " +
                 std::to_string(version) + ", newer than this build of monoplane knows (" +
                 std::to_string(StudyStore::kSchemaVersion) +
                 "); open it with a newer monoplane. It was not changed."};
}

Error foreign(const Connection& db, const std::string& why) {
    return Error{"'" + db.path() + "' is a SQLite database of another program (" + why +
                 "), not a study database; it was not changed. Give a study's .sqlite file, or a "
                 "new file name to start one."};
}

// Tells ours from another program's database by reading only: switching to WAL mode or setting
// the application id would already change its header. Returns the schema version.
Result<std::int64_t> check_ours(const Connection& db) {
    // The first read also tells a database from another file (SQLITE_NOTADB) and sees locks.
    Result<std::int64_t> version =
        query_int(db, "PRAGMA user_version", "reading the schema version");
    MONOPLANE_TRY(version);
    if (*version == 0) {
        Result<std::int64_t> objects =
            query_int(db, "SELECT count(*) FROM sqlite_schema", "reading the schema");
        MONOPLANE_TRY(objects);
        if (*objects > 0)
            return foreign(db, "it has " + std::to_string(*objects) +
                                   " schema objects but no monoplane schema version");
        return version;  // an empty SQLite file: a study is made in it
    }
    Result<std::int64_t> id = query_int(db, "PRAGMA application_id", "reading the application id");
    MONOPLANE_TRY(id);
    if (*id != kStoreApplicationId) return foreign(db, "application_id " + std::to_string(*id));
    if (*version > StudyStore::kSchemaVersion) return newer_schema(db, *version);
    return version;
}

// A damaged page refuses the file before any command works on it (quick_check: each page's
// structure, not the indexes' agreement with their tables).
Result<void> check_integrity(const Connection& db) {
    Result<Statement> stmt = Statement::prepare(db, "PRAGMA quick_check(3)");
    MONOPLANE_TRY(stmt);
    std::string problems;
    for (;;) {
        Result<bool> row = stmt.value().step("checking the file's integrity");
        MONOPLANE_TRY(row);
        if (!*row) break;
        const std::string line = stmt->text(0);
        if (line == "ok") return Ok{};
        problems += (problems.empty() ? "" : "; ") + line;
    }
    return Error{"study database '" + db.path() + "' is damaged (" + problems +
                 "); nothing was written. Restore it from a backup or the lab PC's original."};
}

// The first of FILE.schema<N>.bak, FILE.schema<N>.1.bak, ... that does not exist yet.
fs::path free_backup_name(const fs::path& file, std::int64_t version) {
    const std::string stem = file.string() + ".schema" + std::to_string(version);
    fs::path name = stem + ".bak";
    std::error_code ec;
    for (int n = 1; fs::exists(name, ec); ++n) name = stem + "." + std::to_string(n) + ".bak";
    return name;
}

// Copies the database as it is (its log included) before a migration changes it, so the older
// monoplane that wrote it can still open the copy.
Result<fs::path> keep_backup(const Connection& db, const fs::path& file, std::int64_t version) {
    const fs::path backup = free_backup_name(file, version);
    sqlite3* raw = nullptr;
    const int rc =
        sqlite3_open_v2(backup.c_str(), &raw, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr);
    Connection target(raw, backup.string(), 0);
    if (rc != SQLITE_OK) return target.error(rc, "keeping a copy before migrating");
    ::chmod(backup.c_str(), 0600);
    sqlite3_backup* copy = sqlite3_backup_init(raw, "main", db.get(), "main");
    if (copy == nullptr) return target.error(sqlite3_errcode(raw), "keeping a copy");
    const int step = sqlite3_backup_step(copy, -1);
    sqlite3_backup_finish(copy);
    if (step != SQLITE_DONE) {
        Error failed = target.error(step, "keeping a copy before migrating");
        std::error_code ec;
        fs::remove(backup, ec);
        return failed;
    }
    return backup;
}

// Gives every session written before schema version 8 its derived id (session_uuid.h): from
// the fields no copy changes, so a file migrated in place and a copy of it only read agree.
Result<void> derive_session_uuids(const Connection& db) {
    Result<Statement> select = Statement::prepare(
        db,
        "SELECT s.id, p.code, s.session_number, s.started_utc, s.seed, s.protocol_hash, s.hmd, "
        "s.device, s.runtime, s.observer FROM sessions s JOIN participants p "
        "ON p.id = s.participant_id WHERE s.session_uuid IS NULL");
    MONOPLANE_TRY(select);
    Result<Statement> update =
        Statement::prepare(db, "UPDATE sessions SET session_uuid = ? WHERE id = ?");
    MONOPLANE_TRY(update);
    for (;;) {
        Result<bool> row = select.value().step("reading sessions without an id");
        MONOPLANE_TRY(row);
        if (!*row) break;
        std::string identity = "monoplane session";
        for (int column = 1; column <= 9; ++column) identity += '\n' + select->text(column);
        update.value().reset();
        update.value().bind(1, derived_session_uuid(identity)).bind(2, select->int64(0));
        MONOPLANE_TRY(update.value().run("giving an earlier session its id"));
    }
    return Ok{};
}

// Brings the schema to kSchemaVersion in one transaction. `found` is the version check_ours
// read; another process may have migrated since, so the version is read again under the lock.
Result<void> migrate(const Connection& db, std::int64_t found) {
    if (found == StudyStore::kSchemaVersion) return Ok{};
    Result<Transaction> tx = Transaction::begin(db, "migrating the schema");
    MONOPLANE_TRY(tx);
    Result<std::int64_t> version = check_ours(db);
    MONOPLANE_TRY(version);
    if (*version == StudyStore::kSchemaVersion) return Ok{};
    if (*version == 0)
        MONOPLANE_TRY(db.exec("PRAGMA application_id = " + std::to_string(kStoreApplicationId)));
    const auto steps = store_migrations();
    static_assert(StudyStore::kSchemaVersion >= 1);
    for (std::int64_t v = *version; v < StudyStore::kSchemaVersion; ++v)
        MONOPLANE_TRY(db.exec(steps[static_cast<std::size_t>(v)]));
    MONOPLANE_TRY(derive_session_uuids(db));
    MONOPLANE_TRY(db.exec("PRAGMA user_version = " + std::to_string(StudyStore::kSchemaVersion)));
    return tx.value().commit("migrating the schema");
}

// WAL: readers (an export, the experimenter's view) never block the study's writes.
Result<void> switch_to_wal(const Connection& db) {
    Result<Statement> stmt = Statement::prepare(db, "PRAGMA journal_mode = WAL");
    MONOPLANE_TRY(stmt);
    Result<bool> row = stmt.value().step("switching to WAL mode");
    MONOPLANE_TRY(row);
    if (!*row || stmt->text(0) != "wal")
        return Error{"study database '" + db.path() + "' could not be switched to WAL mode"};
    return Ok{};
}

// How one open goes: which file SQLite opens, and what it may do to it.
struct OpenRequest {
    std::string sqlite_file;  // the database, or the snapshot's copy of it
    StoreOptions options;
    bool read_only = false;       // a snapshot: migrated in the copy, then no writes at all
    bool keep_backup = false;     // a written file: copy it before migrating an older schema
    bool may_initialise = false;  // an empty SQLite file becomes a study (Create only)
};

Result<void> connect(StudyStore::Impl& impl, const OpenRequest& r) {
    sqlite3* raw = nullptr;
    // No SQLITE_OPEN_CREATE: the file exists by now. FULLMUTEX: the experimenter window may
    // read from another thread than the runner writes from.
    const int rc = sqlite3_open_v2(r.sqlite_file.c_str(), &raw,
                                   SQLITE_OPEN_READWRITE | SQLITE_OPEN_FULLMUTEX, nullptr);
    // Messages name the file the user gave, also when SQLite reads a copy of it.
    impl.db = Connection(raw, impl.file.string(), r.options.busy_timeout_ms);  // closes `raw`
    if (rc != SQLITE_OK) return impl.db.error(rc, "opening it");
    sqlite3_extended_result_codes(raw, 1);
    sqlite3_busy_timeout(raw, r.options.busy_timeout_ms);
    if (sqlite3_db_readonly(raw, "main") == 1) return read_only_file(impl.file.string());
    return Ok{};
}

Result<void> open_connection(StudyStore::Impl& impl, const OpenRequest& r) {
    MONOPLANE_TRY(connect(impl, r));
    Result<std::int64_t> version = check_ours(impl.db);
    MONOPLANE_TRY(version);
    impl.found_schema_version = static_cast<int>(*version);
    if (*version == 0 && !r.may_initialise)
        return Error{"'" + impl.file.string() +
                     "' is an empty SQLite database, not a study database (no study was ever "
                     "started in it); it was not changed."};
    if (*version > 0) MONOPLANE_TRY(check_integrity(impl.db));
    MONOPLANE_TRY(switch_to_wal(impl.db));
    // FULL: the WAL is synced at every commit, so an event is on disk when append_event returns.
    // A snapshot is thrown away: no sync.
    MONOPLANE_TRY(
        impl.db.exec(r.read_only ? "PRAGMA synchronous = OFF" : "PRAGMA synchronous = FULL"));
    MONOPLANE_TRY(impl.db.exec("PRAGMA foreign_keys = ON"));
    if (r.options.max_page_count > 0) {
        MONOPLANE_TRY(query_int(
            impl.db, "PRAGMA max_page_count = " + std::to_string(r.options.max_page_count),
            "limiting the database size"));
    }
    if (r.keep_backup && *version > 0 && *version < StudyStore::kSchemaVersion) {
        Result<fs::path> backup = keep_backup(impl.db, impl.file, *version);
        MONOPLANE_TRY(backup);
        impl.schema_backup = *backup;
    }
    MONOPLANE_TRY(migrate(impl.db, *version));
    // A snapshot's store refuses every write: the commands that read must not be able to.
    if (r.read_only) MONOPLANE_TRY(impl.db.exec("PRAGMA query_only = ON"));
    return Ok{};
}

// Makes a new, empty study at `path` as a whole: the schema is written into a private file
// beside it, which is then linked into place. No process ever sees a 0-byte or half-made study
// (it would be refused as a failed copy), and of two processes creating the same file at once
// one links it and the other opens it.
Result<void> create_study_file(const fs::path& path, const StoreOptions& options) {
    const std::string folder = path.parent_path().empty() ? "." : path.parent_path().string();
    std::string temp = folder + "/." + path.filename().string() + ".new-XXXXXX";
    const int fd = ::mkstemp(temp.data());  // mode 0600
    if (fd < 0) {
        const int err = errno;
        return Error{"cannot create study database '" + path.string() + "': " + std::strerror(err) +
                     "; check that its directory exists and is writable by you."};
    }
    ::close(fd);
    Result<void> made = [&]() -> Result<void> {
        StudyStore::Impl impl;
        impl.file = path;
        return open_connection(
            impl, OpenRequest{.sqlite_file = temp, .options = options, .may_initialise = true});
    }();  // closed here: the log is checkpointed into the file and removed
    if (made && ::link(temp.c_str(), path.c_str()) != 0 && errno != EEXIST) {
        const int err = errno;
        made = Error{"cannot create study database '" + path.string() + "': " + std::strerror(err) +
                     "."};
    }
    remove_files(temp);
    return made;
}

// The writers' open (run, resume, note, migrate): Create makes a missing file first.
Result<std::unique_ptr<StudyStore::Impl>> open_for_writing(const fs::path& path,
                                                           const StoreOptions& options,
                                                           StudyFileUse use) {
    Result<StudyFileState> state = check_study_file(path, use);
    MONOPLANE_TRY(state);
    if (!state->exists) {
        MONOPLANE_TRY(create_study_file(path, options));
        state = check_study_file(path, StudyFileUse::Existing);
        MONOPLANE_TRY(state);
    }
    const std::string file = path.string();
    Result<void> writable = open_writable(file);
    MONOPLANE_TRY(writable);
    auto impl = std::make_unique<StudyStore::Impl>();
    impl->file = path;
    MONOPLANE_TRY(open_connection(
        *impl, OpenRequest{.sqlite_file = file, .options = options, .keep_backup = true}));
    restrict_sidecars(file);
    return impl;
}

}  // namespace

Error read_only_file(const std::string& file) {  // store_impl.h
    return Error{"study database '" + file +
                 "' is read-only for you: `study list`, `study export` and `analyze` can read "
                 "it, but running, resuming or noting a session needs write access to the file "
                 "and its folder."};
}

StudyStore::StudyStore(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
StudyStore::~StudyStore() = default;

Result<std::unique_ptr<StudyStore>> StudyStore::open(const fs::path& path) {
    return open(path, StoreOptions{});
}

Result<std::unique_ptr<StudyStore>> StudyStore::open(const fs::path& path,
                                                     const StoreOptions& options) {
    Result<std::unique_ptr<Impl>> impl = open_for_writing(path, options, StudyFileUse::Create);
    MONOPLANE_TRY(impl);
    return std::unique_ptr<StudyStore>(new StudyStore(std::move(impl).value()));
}

Result<std::unique_ptr<StudyStore>> StudyStore::open_existing(const fs::path& path,
                                                              const StoreOptions& options) {
    Result<std::unique_ptr<Impl>> impl = open_for_writing(path, options, StudyFileUse::Existing);
    MONOPLANE_TRY(impl);
    return std::unique_ptr<StudyStore>(new StudyStore(std::move(impl).value()));
}

Result<std::unique_ptr<StudyStore>> StudyStore::open_read_only(const fs::path& path,
                                                               const StoreOptions& options) {
    MONOPLANE_TRY(check_study_file(path, StudyFileUse::Read));
    Result<StoreSnapshot> snapshot = StoreSnapshot::take(path);
    MONOPLANE_TRY(snapshot);
    auto impl = std::make_unique<Impl>();
    impl->snapshot.emplace(std::move(snapshot).value());
    impl->file = path;
    impl->read_only = true;
    MONOPLANE_TRY(open_connection(*impl, OpenRequest{.sqlite_file = impl->snapshot->copy().string(),
                                                     .options = options,
                                                     .read_only = true}));
    return std::unique_ptr<StudyStore>(new StudyStore(std::move(impl)));
}

int StudyStore::found_schema_version() const {
    return impl_->found_schema_version;
}

const std::optional<fs::path>& StudyStore::schema_backup() const {
    return impl_->schema_backup;
}

bool StudyStore::read_only() const {
    return impl_->read_only;
}

}  // namespace monoplane::study
