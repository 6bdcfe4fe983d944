// A session's hold (study/session_hold.h): one process runs a session at a time, the others are
// told which process on which machine has it since when, and a process that dies (SIGKILL)
// releases it at once, without anything to clean up.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstring>
#include <filesystem>
#include <string>

#include "study/session_hold.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

std::string this_host() {
    std::array<char, 256> name{};
    EXPECT_EQ(::gethostname(name.data(), name.size() - 1), 0);
    return name.data();
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A pipe between this process and a forked child.
struct Pipe {
    std::array<int, 2> fd{-1, -1};
    Pipe() { EXPECT_EQ(::pipe(fd.data()), 0); }
    ~Pipe() {
        for (int f : fd)
            if (f >= 0) ::close(f);
    }
    void write_text(const std::string& text) const {
        const ssize_t n = ::write(fd[1], text.data(), text.size());
        (void)n;
    }
    // Everything until the writer closes (or the first `bytes` bytes).
    std::string read_text(std::size_t bytes = 4096) {
        ::close(fd[1]);
        fd[1] = -1;
        std::string text;
        std::array<char, 512> chunk{};
        while (text.size() < bytes) {
            const ssize_t n = ::read(fd[0], chunk.data(), chunk.size());
            if (n <= 0) break;
            text.append(chunk.data(), static_cast<std::size_t>(n));
        }
        return text;
    }
};

int exit_code(pid_t child) {
    int status = 0;
    EXPECT_EQ(::waitpid(child, &status, 0), child);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
}

class SessionHoldTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "session_hold_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        db_ = dir_ / "c.sqlite";
    }
    void TearDown() override { fs::remove_all(dir_); }

    fs::path dir_;
    fs::path db_;
};

TEST_F(SessionHoldTest, TheHolderIsNamedWhileTheHoldLasts) {
    EXPECT_FALSE(*SessionHold::holder(db_, 3));         // no lock file yet: nobody
    EXPECT_FALSE(fs::exists(db_.string() + "-holds"));  // asking created nothing
    {
        Result<SessionHold> hold = SessionHold::acquire(db_, 3);
        ASSERT_TRUE(hold.ok()) << hold.error().message;
        struct stat st {};
        ASSERT_EQ(::stat((db_.string() + "-holds").c_str(), &st), 0);
        EXPECT_EQ(st.st_mode & 0777, 0600u);
        const Result<std::optional<SessionHolder>> holder = SessionHold::holder(db_, 3);
        ASSERT_TRUE(holder.ok()) << holder.error().message;
        ASSERT_TRUE(*holder);
        EXPECT_EQ((*holder)->pid, static_cast<long>(::getpid()));
        EXPECT_EQ((*holder)->host, this_host().substr(0, 64));
        ASSERT_EQ((*holder)->since_utc.size(), 20u) << (*holder)->since_utc;
        EXPECT_EQ((*holder)->since_utc[10], 'T');
        EXPECT_EQ((*holder)->describe(), "process " + std::to_string(::getpid()) + " on " +
                                             (*holder)->host + " since " + (*holder)->since_utc);
        // Other sessions are free.
        EXPECT_FALSE(*SessionHold::holder(db_, 2));
        EXPECT_FALSE(*SessionHold::holder(db_, 4));
        Result<SessionHold> other = SessionHold::acquire(db_, 4);
        ASSERT_TRUE(other.ok()) << other.error().message;
        // The same session again, even from this process: refused, naming the holder.
        const Result<SessionHold> again = SessionHold::acquire(db_, 3);
        ASSERT_FALSE(again.ok());
        EXPECT_TRUE(contains(again.error().message, "session 3 of study database '" + db_.string() +
                                                        "' is being run by process " +
                                                        std::to_string(::getpid()) + " on "))
            << again.error().message;
        // The refused attempt left the holder's line alone.
        EXPECT_EQ((*SessionHold::holder(db_, 3))->pid, static_cast<long>(::getpid()));
    }
    EXPECT_FALSE(*SessionHold::holder(db_, 3));  // released with the object
    EXPECT_FALSE(*SessionHold::holder(db_, 4));
    EXPECT_TRUE(SessionHold::acquire(db_, 3).ok());
}

