// HeadsetLoop's inputs: the controller's presses, the experimenter window's commands (the
// participant's keys among them), a response device and a simulated observer, each press logged
// before the session engine is asked for what it means.
#include <cstdio>
#include <iostream>

#include "app/commands/study_headset_loop.h"
#include "app/commands/window_bridge.h"

namespace monoplane::app {
namespace {

using study::LiveInput;
using study::ScreenKind;

}  // namespace

void HeadsetLoop::handle_inputs(std::int64_t now) {
    // A lost runtime has no presses; the frame then ends at its next OpenXR call.
    const std::vector<headset::ControlPress> presses =
        unless_lost(headset_.sync_controls()).value_or(std::vector<headset::ControlPress>{});
    charge(headset::FrameStep::kOpenXrBegin);
    watch_binding();
    for (const headset::ControlPress& press : presses) {
        answer(controller_press(press.control), live_->session_time(press.time_ns));
    }
    for (const window::Command& c : window_commands_) {
        if (const std::optional<AnswerPress> press = keyboard_press(c, window_read_)) {
            answer(*press, key_time(*press, now));
        } else {
            window_command(c, now);
        }
    }
    window_commands_.clear();
    for (const AnswerPress& press : answers_.device_presses()) {
        answer(press, key_time(press, now));
    }
    if (observer_input_) {
        for (LiveInput input : observer_input_->poll(live_->screen(), live_->progress(), now)) {
            request(input, now);
        }
    }
}

std::int64_t HeadsetLoop::key_time(const AnswerPress& press, std::int64_t frame_ns) const {
    if (!press.monotonic) return frame_ns;
    const std::optional<std::int64_t> runtime = headset_.runtime_time(*press.monotonic);
    return runtime ? live_->session_time(*runtime) : frame_ns;
}

void HeadsetLoop::answer(const AnswerPress& press, std::int64_t time_ns) {
    live_->record_press(press.source, press.action, press.key, time_ns).value_or_throw();
    switch (press.action) {
        case study::PressAction::Switch:
            return request(LiveInput::Switch, time_ns);
        case study::PressAction::Confirm:
            return request(LiveInput::Confirm, time_ns);
        case study::PressAction::Pause:
            return request(live_->screen().paused ? LiveInput::Resume : LiveInput::Pause, time_ns);
    }
}

void HeadsetLoop::watch_binding() {
    const bool focused = headset_.phase() == headset::SessionPhase::Focused;
    if (const std::optional<std::string> change = answers_.after_sync(headset_, focused)) {
        std::cerr << *change << "\n";
        log_tail_.push_back(*change);
    }
}

void HeadsetLoop::window_command(const window::Command& c, std::int64_t now) {
    using Kind = window::Command::Kind;
    switch (c.kind) {
        case Kind::Switch:
            request(LiveInput::Switch, now);
            break;
        case Kind::Confirm:
            request(LiveInput::Confirm, now);
            break;
        case Kind::Pause:
            request(LiveInput::Pause, now);
            break;
        case Kind::Resume:
            request(LiveInput::Resume, now);
            break;
        case Kind::Abort:
            request(LiveInput::Abort, now);
            break;
        case Kind::Unblind:
            unblinded_ = c.value != 0;
            break;
        case Kind::Answer:
            if (c.item >= 0 && c.item < static_cast<int>(window_answers_.size()))
                window_answers_[static_cast<std::size_t>(c.item)] = c.value;
            break;
        case Kind::Note:
            note_status_ = note_outcome(live_->note(c.text, study::NoteSource::Window), c.text,
                                        live_->progress().trial_number);
            break;
        case Kind::SubmitAnswers:
            for (std::size_t i = 0; i < window_answers_.size(); ++i) {
                if (live_->screen().kind != ScreenKind::Questionnaire) break;
                if (window_answers_[i] > 0)
                    live_->answer(static_cast<int>(i), window_answers_[i]).value_or_throw();
            }
            break;
    }
}

void HeadsetLoop::request(LiveInput input, std::int64_t time_ns) {
    const std::string what = live_->request(input, time_ns).value_or_throw();
    if (options_.trace != CommitTrace::Off) {
        std::printf("request %s: %s\n", std::string(study::live_input_name(input)).c_str(),
                    what.c_str());
    }
}

}  // namespace monoplane::app
