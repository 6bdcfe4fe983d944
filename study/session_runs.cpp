#include "study/session_runs.h"

#include <algorithm>

namespace monoplane::study {

std::int64_t RunStart::session_time(std::int64_t clock_ns) const {
    return std::max(start_ns, clock_ns + clock_offset_ns);
}

RunStart plan_run(int run, std::optional<std::int64_t> last_time_ns, std::int64_t first_frame,
                  std::int64_t clock_start_ns) {
    RunStart start{
        .run = run, .first_frame = first_frame, .clock_offset_ns = 0, .start_ns = clock_start_ns};
    // The first run defines the axis; a later one continues it whatever its clock says (a
    // runtime restarted near 0, or one that ran on through the interruption), so the time the
    // session stood interrupted counts nowhere.
    if (run > 1 && last_time_ns) {
        start.start_ns = *last_time_ns + 1;
        start.clock_offset_ns = start.start_ns - clock_start_ns;
    }
    return start;
}

}  // namespace monoplane::study
