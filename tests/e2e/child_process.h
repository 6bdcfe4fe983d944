// Child processes for the end-to-end tests: start the monoplane executable, read what it
// prints, kill it at a chosen moment (tests/e2e/study_crash_test.cpp, study_day_cli_test.cpp).
#pragma once

#include <sys/types.h>

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace monoplane {

// The source tree (MONOPLANE_SOURCE_DIR, set by ctest), or ".".
std::string source_dir();

// Starts `args` with stdout on a pipe; returns the pid and the pipe's read end. tmpdir: the
// child's TMPDIR, where the simulated headset writes its runtime script (a killed child leaves
// it behind), and where its stderr goes (stderr.log); empty: inherited, and stderr discarded.
std::pair<pid_t, int> spawn(const std::vector<std::string>& args, const std::string& tmpdir = {});

// Everything left to read on fd, which is closed after.
std::string read_all(int fd);

// Runs `args` to its end; returns its exit status and, in *output, what it printed (on stdout,
// then on stderr where tmpdir holds it).
int run_to_end(const std::vector<std::string>& args, std::string* output = nullptr,
               const std::string& tmpdir = {});

struct KilledRun {
    std::string output;    // everything the child printed, up to its death
    bool killed = false;   // it died of the SIGKILL (not: it ended first)
    bool stalled = false;  // it printed nothing for a minute
};

// A session child started with `study run|resume ... --trace-stop`: it stops itself after each
// "committed" line and goes on at SIGCONT, so what it has written when it is killed does not
// depend on how quickly this process reads its output.
struct SteppedChild {
    pid_t pid = -1;
    int fd = -1;           // its stdout
    std::string output;    // what it printed so far
    bool stopped = false;  // it is stopped right after the line chosen
    bool stalled = false;  // it printed nothing for a minute
    bool reaped = false;   // it ended first, and waitpid has its status:
    int ended_status = 0;  // this one
    // Where the reading stands: the output's first unread line, the committed lines seen (each
    // a stop waited for), and how many of them the child was continued past.
    std::size_t scanned = 0;
    int committed = 0;
    int stepped_past = 0;
};

// Starts `args` (a study run or resume command) with --trace-stop added and lets it run, one
// committed write at a time, until `chosen(k, line)` is true of its k-th (1-based) committed
// line (without "committed "): there the child is left stopped. Otherwise it runs to its end.
SteppedChild run_until_committed(const std::vector<std::string>& args,
                                 const std::function<bool(int, const std::string&)>& chosen,
                                 const std::string& tmpdir);

// Continues a child left stopped, past each of its later writes, to its end; returns its exit
// status (-1: killed, or it stalled and was killed), with all it printed in child.output.
int continue_to_end(SteppedChild& child);

// SIGKILLs the child (stopped or not) and reads what it printed to the end.
KilledRun kill_child(SteppedChild child);

// Runs `args` and SIGKILLs it right after its k-th committed write (the write is durable then,
// and the child has started nothing after it). What it printed before dying is read to the end:
// every committed line there is a write that must survive.
KilledRun run_and_kill_after(const std::vector<std::string>& args, int k,
                             const std::string& tmpdir);

}  // namespace monoplane
