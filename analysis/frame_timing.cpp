#include "analysis/frame_timing.h"

namespace monoplane::analysis {

FrameTimingSummary summarize_frame_timing(const std::vector<TrialRow>& trials) {
    FrameTimingSummary summary;
    for (const TrialRow& t : trials) {
        if (t.practice || t.frames_shown <= 0) continue;
        TrialFrameTiming timing;
        timing.source = t.source;
        timing.participant = t.participant;
        timing.session_id = t.session_id;
        timing.trial_index = t.trial_index;
        timing.frames = t.frames_shown;
        timing.missed = t.frames_missed;
        timing.share = static_cast<double>(t.frames_missed) / t.frames_shown;
        timing.threshold = t.missed_frame_threshold;
        timing.flagged = timing.share > timing.threshold;
        summary.flagged += timing.flagged ? 1 : 0;
        summary.trials.push_back(std::move(timing));
    }
    summary.trials_with_log = static_cast<int>(summary.trials.size());
    return summary;
}

}  // namespace monoplane::analysis
