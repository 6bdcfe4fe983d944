#include "study/store_sqlite.h"

#include <utility>

namespace monoplane::study::sqlite {

Connection::Connection(Connection&& other) noexcept
    : db_(std::exchange(other.db_, nullptr)),
      path_(std::move(other.path_)),
      busy_timeout_ms_(other.busy_timeout_ms_) {}

Connection& Connection::operator=(Connection&& other) noexcept {
    if (this != &other) {
        if (db_ != nullptr) sqlite3_close_v2(db_);
        db_ = std::exchange(other.db_, nullptr);
        path_ = std::move(other.path_);
        busy_timeout_ms_ = other.busy_timeout_ms_;
    }
    return *this;
}

Connection::~Connection() {
    // The last connection's close checkpoints the WAL into the database file.
    if (db_ != nullptr) sqlite3_close_v2(db_);
}

Result<void> Connection::exec(std::string_view sql) const {
    const std::string text(sql);
    const int rc = sqlite3_exec(db_, text.c_str(), nullptr, nullptr, nullptr);
    if (rc != SQLITE_OK) return error(rc, "running '" + text.substr(0, 60) + "'");
    return Ok{};
}

Error Connection::error(int rc, std::string_view what) const {
    const std::string file = "'" + path_ + "'";
    const std::string detail = db_ != nullptr ? sqlite3_errmsg(db_) : sqlite3_errstr(rc);
    const std::string doing(what);
    switch (rc & 0xff) {  // the primary code; extended codes refine it
        case SQLITE_BUSY:
        case SQLITE_LOCKED:
            return Error{"study database " + file +
                         " is locked by another connection (another "
                         "monoplane process or an open sqlite3 shell?); waited " +
                         std::to_string(busy_timeout_ms_) + " ms while " + doing +
                         ". Close the other program and retry; nothing was written."};
        case SQLITE_FULL:
            return Error{
                "disk full while " + doing + " in study database " + file +
                ": this change was not saved, earlier data are intact. Free space and retry "
                "(a started session continues with `monoplane study resume`)."};
        case SQLITE_NOTADB:
            return Error{file + " is not a SQLite database (" + detail +
                         "); give a new file name or an existing monoplane study database."};
        case SQLITE_CORRUPT:
            return Error{"study database " + file + " is damaged (" + detail + ") while " + doing +
                         "; nothing was written. Restore it from a backup or the lab PC's "
                         "original."};
        case SQLITE_READONLY:
            return Error{"study database " + file + " is read-only (" + detail + ") while " +
                         doing + "; check the file's and the directory's permissions."};
        case SQLITE_CANTOPEN:
            return Error{"cannot open study database " + file + " (" + detail + ") while " + doing +
                         "; check that its directory exists and is writable."};
        case SQLITE_CONSTRAINT:
            return Error{"study database " + file + " refused " + doing + ": " + detail};
        default:
            return Error{doing + " failed in study database " + file + ": " + detail};
    }
}

Result<Statement> Statement::prepare(const Connection& db, std::string_view sql) {
    sqlite3_stmt* stmt = nullptr;
    const int rc =
        sqlite3_prepare_v2(db.get(), sql.data(), static_cast<int>(sql.size()), &stmt, nullptr);
    if (rc != SQLITE_OK) {
        sqlite3_finalize(stmt);
        return db.error(rc, "preparing a statement");
    }
    return Statement(&db, stmt);
}

Statement::~Statement() {
    if (stmt_ != nullptr) sqlite3_finalize(stmt_);
}

// Bind errors (a wrong index, out of memory) surface at step(): SQLite keeps the statement
// unusable and step() reports the misuse, so binding can chain.
Statement& Statement::bind(int index, std::int64_t value) {
    sqlite3_bind_int64(stmt_, index, value);
    return *this;
}

Statement& Statement::bind(int index, double value) {
    sqlite3_bind_double(stmt_, index, value);
    return *this;
}

Statement& Statement::bind(int index, std::string_view value) {
    sqlite3_bind_text(stmt_, index, value.data(), static_cast<int>(value.size()), SQLITE_TRANSIENT);
    return *this;
}

Statement& Statement::bind_null(int index) {
    sqlite3_bind_null(stmt_, index);
    return *this;
}

Result<bool> Statement::step(std::string_view what) {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    return db_->error(rc, what);
}

Result<void> Statement::run(std::string_view what) {
    MONOPLANE_TRY(step(what));
    return Ok{};
}

void Statement::reset() {
    sqlite3_reset(stmt_);
    sqlite3_clear_bindings(stmt_);
}

bool Statement::is_null(int column) const {
    return sqlite3_column_type(stmt_, column) == SQLITE_NULL;
}

std::int64_t Statement::int64(int column) const {
    return sqlite3_column_int64(stmt_, column);
}

double Statement::real(int column) const {
    return sqlite3_column_double(stmt_, column);
}

std::string Statement::text(int column) const {
    const auto* data = reinterpret_cast<const char*>(sqlite3_column_text(stmt_, column));
    return data != nullptr ? std::string(data, sqlite3_column_bytes(stmt_, column)) : std::string();
}

Result<Transaction> Transaction::begin(const Connection& db, std::string_view what) {
    Result<void> begun = db.exec("BEGIN IMMEDIATE");
    if (!begun) {
        // Rephrase: "running 'BEGIN IMMEDIATE'" is not what the user asked for.
        const int rc = sqlite3_errcode(db.get());
        return db.error(rc, what);
    }
    return Transaction(&db);
}

Transaction::~Transaction() {
    if (open_) sqlite3_exec(db_->get(), "ROLLBACK", nullptr, nullptr, nullptr);
}

Result<void> Transaction::commit(std::string_view what) {
    const int rc = sqlite3_exec(db_->get(), "COMMIT", nullptr, nullptr, nullptr);
    if (rc != SQLITE_OK) return db_->error(rc, what);  // the destructor rolls back
    open_ = false;
    return Ok{};
}

Result<std::int64_t> query_int(const Connection& db, std::string_view sql, std::string_view what) {
    Result<Statement> stmt = Statement::prepare(db, sql);
    MONOPLANE_TRY(stmt);
    Result<bool> row = stmt.value().step(what);
    MONOPLANE_TRY(row);
    return *row ? stmt->int64(0) : 0;
}

}  // namespace monoplane::study::sqlite
