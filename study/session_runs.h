// A session's runs (docs/data.md, table session_runs): its first run and every resume, each a
// process that may show it on another clock. A headset session's times come from the OpenXR
// runtime's clock, a headless one's from a virtual clock; both start again in a new process (a
// restarted runtime's clock has a new origin), so each run gets an offset that puts its clock on
// the session's one time axis: a resumed run's clock starts right after the latest time the
// session stored, so no duration across runs is negative or jumps, and the time the session
// stood interrupted is on no one's axis.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace monoplane::study {

// What a front end knows of its run when it begins one.
struct RunInfo {
    // The OpenXR runtime's name, "simulated" or "none"; empty: the session's runtime.
    std::string runtime = {};
    // The front end's clock (the runtime's, or the virtual display's) at the run's start: one
    // display period before its first frame is displayed. Nothing of the run is placed earlier.
    std::int64_t clock_start_ns = 0;
};

// A run as begin_run placed it on the session's axis.
struct RunStart {
    int run = 0;                       // 1 for the session's first, n + 1 for each resume
    std::int64_t first_frame = 0;      // the run's first frame number: after every stored one
    std::int64_t clock_offset_ns = 0;  // session time = the run's clock + this
    std::int64_t start_ns = 0;         // the run's start on the session's axis

    // A time of the run's clock on the session's axis; a time before the run's start (an input
    // the runtime dates before the first frame) is placed at the start.
    std::int64_t session_time(std::int64_t clock_ns) const;
};

// A stored run (StudyStore::runs), for the export and the tests.
struct RunRecord {
    int run = 0;
    std::string started_utc;
    std::string host;
    long pid = 0;
    std::string runtime;
    std::int64_t first_frame = 0;
    std::int64_t clock_offset_ns = 0;
};

// The one rule that places a run. Run 1's clock is the session's axis as it is (offset 0). A
// later run starts 1 ns after the latest time the session stored (`last_time_ns`: events and
// frames; none: the run's clock as it is). Any time the front end may call it.
RunStart plan_run(int run, std::optional<std::int64_t> last_time_ns, std::int64_t first_frame,
                  std::int64_t clock_start_ns);

}  // namespace monoplane::study
