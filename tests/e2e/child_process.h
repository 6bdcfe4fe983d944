// Child processes for the end-to-end tests: start the monoplane executable, read what it
// prints, kill it at a chosen moment (tests/e2e/study_crash_test.cpp, study_day_cli_test.cpp).
#pragma once

#include <sys/types.h>

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

// Runs `args` and SIGKILLs it as soon as it has printed its k-th "committed" line (the write is
// durable then; the child is somewhere in its next frames). What it printed before dying is read
// to the end: every committed line there is a write that must survive.
KilledRun run_and_kill_after(const std::vector<std::string>& args, int k,
                             const std::string& tmpdir);

}  // namespace monoplane
