// A stored staircase session's own threshold estimates (issue 21): its staircases rebuilt from the
// protocol text the session stored and its decisions recorded again in trial order, exactly as a
// resumed session rebuilds them, so the export and the end-of-session summary report what the
// staircase knew after each trial without any state kept beside the decisions.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "common/result.h"
#include "study/adaptive_procedure.h"
#include "study/study_store.h"

namespace monoplane::study {

// After each decided adaptive trial of `session` (trial index -> its scene's estimate after that
// decision); `trials` are the session's records in any order (others are ignored). Empty for a
// constant session. Errors: a stored protocol text that no longer parses as a staircase protocol
// (named by session). Any time.
Result<std::map<int, ThresholdEstimate>> replay_staircase_estimates(
    const SessionInfo& session, const std::vector<TrialRecord>& trials);

// The last of those per scene: each staircase's estimate at the end (or so far).
Result<std::map<std::string, ThresholdEstimate>> final_staircase_estimates(
    const SessionInfo& session, const std::vector<TrialRecord>& trials);

}  // namespace monoplane::study
