// The 2AFC trial's rules. What counts is what the participant saw: a change
// takes effect with the frame that shows it, so a switch requested and taken back before the next
// frame was never seen and is neither logged nor counted, and a confirmation applies to the label
// on screen, not to one still pending. Times on the labels and the decision time leave out pauses,
// during which the participant is not judging. A trial interrupted and shown again in a resumed
// run starts from what its earlier runs showed (trial_runs.h replays them by these rules).
#include "study/trial_state_machine.h"

#include <algorithm>
#include <string>

namespace monoplane::study {
namespace {

const char* state_name(TrialState state) {
    switch (state) {
        case TrialState::NotStarted:
            return "not started";
        case TrialState::Viewing:
            return "viewing";
        case TrialState::Paused:
            return "paused";
        case TrialState::Decided:
            return "decided";
        case TrialState::Aborted:
            return "aborted";
    }
    return "invalid";
}

// Durations never go negative, even if a caller's clocks disagree by a little.
std::int64_t elapsed(std::int64_t from, std::int64_t to) {
    return std::max<std::int64_t>(0, to - from);
}

}  // namespace

TrialStateMachine::TrialStateMachine(const ScheduledTrial& trial, bool require_both_viewed,
                                     const TrialRuns& earlier)
    : trial_(trial),
      require_both_viewed_(require_both_viewed),
      earlier_viewing_ns_(earlier.viewing_ns) {
    outcome_.switches = earlier.switches;
    outcome_.time_on_label_ns[0] = earlier.time_on_label_ns[0];
    outcome_.time_on_label_ns[1] = earlier.time_on_label_ns[1];
    outcome_.runs = earlier.runs + 1;
}

Error TrialStateMachine::fail(const char* request, const char* why) const {
    return Error{"trial " + std::to_string(trial_.index) + ": cannot " + request + ": " + why +
                 " (state: " + state_name(state_) + ")"};
}

TrialEvent TrialStateMachine::event(EventKind kind, int label, std::int64_t time_ns,
                                    std::int64_t frame) const {
    return TrialEvent{kind, trial_.index, label, time_ns, frame, -1};
}

void TrialStateMachine::close_dwell(std::int64_t time_ns) {
    if (visible_ == 0) return;
    outcome_.time_on_label_ns[visible_ - 1] += elapsed(visible_since_ns_, time_ns);
    visible_since_ns_ = time_ns;
}

int TrialStateMachine::visible_label() const {
    return visible_;
}

int TrialStateMachine::label_to_draw() const {
    return requested_;
}

Result<std::vector<TrialEvent>> TrialStateMachine::start(std::int64_t /*time_ns*/) {
    if (state_ != TrialState::NotStarted) return fail("start", "the trial has already started");
    state_ = TrialState::Viewing;
    requested_ = 1;  // shown first, always: the blind labels are assigned by the schedule
    last_refusal_.reset();
    return std::vector<TrialEvent>{};  // nothing is visible until the next frame
}

Result<std::vector<TrialEvent>> TrialStateMachine::request_switch(std::int64_t /*time_ns*/) {
    if (state_ != TrialState::Viewing) return fail("switch", "the trial is not being viewed");
    // Switching away from a label never seen (before the first frame) would show label 2 first.
    if (visible_ == 0) return fail("switch", "no label is visible yet");
    requested_ = 3 - requested_;
    last_refusal_.reset();
    return std::vector<TrialEvent>{};  // logged as Switched when a frame shows it
}

Result<std::vector<TrialEvent>> TrialStateMachine::request_confirm(std::int64_t time_ns) {
    if (state_ != TrialState::Viewing) return fail("confirm", "the trial is not being viewed");
    if (visible_ == 0) return fail("confirm", "no label is visible yet");
    const bool both_seen = seen_[0] && seen_[1];
    if (require_both_viewed_ && !both_seen) {
        last_refusal_ = event(EventKind::Refused, visible_, time_ns, -1);
        return fail("confirm", "both labels must be viewed before deciding");
    }
    last_refusal_.reset();
    close_dwell(time_ns);
    // A pending switch (requested, not yet shown) is dropped: the choice is what was on screen.
    requested_ = visible_;
    outcome_.choice = visible_;
    outcome_.chosen_mode = visible_ == 1 ? trial_.label1_mode : trial_.label2_mode;
    outcome_.valid = both_seen;
    outcome_.decision_time_ns =
        earlier_viewing_ns_ + elapsed(first_visible_ns_, time_ns) - paused_total_ns_;
    state_ = TrialState::Decided;
    return std::vector<TrialEvent>{event(EventKind::Confirmed, visible_, time_ns, -1)};
}

Result<std::vector<TrialEvent>> TrialStateMachine::pause(std::int64_t time_ns) {
    if (state_ != TrialState::Viewing) return fail("pause", "the trial is not being viewed");
    close_dwell(time_ns);
    paused_at_ns_ = time_ns;
    state_ = TrialState::Paused;
    last_refusal_.reset();
    return std::vector<TrialEvent>{event(EventKind::Paused, 0, time_ns, -1)};
}

Result<std::vector<TrialEvent>> TrialStateMachine::resume(std::int64_t time_ns) {
    if (state_ != TrialState::Paused) return fail("resume", "the trial is not paused");
    // A pause before the first frame precedes the decision clock, so it is not subtracted.
    if (first_visible_ns_ >= 0) paused_total_ns_ += elapsed(paused_at_ns_, time_ns);
    visible_since_ns_ = time_ns;
    state_ = TrialState::Viewing;
    last_refusal_.reset();
    return std::vector<TrialEvent>{event(EventKind::Resumed, 0, time_ns, -1)};
}

Result<std::vector<TrialEvent>> TrialStateMachine::abort(std::int64_t time_ns) {
    if (state_ == TrialState::Decided || state_ == TrialState::Aborted) {
        return fail("abort", "the trial has ended");
    }
    // The outcome stays undecided (choice 0) but keeps the viewing times so far.
    if (state_ == TrialState::Viewing) close_dwell(time_ns);
    state_ = TrialState::Aborted;
    last_refusal_.reset();
    return std::vector<TrialEvent>{event(EventKind::Aborted, 0, time_ns, -1)};
}

std::vector<TrialEvent> TrialStateMachine::frame_presented(std::int64_t frame,
                                                           std::int64_t time_ns) {
    // While paused nothing changes: a switch requested just before the pause shows after it.
    if (state_ != TrialState::Viewing || requested_ == visible_) return {};
    close_dwell(time_ns);
    visible_ = requested_;
    visible_since_ns_ = time_ns;
    seen_[visible_ - 1] = true;
    if (first_visible_ns_ < 0) {
        first_visible_ns_ = time_ns;
        return {event(EventKind::Shown, visible_, time_ns, frame)};
    }
    ++outcome_.switches;
    return {event(EventKind::Switched, visible_, time_ns, frame)};
}

}  // namespace monoplane::study
