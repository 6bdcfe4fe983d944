// Runtime-failure channel: functions that can fail because of the user's
// input or the machine (bad file, no device) return Result<T>; programming errors assert.
// A function with nothing to return but success returns Result<void> and ends with
// `return Ok{};`. A failure travels up with MONOPLANE_TRY (below).
#pragma once

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <variant>

namespace monoplane {

// A message a user can act on: what failed, where, and what to do.
struct Error {
    std::string message;
};

// Thrown only when an Error has to travel up to main(), which prints it and exits non-zero.
class UserError : public std::runtime_error {
  public:
    explicit UserError(const Error& error) : std::runtime_error(error.message) {}
    explicit UserError(const std::string& message) : std::runtime_error(message) {}
};

template <class T>
class [[nodiscard]] Result {
  public:
    Result(T value) : state_(std::move(value)) {}      // NOLINT: implicit by design
    Result(Error error) : state_(std::move(error)) {}  // NOLINT: implicit by design

    bool ok() const { return std::holds_alternative<T>(state_); }
    explicit operator bool() const { return ok(); }

    // May be called only when ok().
    const T& value() const& { return std::get<T>(state_); }
    T& value() & { return std::get<T>(state_); }
    T&& value() && { return std::get<T>(std::move(state_)); }
    const T* operator->() const { return &value(); }
    const T& operator*() const { return value(); }

    // May be called only when !ok().
    const Error& error() const { return std::get<Error>(state_); }

    // The value, or a UserError carrying the message: for call sites that hand failure to main().
    T value_or_throw() && {
        if (!ok()) throw UserError(error());
        return std::get<T>(std::move(state_));
    }

  private:
    std::variant<T, Error> state_;
};

// The success of a Result<void>: `return Ok{};`. A named tag rather than a default-constructed
// Result, so that success is always spelled out where a function decides it.
struct Ok {};

// Success or an Error, for an operation whose only outcome is whether it worked. (A Result<bool>
// is for a real yes/no answer that can also fail, such as "is there another row".)
template <>
class [[nodiscard]] Result<void> {
  public:
    Result(Ok /*success*/) {}                          // NOLINT: implicit by design
    Result(Error error) : error_(std::move(error)) {}  // NOLINT: implicit by design

    bool ok() const { return !error_.has_value(); }
    explicit operator bool() const { return ok(); }

    // May be called only when !ok().
    const Error& error() const { return *error_; }

    // Nothing, or a UserError carrying the message: for call sites that hand failure to main().
    void value_or_throw() const {
        if (!ok()) throw UserError(*error_);
    }

  private:
    std::optional<Error> error_;
};

}  // namespace monoplane

// Propagation: `MONOPLANE_TRY(expr);` evaluates `expr` (any Result<T>) once and, when it failed,
// returns its Error from the enclosing function (whose Result<U> takes it implicitly); else
// execution goes on. A value that is needed afterwards is named first, then tried:
//
//   Result<Statement> stmt = Statement::prepare(db, sql);
//   MONOPLANE_TRY(stmt);
//   MONOPLANE_TRY(stmt.value().run("adding a note"));
//
// Why a macro: returning from the caller is what propagation is, and C++ has no operator for it
// (no `?` as in Rust); a function cannot return on its caller's behalf, and the spelled-out
// `if (!r) return r.error();` repeated at every call hid the few places that do more than pass
// an error on (add context, clean up). Those keep their explicit `if`, so they stand out.
#define MONOPLANE_TRY(expr)                                                \
    do {                                                                   \
        if (auto&& monoplane_try_result_ = (expr); !monoplane_try_result_) \
            return monoplane_try_result_.error();                          \
    } while (false)
