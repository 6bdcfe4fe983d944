// A session's staircases (issue 21): one adaptive procedure per scene of a staircase protocol.
// The session engine (LiveSession) asks it for each adaptive trial's mono plane as the trial
// starts and tells it each decision. A resumed session builds a fresh one and records the
// stored decisions again in trial order (replay), which brings every staircase exactly to where
// it was: a procedure's state is a function of its recorded answers alone.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "study/adaptive_procedure.h"
#include "study/protocol.h"
#include "study/schedule.h"
#include "study/trial_state_machine.h"

namespace monoplane::study {

class Staircases {
  public:
    // Requires protocol.procedure == Staircase (asserted).
    explicit Staircases(const Protocol& protocol);

    // A decided trial, in trial order. Only an adaptive trial with a valid decision (both
    // alternatives viewed: what `analyze` keeps) moves its scene's staircase; practice and
    // invalid decisions do not. The answer is whether the reference (the protocol's first
    // alternative) was chosen.
    void record(const ScheduledTrial& trial, const TrialOutcome& outcome);

    // Whether the scene's staircase has stopped: trials_per_scene answers, or (QUEST+ with
    // stop_sd_log10) at least min_trials_per_scene answers and a posterior standard deviation of
    // log10 threshold at most stop_sd_log10. Its remaining slots are skipped.
    bool finished(const std::string& scene) const;
    // Where the scene's next trial goes. Requires a scene of the protocol (asserted).
    double next_mono_plane(const std::string& scene) const;
    ThresholdEstimate estimate(const std::string& scene) const;

  private:
    const AdaptiveProcedure& procedure(const std::string& scene) const;

    StaircaseSettings settings_;
    RenderMode reference_;
    std::map<std::string, std::unique_ptr<AdaptiveProcedure>> by_scene_;
};

}  // namespace monoplane::study
