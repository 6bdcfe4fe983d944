#include "app/commands/simulated_sessions.h"

#include <memory>

#include "study/observer.h"
#include "study/session_log.h"
#include "study/session_runner.h"

namespace monoplane::app {
namespace {

constexpr std::uint64_t mix64(std::uint64_t x) {
    x += 0x9E3779B97F4A7C15ull;
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
    return x ^ (x >> 31);
}

}  // namespace

std::uint64_t session_seed(std::uint64_t seed, int run, int participant) {
    return mix64(mix64(seed ^ 0x51A1'0000'0000'0000ull) + static_cast<std::uint64_t>(run)) ^
           mix64(0xC0DE'0000'0000'0000ull + static_cast<std::uint64_t>(participant));
}

std::vector<SimulatedTrial> simulate_trials(
    const study::Protocol& protocol, const std::string& observer_name, std::uint64_t seed,
    int participant, const std::function<double(const study::ScheduledTrial&)>& error_px) {
    const study::Schedule schedule = study::make_schedule(protocol, seed, participant);
    std::unique_ptr<study::Observer> observer =
        study::make_observer(observer_name, seed).value_or_throw();
    study::RunOptions options;
    options.trial_error_px = error_px;
    options.neutral_ns = 0;  // virtual time between trials changes no decision
    // Decisions do not depend on the display rate, only decision times (not in the power
    // analysis) are quantised by it: a coarse virtual display keeps thousands of sessions fast.
    options.frame_rate_hz = 20.0;
    study::MemorySessionLog log;
    study::run_simulated_session(log, protocol, schedule, *observer, options).value_or_throw();
    std::vector<SimulatedTrial> trials;
    trials.reserve(log.outcomes().size());
    for (const auto& [index, outcome] : log.outcomes()) {
        const auto adaptive = log.adaptive_trials().find(index);
        trials.push_back({adaptive != log.adaptive_trials().end()
                              ? adaptive->second
                              : schedule.trials[static_cast<std::size_t>(index)],
                          outcome});
    }
    return trials;
}

}  // namespace monoplane::app
