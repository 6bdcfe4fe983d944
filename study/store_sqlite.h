// Private to the study store: a thin RAII layer over the SQLite C API. The C API rather than
// SQLiteCpp because failures are the normal path here (locked, full, not a database) and the
// store must turn each into a Result with a message naming the file; SQLiteCpp reports them as
// exceptions, which monoplane keeps for main() only.
#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "common/result.h"

namespace monoplane::study::sqlite {

// Owns one connection. Errors name the database file, which is what a user can act on.
class Connection {
  public:
    Connection() = default;
    Connection(sqlite3* db, std::string path, int busy_timeout_ms)
        : db_(db), path_(std::move(path)), busy_timeout_ms_(busy_timeout_ms) {}
    Connection(Connection&& other) noexcept;
    Connection& operator=(Connection&& other) noexcept;
    Connection(const Connection&) = delete;
    Connection& operator=(const Connection&) = delete;
    ~Connection();

    sqlite3* get() const { return db_; }
    const std::string& path() const { return path_; }

    // Runs statements without results (DDL, PRAGMA, BEGIN/COMMIT).
    Result<void> exec(std::string_view sql) const;
    // The error for the connection's last failed call, phrased for the user: `what` says what
    // the store was doing ("appending an event").
    Error error(int rc, std::string_view what) const;

  private:
    sqlite3* db_ = nullptr;
    std::string path_;
    int busy_timeout_ms_ = 0;  // for the message when the database stays locked
};

// One prepared statement; bind by 1-based index, step, read columns by 0-based index.
class Statement {
  public:
    static Result<Statement> prepare(const Connection& db, std::string_view sql);
    Statement(Statement&& other) noexcept : db_(other.db_), stmt_(other.stmt_) {
        other.stmt_ = nullptr;
    }
    Statement(const Statement&) = delete;
    Statement& operator=(const Statement&) = delete;
    Statement& operator=(Statement&&) = delete;
    ~Statement();

    Statement& bind(int index, std::int64_t value);
    Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
    Statement& bind(int index, double value);
    Statement& bind(int index, std::string_view value);
    Statement& bind_null(int index);
    // The value, or NULL when there is none.
    template <class T>
    Statement& bind(int index, const std::optional<T>& value) {
        return value ? bind(index, *value) : bind_null(index);
    }

    // True while a row is available, false when done; an error names the file and `what`.
    Result<bool> step(std::string_view what);
    // Steps a statement that returns no rows.
    Result<void> run(std::string_view what);
    // Makes the statement ready to run again with new bindings.
    void reset();

    bool is_null(int column) const;
    std::int64_t int64(int column) const;
    int int32(int column) const { return static_cast<int>(int64(column)); }
    double real(int column) const;
    std::string text(int column) const;

  private:
    Statement(const Connection* db, sqlite3_stmt* stmt) : db_(db), stmt_(stmt) {}
    const Connection* db_;
    sqlite3_stmt* stmt_;
};

// BEGIN IMMEDIATE (the write lock up front, so a locked database fails before any work) and a
// ROLLBACK unless commit() succeeded: a failed call leaves nothing half-written.
class Transaction {
  public:
    static Result<Transaction> begin(const Connection& db, std::string_view what);
    Transaction(Transaction&& other) noexcept : db_(other.db_), open_(other.open_) {
        other.open_ = false;
    }
    Transaction(const Transaction&) = delete;
    Transaction& operator=(const Transaction&) = delete;
    Transaction& operator=(Transaction&&) = delete;
    ~Transaction();
    Result<void> commit(std::string_view what);

  private:
    explicit Transaction(const Connection* db) : db_(db), open_(true) {}
    const Connection* db_;
    bool open_;
};

// The first column of the first row of `sql` as an integer (0 when there is no row).
Result<std::int64_t> query_int(const Connection& db, std::string_view sql, std::string_view what);

}  // namespace monoplane::study::sqlite
