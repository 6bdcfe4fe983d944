// HeadsetLoop's experimenter window: each frame's view of the session (progress, labels, log
// tail, questionnaire, the page the participant reads, the participant's gaze), its screenshot,
// and a lost runtime's last frame.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iostream>

#include "app/commands/study_headset_loop.h"
#include "app/commands/study_headset_seat.h"
#include "app/commands/window_bridge.h"
#include "app/window/gaze_marker.h"

namespace monoplane::app {
namespace {

// The frame's gaze in the mirrored image, the left eye's (turned by its cant, with its own
// frustum); none without a valid sample or located views.
std::optional<std::array<double, 2>> mirrored_gaze(const headset::HeadsetFrame& frame) {
    if (!frame.gaze || !frame.gaze->valid || !frame.views_valid) return std::nullopt;
    const LocatedHead located = located_head(frame);
    return window::gaze_in_eye_image(frame.gaze->direction, located.cant[0],
                                     frame.views[0].tangents);
}

}  // namespace

void HeadsetLoop::show_loss() {
    const std::string message = loss_message();
    log_tail_.push_back(message);
    if (!experimenter_ || !last_frame_) return;
    window::ExperimenterView view = window_view(*last_frame_, live_->screen(), last_frame_ns_);
    view.status_line = message;
    window_commands_ = experimenter_->frame(view);
}

void HeadsetLoop::update_window(const headset::HeadsetFrame& frame, const study::LiveScreen& screen,
                                std::int64_t now) {
    window_read_ = monotonic_now();  // the window polls its keys first thing
    window_commands_ = experimenter_->frame(window_view(frame, screen, now));
    if (!options_.screenshot.empty() && frame.index == options_.screenshot_frame) {
        save_screenshot();
    }
    charge(headset::FrameStep::kWindow);
    if (!experimenter_->close_requested()) return;
    if (!live_->finished()) {
        std::cerr << "the experimenter window was closed: ending the session (resume it "
                     "with `monoplane study resume`)\n";
    }
    request_exit();  // after the session: the end screen needs to stay no longer
}

window::ExperimenterView HeadsetLoop::window_view(const headset::HeadsetFrame& frame,
                                                  const study::LiveScreen& screen,
                                                  std::int64_t now) const {
    const study::LiveProgress progress = live_->progress();
    window::ExperimenterView view;
    view.participant = info_.participant_code;
    view.protocol = protocol_.name;
    view.headset = headset_.runtime_name();
    view.hmd = headset_.system_name();
    view.device = ctx_.device_info().name;
    view.trial_number = progress.trial_number;
    view.trial_count = progress.trial_count;
    view.phase = window_phase(screen);
    view.elapsed_s = static_cast<double>(now - first_frame_ns_) * 1e-9;
    if (screen.trial) {
        view.practice = screen.trial->practice;
        view.scene = screen.trial->scene;
        view.mono_plane = screen.trial->mono_plane;
        view.label_modes = {std::string(study::render_mode_name(screen.trial->label1_mode)),
                            std::string(study::render_mode_name(screen.trial->label2_mode))};
        if (progress.trial_started_ns >= 0) {
            view.trial_elapsed_s = static_cast<double>(now - progress.trial_started_ns) * 1e-9;
        }
    }
    view.visible_label = progress.visible_label;
    view.switches = progress.switches;
    view.both_seen = progress.both_seen;
    view.unblinded = unblinded_;
    const auto shown_tail =
        std::min<std::ptrdiff_t>(40, static_cast<std::ptrdiff_t>(log_tail_.size()));
    view.log_tail.assign(log_tail_.end() - shown_tail, log_tail_.end());
    view.questionnaire_items = protocol_.questionnaire.items;
    view.scale_points = protocol_.questionnaire.scale_points;
    view.answers = window_answers_;
    view.frame_index = static_cast<std::uint64_t>(frame.index);
    view.frame_ms = std::chrono::duration<double, std::milli>(Clock::now() - frame_start_).count();
    mirror_page(screen, view);
    view.gaze_tracked = headset_.tracks_eye_gaze();
    view.gaze_uv = mirrored_gaze(frame);
    view.note_status = note_status_;
    view.status_line =
        std::string("session ") + std::string(headset::session_phase_name(headset_.phase()));
    if (answers_.cannot_answer()) view.status_line = *answers_.cannot_answer();
    return view;
}

// The PNG, and beside it what the window showed as JSON (the same name, .json).
void HeadsetLoop::save_screenshot() {
    experimenter_->save_screenshot(options_.screenshot).value_or_throw();
    const std::filesystem::path state =
        std::filesystem::path(options_.screenshot).replace_extension(".json");
    experimenter_->save_state(state).value_or_throw();
    std::cerr << "wrote " << options_.screenshot << " and " << state.string() << "\n";
    screenshot_saved_ = true;
}

}  // namespace monoplane::app
