// LiveSession's part in the protocol's screens: showing the instructions, ready, break and end
// screens that study/session_screens.h says are due, taking the participant's confirm and
// switch on them, and logging each appearance and dismissal like a trial's events.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "study/live_session.h"

namespace monoplane::study {

namespace {

EventKind shown_event(ScreenKind kind) {
    switch (kind) {
        case ScreenKind::Instructions:
            return EventKind::InstructionsShown;
        case ScreenKind::Ready:
            return EventKind::ReadyShown;
        case ScreenKind::Break:
            return EventKind::BreakStarted;
        default:
            return EventKind::EndShown;
    }
}

// "12.4 s", rounded up: the participant may confirm when it reads 0.
std::string seconds_left(std::int64_t ns) {
    char text[32];
    std::snprintf(text, sizeof text, "%.1f s", std::ceil(static_cast<double>(ns) / 1e8) / 10.0);
    return text;
}

}  // namespace

bool LiveSession::on_page_screen() const {
    return kind_ == ScreenKind::Instructions || kind_ == ScreenKind::Ready ||
           kind_ == ScreenKind::Break || kind_ == ScreenKind::End;
}

std::optional<std::size_t> LiveSession::peek_next_trial() const {
    for (std::size_t i = next_trial_; i < schedule_.trials.size(); ++i) {
        const ScheduledTrial& trial = schedule_.trials[i];
        if (decided_.contains(trial.index)) continue;
        // As prepare_next_trial(): a stopped staircase's slot is skipped.
        if (trial.adaptive && std::isnan(trial.mono_plane) && staircases_->finished(trial.scene)) {
            continue;
        }
        return i;
    }
    return std::nullopt;
}

void LiveSession::show_screen(ScreenKind kind) {
    kind_ = kind;
    screen_visible_ = false;
}

void LiveSession::enter_next(std::int64_t time_ns) {
    const std::optional<std::size_t> next = peek_next_trial();
    int data_decided = 0;
    const ScheduledTrial* previous = nullptr;  // the last data trial decided
    for (const ScheduledTrial& trial : schedule_.trials) {
        if (trial.practice || !decided_.contains(trial.index)) continue;
        ++data_decided;
        previous = &trial;
    }
    const ScheduledTrial* next_trial = next ? &schedule_.trials[*next] : nullptr;
    switch (screen_before_trial(protocol_.day, screens_, data_decided, previous, next_trial)) {
        case ScreenDue::Instructions:
            show_screen(ScreenKind::Instructions);
            page_ = screens_.instructions_page;
            return;
        case ScreenDue::Ready:
            show_screen(ScreenKind::Ready);
            return;
        case ScreenDue::Break:
            show_screen(ScreenKind::Break);
            screens_.break_taken = true;
            break_min_ns_ = break_remaining_ns(*protocol_.day.breaks, 0);
            return;
        case ScreenDue::None:
            kind_ = ScreenKind::Neutral;
            neutral_since_ns_ = time_ns;
            return;
    }
}

void LiveSession::resume_screens(const std::vector<TrialEvent>& events,
                                 const std::vector<FrameRecord>& frames) {
    const ScreenResume resume =
        study::resume_screens(events, static_cast<int>(protocol_.day.instructions.size()), frames);
    screens_ = resume.progress;
    if (resume.last_trial >= 0) last_trial_shown_ = resume.last_trial;
    const std::optional<std::size_t> next = peek_next_trial();
    if (next && schedule_.trials[*next].index == resume.last_trial) {
        // The next trial had started: whatever came before it was passed.
        screens_.break_taken = true;
    } else if (resume.break_open && protocol_.day.breaks) {
        // The same break goes on for what is left of its minimum. Its start is logged again when
        // it shows: each run's break_started has its break_ended or its interruption, and
        // resume_screens() counts the two starts as one break.
        show_screen(ScreenKind::Break);
        screens_.break_taken = true;
        break_min_ns_ = break_remaining_ns(*protocol_.day.breaks, resume.break_elapsed_ns);
        return;
    }
    enter_next(-1);
}

Result<void> LiveSession::log_screen(EventKind kind, std::int64_t time_ns, std::int64_t frame) {
    TrialEvent event;
    event.kind = kind;
    event.trial_index = -1;
    event.time_ns = time_ns;
    event.frame = frame;
    if (kind == EventKind::InstructionsShown || kind == EventKind::InstructionsConfirmed) {
        event.page = page_;
    }
    return log({event});
}

Result<void> LiveSession::screen_presented(std::int64_t frame, std::int64_t time_ns) {
    if (!screen_visible_) {
        screen_visible_ = true;
        if (kind_ == ScreenKind::Break) break_visible_ns_ = time_ns;
        MONOPLANE_TRY(log_screen(shown_event(kind_), time_ns, frame));
        if (kind_ == ScreenKind::End) return finish(SessionStatus::Completed);
    }
    if (kind_ == ScreenKind::Break) {
        // The countdown runs on the frames' time: what the participant sees.
        break_remaining_ns_ =
            std::max<std::int64_t>(0, break_min_ns_ - (time_ns - break_visible_ns_));
    }
    return Ok{};
}

Result<std::string> LiveSession::screen_request(LiveInput input, std::int64_t time_ns) {
    const std::string name(live_input_name(input));
    const std::string ignored =
        name + " ignored on the " + std::string(screen_kind_name(kind_)) + " screen";
    if (input != LiveInput::Switch && input != LiveInput::Confirm) return ignored;
    // Input for a screen not yet presented would answer a page the participant has not seen.
    if (!screen_visible_) return ignored + ": not visible yet";
    if (input == LiveInput::Confirm) return confirm_screen(time_ns);
    if (kind_ != ScreenKind::Instructions || page_ == 0) return ignored;
    --page_;  // back one page; shown again with the next frame
    screen_visible_ = false;
    return "instructions page " + std::to_string(page_ + 1);
}

Result<std::string> LiveSession::confirm_screen(std::int64_t time_ns) {
    EventKind kind = EventKind::ReadyConfirmed;
    if (kind_ == ScreenKind::Instructions) kind = EventKind::InstructionsConfirmed;
    if (kind_ == ScreenKind::Break) {
        if (break_remaining_ns_ > 0) {
            return "confirm ignored: the break lasts another " + seconds_left(break_remaining_ns_);
        }
        kind = EventKind::BreakEnded;
    }
    MONOPLANE_TRY(log_screen(kind, time_ns, -1));
    const int pages = static_cast<int>(protocol_.day.instructions.size());
    if (kind_ == ScreenKind::Instructions) {
        screens_.instructions_page = std::max(screens_.instructions_page, page_ + 1);
        if (page_ + 1 < pages) {
            show_screen(ScreenKind::Instructions);
            ++page_;
            return "instructions page " + std::to_string(page_ + 1);
        }
        screens_.instructions_page = pages;
    }
    if (kind_ == ScreenKind::Ready) screens_.ready_confirmed = true;
    const std::string done = kind_ == ScreenKind::Instructions ? "instructions read"
                             : kind_ == ScreenKind::Ready      ? "ready confirmed"
                                                               : "break ended";
    enter_next(time_ns);
    return done;
}

}  // namespace monoplane::study
