// HeadsetLoop's turns and frames: the runtime's events, each frame from xrWaitFrame to its log
// line, the session's run and its end.
#include <chrono>
#include <iostream>
#include <thread>

#include "app/commands/runtime_lost.h"
#include "app/commands/study_headset_loop.h"
#include "app/headset/overlay_text.h"

namespace monoplane::app {
namespace {

using study::ScreenKind;

}  // namespace

HeadsetLoop::HeadsetLoop(const HeadsetStudyOptions& options, const study::Protocol& protocol,
                         study::StudyStore& store, std::int64_t session_id,
                         headset::OpenXrHeadset& headset, const vk_core::Context& ctx,
                         window::ExperimenterWindow* experimenter, StudyRenderers& renderers,
                         study::Observer* observer,
                         const std::function<double(const study::ScheduledTrial&)>& trial_error_px,
                         ParticipantAnswers& answers)
    : options_(options),
      protocol_(protocol),
      info_(store.session(session_id).value_or_throw()),
      db_(store.path()),
      headset_(headset),
      ctx_(ctx),
      experimenter_(experimenter),
      renderers_(renderers),
      extent_(headset.eye_extent()),
      compositor_(ctx),
      compositor_frames_(ctx),
      frame_log_(store, session_id),
      pages_(headset::TextPanelOptions{.text_height_deg = protocol.day.text_height_deg,
                                       .font = protocol.day.font},
             protocol.day.prompts),
      window_answers_(protocol.questionnaire.items.size(), 0),
      answers_(answers) {
    headset::TextStyle label_style;
    label_style.capital_px = 14.0;
    label_style.padding_px = 4;
    compositor_.set_overlay("label1", headset::render_text({"1"}, label_style));
    compositor_.set_overlay("label2", headset::render_text({"2"}, label_style));
    compositor_.set_overlay("paused",
                            headset::render_text({protocol.day.prompts.paused},
                                                 headset::TextStyle{.font = protocol.day.font}));
    if (headset.depth_format() != vk::Format::eUndefined) {
        depth_writer_.emplace(ctx, headset.depth_format());
    }
    study::LiveOptions live_options;
    live_options.neutral_ns = static_cast<std::int64_t>(options.neutral_s * 1e9);
    live_options.on_committed = [this](const std::string& what) { committed(what); };
    live_ = study::LiveSession::open(store, session_id, protocol, live_options).value_or_throw();
    if (observer) observer_input_.emplace(*observer, protocol, trial_error_px);
    if (protocol.gaze.record && headset.tracks_eye_gaze()) {
        gaze_points_ = GazePointFinder::build(renderers.scenes()).value_or_throw();
    }
}

void HeadsetLoop::run() {
    while (turn()) {
    }
    if (headset_.lost()) show_loss();
    finish();
}

std::string HeadsetLoop::loss_message() const {
    return runtime_lost_message(live_->screen(), live_->progress(), info_, db_, options_.headset);
}

bool HeadsetLoop::end_screen_seen() const {
    if (live_->screen().kind != ScreenKind::End) return true;
    return end_shown_ns_ >= 0 &&
           last_frame_ns_ - end_shown_ns_ >= static_cast<std::int64_t>(options_.end_s * 1e9);
}

bool HeadsetLoop::turn() {
    const std::optional<bool> alive = unless_lost(headset_.poll_events());
    if (!alive || !*alive) return false;
    // A runtime that stops showing frames ends the end screen's hold too.
    if (live_->finished() && (end_screen_seen() || !headset_.running())) request_exit();
    if (!headset_.running()) {
        // Waiting for the runtime (READY, or EXITING after the end): nothing to render.
        if (experimenter_) experimenter_->frame({});
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
        return !headset_.lost();
    }
    frame();
    return !headset_.lost();
}

void HeadsetLoop::frame() {
    frame_start_ = Clock::now();
    step_start_ = frame_start_;
    std::optional<headset::HeadsetFrame> begun = unless_lost(headset_.begin_frame());
    if (!begun) return;
    headset::HeadsetFrame& frame = *begun;
    if (live_->run().run == 0) begin_run(frame);
    // The session's frame number and time: this run's frames after every frame an earlier
    // run used, its clock after every earlier time (the runtime's may have started again).
    frame.index += live_->run().first_frame;
    last_frame_ = frame;
    const std::int64_t now = live_->session_time(frame.display_time_ns);
    if (first_frame_ns_ < 0) first_frame_ns_ = now;
    last_frame_ns_ = now;
    if (end_shown_ns_ < 0 && live_->screen().kind == ScreenKind::End) end_shown_ns_ = now;
    // The head relative to the seat: what the frame log records for every frame (the
    // participant's own motion, whatever the screen), and what a trial's views start from.
    std::optional<rig::Pose> tracked;
    const LocatedHead located = frame.views_valid ? located_head(frame) : LocatedHead{};
    if (frame.views_valid) tracked = anchor_.relative(located.head);
    const rig::Pose head = tracked.value_or(rig::Pose{});
    handle_inputs(now);
    // The gaze at the frame's display time, after handle_inputs synced the gaze action.
    if (headset_.tracks_eye_gaze()) {
        frame.gaze =
            unless_lost(headset_.locate_gaze(frame.display_time_ns)).value_or(std::nullopt);
        last_frame_->gaze = frame.gaze;
    }
    const study::LiveScreen screen = live_->screen();
    const Rendered rendered =
        frame.should_render ? render(frame, located, screen, head) : Rendered{};
    // Every frame the eyes' depth was written in carries it (an encoding for all of them).
    std::optional<headset::DepthEncoding> depth;
    if (depth_writer_) depth = headset::DepthEncoding{protocol_.near};
    // A frame the runtime did not take was never seen: it is not logged.
    if (headset_.lost() || !unless_lost(headset_.end_frame(frame, depth))) return;
    charge(headset::FrameStep::kOpenXrEnd);
    // What the participant sees changes only with a frame that was shown.
    if (rendered.shown) {
        const double cpu_ms =
            std::chrono::duration<double, std::milli>(Clock::now() - frame_start_).count();
        headset::HeadsetFrame logged = frame;
        logged.display_time_ns = now;  // the runtime's own time goes to xrEndFrame only
        frame_log_.displayed(logged, screen, tracked, cpu_ms, rendered.renderer,
                             find_gaze_point(frame, rendered));
        // After displayed(): a renderer that waited may return this very frame's time.
        frame_log_.completed(rendered.renderer, rendered.completed);
        live_->frame_presented(frame.index, now).value_or_throw();
    }
    charge(headset::FrameStep::kLog);
    report_progress(screen);
    if (experimenter_) update_window(frame, screen, now);
    times_.end_frame(rendered.renderer != nullptr);
}

std::optional<study::GazePointRecord> HeadsetLoop::find_gaze_point(
    const headset::HeadsetFrame& frame, const Rendered& rendered) {
    if (!gaze_points_ || !rendered.trial_view || !frame.gaze || !frame.gaze->valid) {
        return std::nullopt;
    }
    const TrialView& view = *rendered.trial_view;
    // The eyes' size in pixels does not enter an angle; any valid size builds the rig.
    rig::RigInputs inputs = modes::rig_inputs_for(view.views, extent_.width, extent_.height);
    inputs.mono_plane = view.mono_plane;
    return gaze_points_->find(view.scene, view.views.head, inputs, frame.gaze->direction);
}

void HeadsetLoop::begin_run(const headset::HeadsetFrame& first) {
    live_
        ->begin_run({.runtime = headset_.runtime_name(),
                     .clock_start_ns = first.display_time_ns - first.display_period_ns})
        .value_or_throw();
}

void HeadsetLoop::report_progress(const study::LiveScreen& screen) {
    const study::LiveProgress progress = live_->progress();
    if (progress.trial_number == last_reported_trial_ || screen.kind != ScreenKind::Trial) {
        return;
    }
    last_reported_trial_ = progress.trial_number;
    std::cerr << "trial " << progress.trial_number << "/" << progress.trial_count << ": "
              << screen.trial->scene << " m = " << screen.trial->mono_plane
              << (screen.trial->practice ? " (practice)" : "") << "\n";
}

void HeadsetLoop::finish() {
    if (experimenter_ && !options_.screenshot.empty() && !screenshot_saved_) save_screenshot();
    if (times_.scene_frames() > 0) std::cerr << times_.summary();
    renderers_.for_each(
        [&](modes::ModeRenderer& r) { frame_log_.completed(&r, r.finish_frames()); });
    frame_log_.flush();
    std::cerr << frame_log_.build_summary();
    if (gaze_points_) std::cerr << gaze_points_->cost().summary();
}

void HeadsetLoop::request_exit() {
    if (exit_requested_) return;
    if (!unless_lost(headset_.request_exit())) return;  // lost: the session is over anyway
    exit_requested_ = true;
}

void HeadsetLoop::committed(const std::string& what) {
    trace_committed(options_.trace, what);
    log_tail_.push_back(what);
    if (log_tail_.size() > 200) log_tail_.pop_front();
}

void HeadsetLoop::charge(headset::FrameStep step) {
    const auto now = Clock::now();
    times_.add(step, std::chrono::duration<double, std::milli>(now - step_start_).count());
    step_start_ = now;
}

}  // namespace monoplane::app
