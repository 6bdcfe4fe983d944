// Simulated sessions for `simulate` and `simulate-threshold`: a participant's schedule run by the
// session engine of `study run --headset none` (LiveSession with the simulated observer at its
// controls) into memory instead of a database, so every trial, and every staircase's choice of
// m, follows the rules a participant's session follows.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "study/protocol.h"
#include "study/schedule.h"
#include "study/trial_state_machine.h"

namespace monoplane::app {

// The session seed of participant p in simulated study r: the same for every n of a power
// curve (common random numbers), different between runs and participants.
std::uint64_t session_seed(std::uint64_t seed, int run, int participant);

// A decided trial of a simulated session, with the m it was shown at.
struct SimulatedTrial {
    study::ScheduledTrial trial;
    study::TrialOutcome outcome;
};

// The decided trials of one session of `participant` (the schedule's Latin square row) with the
// observer `observer_name` seeded by `seed`, in trial order: a staircase's skipped slots are not
// among them. error_px: the observer's stimulus (study_rows.h trial_error_model). Throws
// UserError for an unknown observer; a session that fails is a programming error (throws).
std::vector<SimulatedTrial> simulate_trials(
    const study::Protocol& protocol, const std::string& observer_name, std::uint64_t seed,
    int participant, const std::function<double(const study::ScheduledTrial&)>& error_px);

}  // namespace monoplane::app
