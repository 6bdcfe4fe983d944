#include "study/observer_input.h"

namespace monoplane::study {

ObserverInput::ObserverInput(Observer& observer, const Protocol& protocol,
                             std::function<double(const ScheduledTrial&)> trial_error_px)
    : observer_(observer), protocol_(protocol), trial_error_px_(std::move(trial_error_px)) {}

std::int64_t ObserverInput::reading_ns(const std::string& text) {
    constexpr std::int64_t kBaseNs = 2'000'000'000;
    constexpr std::int64_t kPerCharacterNs = 40'000'000;
    return kBaseNs + static_cast<std::int64_t>(text.size()) * kPerCharacterNs;
}

std::vector<LiveInput> ObserverInput::poll_page(const LiveScreen& screen, std::int64_t time_ns) {
    if (screen.kind == ScreenKind::End) return {};  // the experimenter takes over
    const std::pair<ScreenKind, int> page{screen.kind, screen.page};
    if (page_ != page) {
        page_ = page;
        page_since_ns_ = time_ns;
    }
    if (screen.kind == ScreenKind::Break) {
        // Rests until confirm is accepted.
        if (screen.break_remaining_ns > 0) return {};
        return {LiveInput::Confirm};
    }
    if (time_ns - page_since_ns_ < reading_ns(screen.text ? *screen.text : std::string()))
        return {};
    return {LiveInput::Confirm};
}

std::vector<LiveInput> ObserverInput::poll(const LiveScreen& screen, const LiveProgress& progress,
                                           std::int64_t time_ns) {
    if (screen.kind == ScreenKind::Instructions || screen.kind == ScreenKind::Ready ||
        screen.kind == ScreenKind::Break || screen.kind == ScreenKind::End) {
        return poll_page(screen, time_ns);
    }
    page_.reset();  // a later screen, even of the same kind and page, is read anew
    if (screen.kind == ScreenKind::Questionnaire) {
        if (screen.question != question_) {
            question_ = screen.question;
            wanted_answer_ = observer_.answer(question_, protocol_.questionnaire.scale_points);
        }
        // One step per frame, as a participant clicking through the scale would.
        if (screen.selection != wanted_answer_) return {LiveInput::Switch};
        question_ = -1;  // asks the observer again if the same item comes back
        return {LiveInput::Confirm};
    }
    if (screen.kind != ScreenKind::Trial || screen.paused || progress.visible_label == 0) return {};

    const ScheduledTrial& trial = *screen.trial;
    if (trial.index != trial_index_) {
        trial_index_ = trial.index;
        const int reference_label = trial.label1_alternative == 0 ? 1 : 2;
        plan_ = observer_.plan_trial(trial, reference_label,
                                     trial_error_px_ ? trial_error_px_(trial) : 0.0);
        dwell_ = 0;
        seen_label_ = progress.visible_label;
        since_ns_ = time_ns;
        waiting_ = false;
    }
    if (progress.visible_label != seen_label_) {
        // The switch it asked for is on screen: the next dwell starts with this frame.
        seen_label_ = progress.visible_label;
        since_ns_ = time_ns;
        ++dwell_;
        waiting_ = false;
    } else if (waiting_) {
        // What it asked for has not shown. A switch still pending (the trial was paused, or no
        // frame was presented, since it was requested) shows with a later frame: wait for it.
        if (screen.label != progress.visible_label) return {};
        if (sent_ == LiveInput::Confirm && protocol_.require_both_viewed && !progress.both_seen) {
            // The confirmation was refused (both labels must be seen): look at the other one as
            // long as the last dwell, then confirm again.
            plan_.dwell_ns.push_back(plan_.dwell_ns.back());
            sent_ = LiveInput::Switch;
            return {sent_};
        }
        // Not applied because the trial was paused when it arrived: ask again, the plan unchanged.
        return {sent_};
    }
    if (time_ns - since_ns_ < plan_.dwell_ns[dwell_]) return {};
    waiting_ = true;
    sent_ = dwell_ + 1 < plan_.dwell_ns.size() ? LiveInput::Switch : LiveInput::Confirm;
    return {sent_};
}

}  // namespace monoplane::study
