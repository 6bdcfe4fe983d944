// Which process runs a session: a session being run (or resumed) is held by that process, so a
// second `study resume`, the roster and the launcher can refuse it and say who holds it. The
// hold is an open-file-description lock (fcntl F_OFD_SETLK) on one byte of a lock file beside the
// database (`<database>-holds`, created readable by its owner only): the operating system
// releases it when the process ends, however it ends (SIGKILL, power loss), so a dead session
// resumes at once; nothing in the database says "running" for a process that no longer exists.
// The file is a row of 128-byte text lines, line n for session id n: the hold locks the line's
// first byte (offset 128 n), and the line says who holds it ("pid host since", space-padded),
// for the message only: a line whose byte is not locked is stale and ignored.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "common/result.h"

namespace monoplane::study {

struct SessionHolder {
    long pid = 0;
    std::string host;
    std::string since_utc;  // ISO 8601 UTC

    // "process 1234 on lab-pc-2 since 2026-12-03T10:15:00Z"
    std::string describe() const;
};

// This machine's name as holds and a session's runs record it. Any time.
std::string host_name();

class SessionHold {
  public:
    // Takes the hold on `session_id` of the database at `database`, or says who has it:
    // "session 3 is being run by process 1234 on lab-pc-2 since ...". Held until the object
    // is destroyed or the process ends. Any time; not twice for one session in one process.
    static Result<SessionHold> acquire(const std::filesystem::path& database,
                                       std::int64_t session_id);
    // Who holds the session now, or none (a session nobody runs, or whose process died).
    static Result<std::optional<SessionHolder>> holder(const std::filesystem::path& database,
                                                       std::int64_t session_id);

    SessionHold(SessionHold&& other) noexcept;
    SessionHold& operator=(SessionHold&& other) noexcept;
    SessionHold(const SessionHold&) = delete;
    SessionHold& operator=(const SessionHold&) = delete;
    ~SessionHold();

  private:
    SessionHold(int fd, std::int64_t session_id) : fd_(fd), session_id_(session_id) {}
    int fd_ = -1;
    std::int64_t session_id_ = 0;
};

}  // namespace monoplane::study
