// What `study run|resume --trace` prints: one line per durable write ("committed trial 3 outcome
// choice 2"), flushed at once, so a harness that kills the process knows what was committed before
// the kill. With --trace-stop the process also stops itself (SIGSTOP) after each line and goes on
// when it receives SIGCONT: a harness that kills it at a chosen write kills it exactly there,
// however loaded the machine, where with the line alone the process races on to its next writes.
#pragma once

#include <string>

namespace monoplane::app {

enum class CommitTrace {
    Off,
    Print,         // --trace
    PrintAndStop,  // --trace-stop
};

// Called by the session after each durable write; does nothing with CommitTrace::Off.
void trace_committed(CommitTrace trace, const std::string& what);

}  // namespace monoplane::app
