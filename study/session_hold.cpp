#include "study/session_hold.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstring>
#include <utility>

#include "common/utc_time.h"

namespace monoplane::study {
namespace {

// Each session owns one line of the lock file: the hold is a lock on the line's first byte, the
// line says who holds it. Fixed width, so a line is found by arithmetic and rewritten in place.
constexpr std::int64_t kLineBytes = 128;
// Ids beyond this would put the line past what off_t addresses comfortably; SQLite's row ids of a
// study database stay far below it.
constexpr std::int64_t kMaxSessionId = std::int64_t{1} << 40;

std::string lock_file(const std::filesystem::path& database) {
    // The file as it really is: a symbolic link or another spelling of the database's path must
    // find the same holds (SQLite writes to the link's target).
    std::error_code error;
    const std::filesystem::path real = std::filesystem::weakly_canonical(database, error);
    return (error ? database : real).string() + "-holds";
}

struct flock byte_lock(short type, std::int64_t session_id) {
    struct flock lock {};
    lock.l_type = type;
    lock.l_whence = SEEK_SET;
    lock.l_start = static_cast<off_t>(session_id * kLineBytes);
    lock.l_len = 1;
    lock.l_pid = 0;  // required by F_OFD_*: the lock belongs to the open file description
    return lock;
}

Error io_error(const std::string& what, const std::string& file, int err) {
    return Error{"cannot " + what + " session lock file '" + file + "': " + std::strerror(err) +
                 "; check that the database's directory is writable by you."};
}

// The line written for a hold: "pid host since", padded with spaces, ending in a newline.
std::string holder_line(const SessionHolder& h) {
    std::string line = std::to_string(h.pid) + " " + h.host + " " + h.since_utc;
    line.resize(kLineBytes - 1, ' ');
    line += '\n';
    return line;
}

// Reads the line of a held session. A line not (yet) written reads as an unknown holder: the
// hold is the lock, the line only describes it.
SessionHolder read_holder(int fd, std::int64_t session_id) {
    std::array<char, kLineBytes + 1> line{};
    const ssize_t n =
        ::pread(fd, line.data(), kLineBytes, static_cast<off_t>(session_id * kLineBytes));
    SessionHolder holder{.pid = 0, .host = "an unknown host", .since_utc = "an unknown time"};
    if (n <= 0) return holder;
    long pid = 0;
    std::array<char, 65> host{};
    std::array<char, 33> since{};
    if (std::sscanf(line.data(), "%ld %64s %32s", &pid, host.data(), since.data()) == 3 &&
        pid > 0) {
        holder = SessionHolder{.pid = pid, .host = host.data(), .since_utc = since.data()};
    }
    return holder;
}

// Who holds the session's byte, as seen through `fd`; none when nobody does.
Result<std::optional<SessionHolder>> query(int fd, const std::string& file,
                                           std::int64_t session_id) {
    struct flock lock = byte_lock(F_WRLCK, session_id);
    if (::fcntl(fd, F_OFD_GETLK, &lock) != 0) return io_error("query", file, errno);
    if (lock.l_type == F_UNLCK) return std::optional<SessionHolder>();
    return std::optional<SessionHolder>(read_holder(fd, session_id));
}

Result<void> check_id(std::int64_t session_id) {
    if (session_id < 1 || session_id >= kMaxSessionId)
        return Error{"session id " + std::to_string(session_id) + " cannot be held (1 to 2^40)"};
    return Ok{};
}

// Locks the session's byte through `fd` and writes our line, or says who holds it.
Result<void> take(int fd, const std::filesystem::path& database, std::int64_t session_id) {
    const std::string file = lock_file(database);
    // A holder that lets go between our attempt and our query leaves nobody to name: try again.
    for (int attempt = 0; attempt < 3; ++attempt) {
        struct flock lock = byte_lock(F_WRLCK, session_id);
        if (::fcntl(fd, F_OFD_SETLK, &lock) == 0) {
            const SessionHolder me{.pid = static_cast<long>(::getpid()),
                                   .host = host_name(),
                                   .since_utc = utc_now_iso8601()};
            const std::string line = holder_line(me);
            // Best effort: the lock is the hold; the line only lets others name us.
            const ssize_t written =
                ::pwrite(fd, line.data(), line.size(), static_cast<off_t>(session_id * kLineBytes));
            (void)written;
            return Ok{};
        }
        if (errno != EAGAIN && errno != EACCES) return io_error("lock", file, errno);
        Result<std::optional<SessionHolder>> holder = query(fd, file, session_id);
        MONOPLANE_TRY(holder);
        if (*holder)
            return Error{"session " + std::to_string(session_id) + " of study database '" +
                         database.string() + "' is being run by " + (*holder)->describe() +
                         "; wait until it ends there, or stop that process and resume the "
                         "session."};
    }
    return Error{"session " + std::to_string(session_id) + " of study database '" +
                 database.string() + "' is being taken and released by other processes; retry."};
}

}  // namespace

// One word of at most 64 characters: it goes into a fixed-width line.
std::string host_name() {
    std::array<char, 256> name{};
    if (::gethostname(name.data(), name.size() - 1) != 0) return "unknown-host";
    std::string host(name.data());
    if (host.empty()) return "unknown-host";
    if (host.size() > 64) host.resize(64);
    for (char& c : host)
        if (c <= ' ' || c == 0x7f) c = '?';
    return host;
}

std::string SessionHolder::describe() const {
    return "process " + std::to_string(pid) + " on " + host + " since " + since_utc;
}

Result<SessionHold> SessionHold::acquire(const std::filesystem::path& database,
                                         std::int64_t session_id) {
    MONOPLANE_TRY(check_id(session_id));
    const std::string file = lock_file(database);
    // O_CLOEXEC: a program this process starts must not keep the hold alive after it ends.
    const int fd = ::open(file.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    if (fd < 0) return io_error("open", file, errno);
    Result<void> taken = take(fd, database, session_id);
    if (!taken) {
        ::close(fd);  // not ours: the holder's line stays as it is
        return taken.error();
    }
    return SessionHold(fd, session_id);
}

Result<std::optional<SessionHolder>> SessionHold::holder(const std::filesystem::path& database,
                                                         std::int64_t session_id) {
    MONOPLANE_TRY(check_id(session_id));
    const std::string file = lock_file(database);
    // Read-only and never created: asking who runs a session changes nothing on disk.
    const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd < 0) {
        if (errno == ENOENT) return std::optional<SessionHolder>();  // nobody ever held one
        return io_error("open", file, errno);
    }
    Result<std::optional<SessionHolder>> found = query(fd, file, session_id);
    ::close(fd);
    return found;
}

SessionHold::SessionHold(SessionHold&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), session_id_(other.session_id_) {}

SessionHold& SessionHold::operator=(SessionHold&& other) noexcept {
    if (this != &other) {
        SessionHold released(std::move(*this));  // lets go of ours at the end of this scope
        fd_ = std::exchange(other.fd_, -1);
        session_id_ = other.session_id_;
    }
    return *this;
}

SessionHold::~SessionHold() {
    if (fd_ < 0) return;
    // Clearing the line is tidiness only (holder() ignores a line whose byte is not locked);
    // closing the last descriptor of the open file description releases the lock.
    const std::string blank(kLineBytes - 1, ' ');
    const std::string line = blank + '\n';
    const ssize_t written =
        ::pwrite(fd_, line.data(), line.size(), static_cast<off_t>(session_id_ * kLineBytes));
    (void)written;
    ::close(fd_);
}

}  // namespace monoplane::study