TEST_F(SessionHoldTest, MovingAHoldKeepsItAndAssigningReleasesTheOld) {
    Result<SessionHold> first = SessionHold::acquire(db_, 1);
    ASSERT_TRUE(first.ok()) << first.error().message;
    SessionHold moved(std::move(first).value());
    EXPECT_TRUE(*SessionHold::holder(db_, 1));
    Result<SessionHold> second = SessionHold::acquire(db_, 2);
    ASSERT_TRUE(second.ok());
    moved = std::move(second).value();  // lets go of session 1, keeps session 2
    EXPECT_FALSE(*SessionHold::holder(db_, 1));
    EXPECT_TRUE(*SessionHold::holder(db_, 2));
}

TEST_F(SessionHoldTest, AnotherProcessIsToldWhoHoldsTheSession) {
    Result<SessionHold> hold = SessionHold::acquire(db_, 7);
    ASSERT_TRUE(hold.ok()) << hold.error().message;
    Pipe pipe;
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        const Result<SessionHold> taken = SessionHold::acquire(db_, 7);
        pipe.write_text(taken.ok() ? "acquired" : taken.error().message);
        ::_exit(taken.ok() ? 1 : 0);
    }
    const std::string message = pipe.read_text();
    EXPECT_EQ(exit_code(child), 0) << message;
    EXPECT_TRUE(contains(message, "session 7 of study database '" + db_.string() +
                                      "' is being run by process " + std::to_string(::getpid()) +
                                      " on " + this_host().substr(0, 64) + " since "))
        << message;
}

TEST_F(SessionHoldTest, AKilledHolderReleasesTheSessionAtOnce) {
    Pipe ready;
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        Result<SessionHold> hold = SessionHold::acquire(db_, 5);
        ready.write_text(hold.ok() ? "held" : hold.error().message);
        ::close(ready.fd[1]);
        for (;;) ::pause();  // holds until killed
    }
    const std::string said = ready.read_text(4);
    ASSERT_EQ(said, "held") << said;
    const Result<std::optional<SessionHolder>> holder = SessionHold::holder(db_, 5);
    ASSERT_TRUE(holder.ok() && *holder);
    EXPECT_EQ((*holder)->pid, static_cast<long>(child));
    const Result<SessionHold> refused = SessionHold::acquire(db_, 5);
    ASSERT_FALSE(refused.ok());
    EXPECT_TRUE(contains(refused.error().message, "process " + std::to_string(child) + " on "))
        << refused.error().message;

    ASSERT_EQ(::kill(child, SIGKILL), 0);
    EXPECT_EQ(exit_code(child), -SIGKILL);
    // Nothing to clean up: the dead process's line is stale and ignored, the session free.
    EXPECT_FALSE(*SessionHold::holder(db_, 5));
    const Result<SessionHold> taken = SessionHold::acquire(db_, 5);
    ASSERT_TRUE(taken.ok()) << taken.error().message;
    EXPECT_EQ((*SessionHold::holder(db_, 5))->pid, static_cast<long>(::getpid()));
}

TEST_F(SessionHoldTest, RefusesIdsItCannotHoldAndUnwritablePlaces) {
    EXPECT_FALSE(SessionHold::acquire(db_, 0).ok());
    EXPECT_FALSE(SessionHold::holder(db_, -1).ok());
    const Result<SessionHold> missing = SessionHold::acquire(dir_ / "no-such-dir" / "c.sqlite", 1);
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(contains(missing.error().message, "no-such-dir/c.sqlite-holds"))
        << missing.error().message;
}

}  // namespace
}  // namespace monoplane::study
