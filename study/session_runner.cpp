#include "study/session_runner.h"

#include <chrono>
#include <cmath>
#include <thread>

#include "study/live_session.h"
#include "study/observer_input.h"

namespace monoplane::study {
namespace {

// A session far longer than any protocol allows (a day of virtual time at the display's rate)
// means the observer and the session wait for each other: an error, not a hang.
constexpr double kMaxVirtualSeconds = 24.0 * 3600.0;

LiveOptions live_options(const RunOptions& options) {
    LiveOptions live;
    live.neutral_ns = options.neutral_ns;
    live.on_committed = [&options](const std::string& what) {
        if (options.on_committed) options.on_committed(what);
        if (options.pace_ns > 0) {
            std::this_thread::sleep_for(std::chrono::nanoseconds(options.pace_ns));
        }
    };
    return live;
}

// The virtual display: a run of the session begins at 0 on its virtual clock, and its frame
// k = 1, 2, ... is shown at k periods (frame 0, the clock's start, is not shown, as on the
// simulated runtime), numbered first_frame + k (after every frame an earlier run used); its
// times go on the session's axis (a resumed run's after the last time stored). Each frame, as on
// a headset: the observer reacts to what is on screen, then the frame is presented and its
// changes logged.
Result<void> drive(LiveSession& session, ObserverInput& input, const RunOptions& options) {
    if (!(options.frame_rate_hz > 0.0)) return Error{"the virtual display's rate must be positive"};
    const auto period = static_cast<std::int64_t>(std::llround(1e9 / options.frame_rate_hz));
    const auto last_k = static_cast<std::int64_t>(kMaxVirtualSeconds * options.frame_rate_hz);
    MONOPLANE_TRY(session.begin_run(RunInfo{.runtime = "none", .clock_start_ns = 0}));
    for (std::int64_t k = 1; !session.finished(); ++k) {
        if (k > last_k) {
            return Error{"the simulated session did not finish within a day of virtual time"};
        }
        const std::int64_t frame = session.run().first_frame + k;
        const std::int64_t now = session.session_time(k * period);
        for (LiveInput request : input.poll(session.screen(), session.progress(), now)) {
            MONOPLANE_TRY(session.request(request, now));
        }
        MONOPLANE_TRY(session.frame_presented(frame, now));
    }
    return Ok{};
}

}  // namespace

Result<SessionStatus> run_session(StudyStore& store, std::int64_t session_id,
                                  const Protocol& protocol, Observer& observer,
                                  const RunOptions& options) {
    Result<std::unique_ptr<LiveSession>> session =
        LiveSession::open(store, session_id, protocol, live_options(options));
    MONOPLANE_TRY(session);
    ObserverInput input(observer, protocol, options.trial_error_px);
    MONOPLANE_TRY(drive(*session.value(), input, options));
    Result<SessionInfo> info = store.session(session_id);
    MONOPLANE_TRY(info);
    return info->status;
}

Result<void> run_simulated_session(SessionLog& log, const Protocol& protocol, Schedule schedule,
                                   Observer& observer, const RunOptions& options) {
    Result<std::unique_ptr<LiveSession>> session =
        LiveSession::begin(log, 1, protocol, live_options(options), std::move(schedule), 0);
    MONOPLANE_TRY(session);
    ObserverInput input(observer, protocol, options.trial_error_px);
    return drive(*session.value(), input, options);
}

}  // namespace monoplane::study
