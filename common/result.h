// Runtime-failure channel: functions that can fail because of the user's
// input or the machine (bad file, no device) return Result<T>; programming errors assert.
#pragma once

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

}  // namespace monoplane
