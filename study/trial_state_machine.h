// The 2AFC trial: label 1 is shown first; the participant switches freely
// between labels 1 and 2, unlimited in time, then confirms the label shown. Confirmation is
// refused until both were shown when the protocol requires it. The experimenter may pause,
// resume and abort.
//
// Timing: input arrives with the monotonic time of the request; a change of what is shown becomes
// *visible* only with the next presented frame, and that frame's index and time are what the
// events carry. The renderer side calls frame_presented() once per frame; without a renderer
// (headset none) a virtual clock calls it.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "common/result.h"
#include "study/schedule.h"
#include "study/trial_events.h"
#include "study/trial_runs.h"

namespace monoplane::study {

enum class TrialState { NotStarted, Viewing, Paused, Decided, Aborted };

struct TrialOutcome {
    int choice = 0;  // label confirmed, 1 or 2 (0: undecided)
    RenderMode chosen_mode = RenderMode::Stereo;
    bool valid = false;  // both labels were viewed before the decision
    int switches = 0;
    std::int64_t time_on_label_ns[2] = {0, 0};  // visible time of label 1 and label 2
    // First visibility to confirmation, pauses excluded. A trial shown in several runs (an
    // interruption, then a resume) counts each run's share: its first visibility there to the
    // confirmation or the end of its record (trial_runs.h); switches and the labels' times too.
    std::int64_t decision_time_ns = 0;
    int runs = 1;  // the runs that showed the trial: 1 + the interruptions it spanned
};

class TrialStateMachine {
  public:
    // `earlier`: what earlier runs of the session showed of this trial (an interrupted trial
    // shown again after a resume; trial_runs()), counted into its outcome. Whether both labels
    // were seen is this run's alone: a comparison does not span an interruption.
    TrialStateMachine(const ScheduledTrial& trial, bool require_both_viewed,
                      const TrialRuns& earlier = {});

    // Requests; the returned events (if any) must be logged before the next frame starts.
    // start(): label 1 is to be shown; it becomes visible at the next frame.
    Result<std::vector<TrialEvent>> start(std::int64_t time_ns);
    Result<std::vector<TrialEvent>> request_switch(std::int64_t time_ns);
    // Confirms the label currently visible. Refused (an error, plus a Refused event) when the
    // protocol requires both labels seen and one was not: a Result carries either events or an
    // error, so the Refused event to log is then last_refusal().
    Result<std::vector<TrialEvent>> request_confirm(std::int64_t time_ns);
    // The Refused event of the latest refused confirmation, until the next successful request.
    const std::optional<TrialEvent>& last_refusal() const { return last_refusal_; }
    Result<std::vector<TrialEvent>> pause(std::int64_t time_ns);
    Result<std::vector<TrialEvent>> resume(std::int64_t time_ns);
    Result<std::vector<TrialEvent>> abort(std::int64_t time_ns);

    // A frame became visible at time_ns: pending changes take effect and are returned as events
    // attributed to that frame.
    std::vector<TrialEvent> frame_presented(std::int64_t frame, std::int64_t time_ns);

    TrialState state() const { return state_; }
    int visible_label() const;  // 0 before the first frame, else 1 or 2
    // The label the renderer should draw now (the requested one, visible from the next frame).
    int label_to_draw() const;
    bool seen(int label) const { return seen_[label - 1]; }  // label 1 or 2 was visible
    const ScheduledTrial& trial() const { return trial_; }
    const TrialOutcome& outcome() const { return outcome_; }

  private:
    ScheduledTrial trial_;
    bool require_both_viewed_;
    TrialState state_ = TrialState::NotStarted;
    int visible_ = 0;
    int requested_ = 0;
    bool seen_[2] = {false, false};
    std::int64_t visible_since_ns_ = 0;
    std::int64_t first_visible_ns_ = -1;
    std::int64_t paused_at_ns_ = 0;
    std::int64_t paused_total_ns_ = 0;
    std::int64_t earlier_viewing_ns_ = 0;  // the decision time earlier runs contribute
    TrialOutcome outcome_;
    std::optional<TrialEvent> last_refusal_;

    Error fail(const char* request, const char* why) const;
    TrialEvent event(EventKind kind, int label, std::int64_t time_ns, std::int64_t frame) const;
    void close_dwell(std::int64_t time_ns);  // adds the visible label's time up to time_ns
};

}  // namespace monoplane::study
