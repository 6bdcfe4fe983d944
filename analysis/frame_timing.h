// Frame timing per trial, from headset sessions' frame and head log (issue 17; docs/data.md,
// table frames): the share of a trial's displayed frames that missed their display slot, flagged
// above the session protocol's missed_frame_threshold, so a reviewer sees which decisions were
// made on a stuttering display. Trials without a log (headless sessions, CSV input) are not
// counted. Pure.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "analysis/dataset.h"

namespace monoplane::analysis {

struct TrialFrameTiming {
    std::string source;
    std::string participant;
    std::int64_t session_id = 0;
    int trial_index = 0;
    int frames = 0;  // frames the trial showed (either label)
    int missed = 0;
    double share = 0.0;  // missed / frames
    double threshold = 0.05;
    bool flagged = false;  // share > threshold
};

struct FrameTimingSummary {
    int trials_with_log = 0;  // data trials (not practice) with at least one logged frame
    int flagged = 0;
    std::vector<TrialFrameTiming> trials;  // those trials, in input order
};

FrameTimingSummary summarize_frame_timing(const std::vector<TrialRow>& trials);

}  // namespace monoplane::analysis
