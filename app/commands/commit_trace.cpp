#include "app/commands/commit_trace.h"

#include <signal.h>

#include <cstdio>

namespace monoplane::app {

void trace_committed(CommitTrace trace, const std::string& what) {
    if (trace == CommitTrace::Off) return;
    std::printf("committed %s\n", what.c_str());
    std::fflush(stdout);
    if (trace == CommitTrace::PrintAndStop) raise(SIGSTOP);
}

}  // namespace monoplane::app
