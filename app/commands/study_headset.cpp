#include "app/commands/study_headset.h"

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <iostream>
#include <thread>

#include <glm/gtc/quaternion.hpp>

#include "app/commands/headset_frame_log.h"
#include "app/commands/participant_answers.h"
#include "app/commands/runtime_lost.h"
#include "app/commands/screen_pages.h"
#include "app/commands/study_renderers.h"
#include "app/commands/validation_report.h"
#include "app/commands/window_bridge.h"
#include "app/headset/eye_compositor.h"
#include "app/headset/eye_depth_writer.h"
#include "app/headset/frame_times.h"
#include "app/headset/headset_device.h"
#include "app/headset/openxr_headset.h"
#include "app/headset/overlay_text.h"
#include "app/window/experimenter_window.h"
#include "common/result.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/vk/frame_ring.h"
#include "study/live_session.h"
#include "study/observer_input.h"

namespace monoplane::app {
namespace {

namespace fs = std::filesystem;
using study::LiveInput;
using study::ScreenKind;

// Where the overlays sit, as directions of view (tangents, +y up): the label low and small, in
// the lower periphery; the questionnaire straight ahead.
constexpr headset::OverlayPlacement kLabelPlacement{0.0, -0.55, 0.05};
constexpr headset::OverlayPlacement kPanelPlacement{0.0, 0.05, 0.45};

// The participant's seat: the head pose of the first tracked frame, turned about the vertical
// only, is where the scene's viewpoint is. LOCAL space puts its origin near the starting head on
// most runtimes but not all (some at floor level, simxr at 1.6 m); recentring on the first frame
// makes every runtime start the participant exactly at the viewpoint, looking along it, while
// later head motion (and the head's own pitch and roll) is kept.
class SeatAnchor {
  public:
    // The head pose relative to the anchor, setting the anchor from the first call.
    rig::Pose relative(const rig::Pose& head) {
        if (!set_) {
            const glm::dvec3 forward = head.orientation * glm::dvec3(0.0, 0.0, -1.0);
            const double yaw = std::atan2(-forward.x, -forward.z);
            inverse_yaw_ = glm::angleAxis(-yaw, glm::dvec3(0.0, 1.0, 0.0));
            origin_ = head.position;
            set_ = true;
        }
        rig::Pose pose;
        pose.position = inverse_yaw_ * (head.position - origin_);
        pose.orientation = inverse_yaw_ * head.orientation;
        return pose;
    }

  private:
    bool set_ = false;
    glm::dvec3 origin_{0.0};
    glm::dquat inverse_yaw_{1.0, 0.0, 0.0, 0.0};
};

// The head from the two located eyes: their midpoint, and the orientation halfway between
// theirs. Canted views differ from it by a yaw each, their cant; a
// runtime whose views differ otherwise (a pitch or roll between the eyes) is refused, because
// the rig models displays turned about the head's vertical axis only.
struct LocatedHead {
    rig::Pose head;
    std::array<double, 2> cant = {0.0, 0.0};  // radians, positive turning the eye left
};

LocatedHead located_head(const headset::HeadsetFrame& frame) {
    const rig::Pose& l = frame.views[0].pose;
    const rig::Pose& r = frame.views[1].pose;
    LocatedHead located;
    located.head.position = 0.5 * (l.position + r.position);
    const glm::dquat right =
        glm::dot(l.orientation, r.orientation) < 0.0 ? -r.orientation : r.orientation;
    located.head.orientation = glm::normalize(glm::slerp(l.orientation, right, 0.5));
    constexpr double kTolerance = 0.2 * 3.14159265358979 / 180.0;
    for (int e : {0, 1}) {
        glm::dquat relative =
            glm::inverse(located.head.orientation) * frame.views[e].pose.orientation;
        if (relative.w < 0.0) relative = -relative;
        // A pure yaw is (cos a/2, 0, sin a/2, 0).
        const double off_axis = 2.0 * std::asin(std::min(1.0, std::hypot(relative.x, relative.z)));
        if (off_axis > kTolerance) {
            throw UserError("the headset's " + std::string(e == 0 ? "left" : "right") +
                            " view is turned by " +
                            std::to_string(off_axis * 180.0 / 3.14159265358979) +
                            " degrees about an axis other than the head's vertical; monoplane's "
                            "rig supports parallel views and views canted by a yaw "
                            "(docs/headsets.md, \"Canted headsets\")");
        }
        located.cant[e] = 2.0 * std::atan2(relative.y, relative.w);
    }
    return located;
}

// The renderer's viewer: the head relative to the seat, placed at the scene's viewpoint, with
// the runtime's eye distance and calibrated frusta.
modes::StereoViewInputs view_inputs(const headset::HeadsetFrame& frame, const LocatedHead& located,
                                    const rig::Pose& head, const rig::Pose& seat,
                                    const study::Protocol& protocol) {
    modes::StereoViewInputs inputs;
    inputs.head.position = seat.position + seat.orientation * head.position;
    inputs.head.orientation = seat.orientation * head.orientation;
    inputs.ipd = glm::length(frame.views[1].pose.position - frame.views[0].pose.position);
    inputs.left = frame.views[0].tangents;
    inputs.right = frame.views[1].tangents;
    inputs.cant = located.cant;
    inputs.near = protocol.near;
    inputs.far = protocol.far;
    return inputs;
}

std::vector<std::string> questionnaire_lines(const study::Protocol& protocol, int question,
                                             int selection) {
    const study::Questionnaire& q = protocol.questionnaire;
    const study::HeadsetPrompts& prompts = protocol.day.prompts;
    std::string scale;
    for (int v = 1; v <= q.scale_points; ++v) {
        scale += v == selection ? "[" + std::to_string(v) + "] " : " " + std::to_string(v) + "  ";
    }
    const std::pair<std::string_view, std::string> counts[] = {
        {"question", std::to_string(question + 1)},
        {"questions", std::to_string(q.items.size())},
        {"points", std::to_string(q.scale_points)}};
    return {study::fill_prompt(prompts.question, counts),
            q.items[static_cast<std::size_t>(question)],
            "",
            study::fill_prompt(prompts.scale, counts),
            scale,
            "",
            prompts.answer};
}

bool has_display() {
    const char* x11 = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x11 && *x11) || (wayland && *wayland);
}

// One headset session's frame loop, its state in one place: the runtime and device it renders
// with, the session engine (LiveSession) and its inputs, the per-frame log and timing, and the
// experimenter window's state. run() drives frames until the runtime ends the session; each frame
// is begin (OpenXR), inputs, render, end (OpenXR), log, window.
class HeadsetLoop {
  public:
    HeadsetLoop(const HeadsetStudyOptions& options, const study::Protocol& protocol,
                study::StudyStore& store, std::int64_t session_id, headset::OpenXrHeadset& headset,
                const vk_core::Context& ctx, window::ExperimenterWindow* experimenter,
                StudyRenderers& renderers, study::Observer* observer,
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
        compositor_.set_overlay(
            "paused", headset::render_text({protocol.day.prompts.paused},
                                           headset::TextStyle{.font = protocol.day.font}));
        if (headset.depth_format() != vk::Format::eUndefined) {
            depth_writer_.emplace(ctx, headset.depth_format());
        }
        study::LiveOptions live_options;
        live_options.neutral_ns = static_cast<std::int64_t>(options.neutral_s * 1e9);
        live_options.on_committed = [this](const std::string& what) { committed(what); };
        live_ =
            study::LiveSession::open(store, session_id, protocol, live_options).value_or_throw();
        if (observer) observer_input_.emplace(*observer, protocol, trial_error_px);
    }

    // Frames until the runtime ends the session (after the study, or when the window closes) or
    // is lost; then the frame log and the summaries.
    void run() {
        while (turn()) {
        }
        if (headset_.lost()) show_loss();
        finish();
    }

    bool finished() const { return live_->finished(); }

    // The one message of a lost runtime (runtime_lost.h): where the session stood. After run().
    std::string loss_message() const {
        return runtime_lost_message(live_->screen(), live_->progress(), info_, db_,
                                    options_.headset);
    }

    // The protocol's end screen stays up for --end-s of display time (or until the experimenter
    // closes the window), so the participant reads it; an aborted session or one without an end
    // screen ends at once.
    bool end_screen_seen() const {
        if (live_->screen().kind != ScreenKind::End) return true;
        return end_shown_ns_ >= 0 &&
               last_frame_ns_ - end_shown_ns_ >= static_cast<std::int64_t>(options_.end_s * 1e9);
    }

  private:
    using Clock = std::chrono::steady_clock;

    // One turn: the runtime's events, then a frame while the session runs. False once the
    // session is over: the runtime ended it, or lost it.
    bool turn() {
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

    // An OpenXR call's value, or none once the runtime is lost: the session then ends as an
    // interruption (loss_message), not as an error. Any other failure goes to main().
    template <class T>
    std::optional<T> unless_lost(Result<T> result) const {
        if (result) return std::move(result).value();
        if (!headset_.lost()) throw UserError(result.error());
        return std::nullopt;
    }
    bool unless_lost(const Result<void>& result) const {
        if (result) return true;
        if (!headset_.lost()) throw UserError(result.error());
        return false;
    }

    // The loss in the experimenter window as on stderr: its status line and log tail, one last
    // frame (the one --screenshot saves).
    void show_loss() {
        const std::string message = loss_message();
        log_tail_.push_back(message);
        if (!experimenter_ || !last_frame_) return;
        window::ExperimenterView view = window_view(*last_frame_, live_->screen(), last_frame_ns_);
        view.status_line = message;
        window_commands_ = experimenter_->frame(view);
    }

    // What one frame rendered: the scene's renderer (or none) and what it returned.
    struct Rendered {
        bool shown = false;
        modes::ModeRenderer* renderer = nullptr;
        std::vector<profile::FrameStats> completed;
    };

    void frame() {
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
            frame_log_.displayed(logged, screen, tracked, cpu_ms, rendered.renderer);
            // After displayed(): a renderer that waited may return this very frame's time.
            frame_log_.completed(rendered.renderer, rendered.completed);
            live_->frame_presented(frame.index, now).value_or_throw();
        }
        charge(headset::FrameStep::kLog);
        report_progress(screen);
        if (experimenter_) update_window(frame, screen, now);
        times_.end_frame(rendered.renderer != nullptr);
    }

    // This process's run of the session begins with the runtime's first frame, one display period
    // after the run's clock starts (study/session_runs.h).
    void begin_run(const headset::HeadsetFrame& first) {
        live_
            ->begin_run({.runtime = headset_.runtime_name(),
                         .clock_start_ns = first.display_time_ns - first.display_period_ns})
            .value_or_throw();
    }

    // The controller, then the experimenter's window (the participant's keys among its
    // commands), then a response device, then a simulated observer. Every press of the
    // participant is logged with its source before what it asks for is requested.
    void handle_inputs(std::int64_t now) {
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

    // A key's time on the session's axis: its CLOCK_MONOTONIC time converted by the runtime
    // (XR_KHR_convert_timespec_time), else the time of the frame that read it (docs/data.md,
    // presses).
    std::int64_t key_time(const AnswerPress& press, std::int64_t frame_ns) const {
        if (!press.monotonic) return frame_ns;
        const std::optional<std::int64_t> runtime = headset_.runtime_time(*press.monotonic);
        return runtime ? live_->session_time(*runtime) : frame_ns;
    }

    // One press of the participant: logged, then requested as the controller's would be.
    void answer(const AnswerPress& press, std::int64_t time_ns) {
        live_->record_press(press.source, press.action, press.key, time_ns).value_or_throw();
        switch (press.action) {
            case study::PressAction::Switch:
                return request(LiveInput::Switch, time_ns);
            case study::PressAction::Confirm:
                return request(LiveInput::Confirm, time_ns);
            case study::PressAction::Pause:
                return request(live_->screen().paused ? LiveInput::Resume : LiveInput::Pause,
                               time_ns);
        }
    }

    // Whether anyone can answer, once the runtime had its syncs to bind a controller: a change
    // goes to stderr and the log tail; while nobody can, the window's status line says so.
    void watch_binding() {
        const bool focused = headset_.phase() == headset::SessionPhase::Focused;
        if (const std::optional<std::string> change = answers_.after_sync(headset_, focused)) {
            std::cerr << *change << "\n";
            log_tail_.push_back(*change);
        }
    }

    void window_command(const window::Command& c, std::int64_t now) {
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

    void request(LiveInput input, std::int64_t time_ns) {
        const std::string what = live_->request(input, time_ns).value_or_throw();
        if (options_.trace) {
            std::printf("request %s: %s\n", std::string(study::live_input_name(input)).c_str(),
                        what.c_str());
        }
    }

    // The screen into both eyes' swapchain images: the trial's scene through its renderer (the
    // eyes' copies ride in its submission), else the compositor's grey with overlays. No wait for
    // the GPU: each ring waits only for its frame two before.
    Rendered render(const headset::HeadsetFrame& frame, const LocatedHead& located,
                    const study::LiveScreen& screen, const rig::Pose& head) {
        std::array<vk::Image, 2> targets;
        std::array<vk::Image, 2> depth_targets;
        for (int e = 0; e < 2; ++e) {
            const std::optional<vk::Image> image = unless_lost(headset_.acquire_eye_image(e));
            std::optional<vk::Image> depth_image = vk::Image{};
            if (image && depth_writer_)
                depth_image = unless_lost(headset_.acquire_eye_depth_image(e));
            if (!image || !depth_image) return Rendered{};  // lost: nothing is drawn or shown
            targets[e] = *image;
            depth_targets[e] = *depth_image;
        }
        charge(headset::FrameStep::kOpenXrBegin);
        Rendered rendered;
        rendered.shown = true;
        modes::FrameInputs inputs;
        const std::vector<headset::EyeCompositor::Overlay> overlays =
            screen_overlays(screen, frame);
        if (screen.kind == ScreenKind::Trial && !screen.paused && frame.views_valid) {
            const study::ScheduledTrial& trial = *screen.trial;
            rendered.renderer = &renderers_.renderer(trial.scene, screen.mode);
            inputs.views =
                view_inputs(frame, located, head, renderers_.seat(trial.scene), protocol_);
            inputs.mono_plane = trial.mono_plane;
            // hybrid-auto: the trial's distance is the nearest plane its chooser may take.
            inputs.nearest_auto_plane = trial.mono_plane;
        }
        const modes::ModeRenderer* renderer = rendered.renderer;
        const auto record_eyes = [&](const vk::raii::CommandBuffer& cmd) {
            for (int e = 0; e < 2; ++e) {
                const auto eye = static_cast<modes::Eye>(e);
                headset::EyeCompositor::MirrorRecorder mirror;
                if (experimenter_ && e == 0) {
                    mirror = [this](const vk::raii::CommandBuffer& c, vk::Image image,
                                    vk::ImageLayout layout, vk::Extent2D size) {
                        experimenter_->record_mirror(c, image, layout, size);
                    };
                }
                compositor_.record_eye(cmd, targets[e], extent_, frame.views[e].tangents,
                                       renderer ? &renderer->display_image(eye) : nullptr, overlays,
                                       mirror);
                if (depth_writer_) {
                    record_depth(cmd, e, depth_targets[e], frame.views[e].tangents,
                                 inputs.views.cant[e], renderer, overlays);
                }
            }
        };
        charge(headset::FrameStep::kSession);
        if (rendered.renderer) {
            rendered.renderer->submit_frame(inputs, record_eyes);
            rendered.completed = rendered.renderer->take_completed();
            for (const profile::FrameStats& stats : rendered.completed) {
                times_.add_gpu_ms(stats.gpu_frame_ms);
            }
        } else {
            const std::uint32_t slot = compositor_frames_.begin();
            record_eyes(compositor_frames_.commands(slot));
            compositor_frames_.submit(slot);
        }
        charge(headset::FrameStep::kRender);
        return rendered;
    }

    // The eye's depth beside its colour (XR_KHR_composition_layer_depth, docs/headsets.md): the
    // scene's as the renderer left it, or infinity without a scene; the overlays at infinity,
    // where their zero disparity puts them.
    void record_depth(const vk::raii::CommandBuffer& cmd, int e, vk::Image target,
                      const rig::Tangents& tangents, double cant,
                      const modes::ModeRenderer* renderer,
                      const std::vector<headset::EyeCompositor::Overlay>& overlays) {
        std::optional<headset::EyeDepthSource> source;
        if (renderer) {
            source.emplace();
            source->linear_depth = renderer->eye_linear_depth_image(static_cast<modes::Eye>(e));
            source->tangents = tangents;
            // The renderer turns the eye by R_y(cant) in the head's frame (view_setup.cpp), its
            // position on the eyes' plane: head -> eye undoes the turn.
            source->head_to_eye = glm::mat3_cast(glm::angleAxis(-cant, glm::dvec3(0.0, 1.0, 0.0)));
        }
        depth_writer_->record(cmd, target, extent_, source ? &*source : nullptr, protocol_.near,
                              compositor_.overlay_rects(overlays, tangents, extent_));
    }

    // The label in a trial, the pause panel, the questionnaire item with its selection, or a page.
    std::vector<headset::EyeCompositor::Overlay> screen_overlays(const study::LiveScreen& screen,
                                                                 const headset::HeadsetFrame& f) {
        if (is_page_screen(screen.kind)) {
            return {pages_.overlay(screen, compositor_, {f.views[0].tangents, f.views[1].tangents},
                                   extent_)};
        }
        if (screen.kind == ScreenKind::Trial && screen.paused) {
            return {{"paused", kPanelPlacement}};
        }
        if (screen.kind == ScreenKind::Trial) {
            return {{screen.label == 1 ? "label1" : "label2", kLabelPlacement}};
        }
        if (screen.kind != ScreenKind::Questionnaire) return {};
        const std::string key =
            "question" + std::to_string(screen.question) + "-" + std::to_string(screen.selection);
        if (!compositor_.has_overlay(key)) {
            compositor_.set_overlay(
                key, headset::render_text(
                         questionnaire_lines(protocol_, screen.question, screen.selection),
                         headset::TextStyle{.font = protocol_.day.font}));
        }
        return {{key, kPanelPlacement}};
    }

    void report_progress(const study::LiveScreen& screen) {
        const study::LiveProgress progress = live_->progress();
        if (progress.trial_number == last_reported_trial_ || screen.kind != ScreenKind::Trial) {
            return;
        }
        last_reported_trial_ = progress.trial_number;
        std::cerr << "trial " << progress.trial_number << "/" << progress.trial_count << ": "
                  << screen.trial->scene << " m = " << screen.trial->mono_plane
                  << (screen.trial->practice ? " (practice)" : "") << "\n";
    }

    void update_window(const headset::HeadsetFrame& frame, const study::LiveScreen& screen,
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

    window::ExperimenterView window_view(const headset::HeadsetFrame& frame,
                                         const study::LiveScreen& screen, std::int64_t now) const {
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
        view.frame_ms =
            std::chrono::duration<double, std::milli>(Clock::now() - frame_start_).count();
        mirror_page(screen, view);
        view.note_status = note_status_;
        view.status_line =
            std::string("session ") + std::string(headset::session_phase_name(headset_.phase()));
        if (answers_.cannot_answer()) view.status_line = *answers_.cannot_answer();
        return view;
    }

    void save_screenshot() {
        experimenter_->save_screenshot(options_.screenshot).value_or_throw();
        std::cerr << "wrote " << options_.screenshot << "\n";
        screenshot_saved_ = true;
    }

    // The last frames' GPU times into the log, the log to disk, the timing summary.
    void finish() {
        if (experimenter_ && !options_.screenshot.empty() && !screenshot_saved_) save_screenshot();
        if (times_.scene_frames() > 0) std::cerr << times_.summary();
        renderers_.for_each(
            [&](modes::ModeRenderer& r) { frame_log_.completed(&r, r.finish_frames()); });
        frame_log_.flush();
        std::cerr << frame_log_.build_summary();
    }

    void request_exit() {
        if (exit_requested_) return;
        if (!unless_lost(headset_.request_exit())) return;  // lost: the session is over anyway
        exit_requested_ = true;
    }

    void committed(const std::string& what) {
        if (options_.trace) {
            std::printf("committed %s\n", what.c_str());
            std::fflush(stdout);
        }
        log_tail_.push_back(what);
        if (log_tail_.size() > 200) log_tail_.pop_front();
    }

    // Charges the time since the last step to `step`.
    void charge(headset::FrameStep step) {
        const auto now = Clock::now();
        times_.add(step, std::chrono::duration<double, std::milli>(now - step_start_).count());
        step_start_ = now;
    }

    const HeadsetStudyOptions& options_;
    const study::Protocol& protocol_;
    study::SessionInfo info_;
    std::filesystem::path db_;  // the study database, for the resume line of a lost runtime
    headset::OpenXrHeadset& headset_;
    const vk_core::Context& ctx_;
    window::ExperimenterWindow* experimenter_;
    StudyRenderers& renderers_;
    vk::Extent2D extent_;
    headset::EyeCompositor compositor_;
    // Frames without a scene (neutral screen, questionnaire) are the compositor's alone; scene
    // frames ride in their renderer's ring.
    vk_core::FrameRing compositor_frames_;
    // The eyes' depth, when the runtime takes it (XR_KHR_composition_layer_depth).
    std::optional<headset::EyeDepthWriter> depth_writer_;
    std::unique_ptr<study::LiveSession> live_;
    std::optional<study::ObserverInput> observer_input_;
    HeadsetFrameLog frame_log_;
    PagePanels pages_;  // the protocol's pages of text (instructions, breaks...)
    headset::FrameTimes times_;
    Clock::time_point frame_start_;
    Clock::time_point step_start_;
    SeatAnchor anchor_;
    std::optional<headset::HeadsetFrame> last_frame_;  // the latest begun, for the window
    std::int64_t first_frame_ns_ = -1;
    std::int64_t last_frame_ns_ = -1;
    std::int64_t end_shown_ns_ = -1;  // the first frame that showed the end screen
    int last_reported_trial_ = -1;
    bool exit_requested_ = false;
    // The experimenter window's state.
    std::deque<std::string> log_tail_;
    std::vector<window::Command> window_commands_;
    timespec window_read_{};  // when the window last polled its keys (CLOCK_MONOTONIC)
    std::vector<int> window_answers_;
    std::string note_status_;  // the last note's outcome, for the note field
    bool unblinded_ = false;
    bool screenshot_saved_ = false;
    ParticipantAnswers& answers_;  // keys, a response device, the controller's binding
};

// The experimenter window when wanted and possible, and the instance and device extensions it
// needs added to the context's.
bool want_window(const HeadsetStudyOptions& options, vk_core::ContextOptions& context_options) {
    if (!(options.window == "on" || (options.window == "auto" && has_display()))) return false;
    auto extensions = window::required_instance_extensions();
    if (!extensions) {
        if (options.window == "on") throw UserError(extensions.error().message);
        std::cerr << "no experimenter window: " << extensions.error().message << "\n";
        return false;
    }
    context_options.instance_extensions = *extensions;
    context_options.device_extensions = window::required_device_extensions();
    return true;
}

// The runtime `options.headset` names (simxr, written a script, for simulated) with the Vulkan
// device it makes from `context_options`.
headset::HeadsetDevice open_headset(const HeadsetStudyOptions& options, const GlobalOptions& global,
                                    const vk_core::ContextOptions& context_options) {
    RuntimeSelection selection(options);
    auto created = headset::OpenXrHeadset::create(global.validation, options.layer_depth != "off");
    // simxr has read its script (in xrCreateInstance): the environment goes back as it was, so
    // the launcher's next session reaches the runtime it chooses.
    selection.instance_created();
    std::unique_ptr<headset::OpenXrHeadset> openxr = std::move(created).value_or_throw();
    std::cerr << "OpenXR runtime: " << openxr->runtime_name() << ", system "
              << openxr->system_name() << "\n";
    return headset::HeadsetDevice::create(std::move(openxr), context_options).value_or_throw();
}

}  // namespace

study::SessionStatus run_headset_session(
    const HeadsetStudyOptions& options, const GlobalOptions& global, study::StudyStore& store,
    const study::Protocol& protocol, ImportedStudyScenes imported, study::Observer* observer,
    const std::function<double(const study::ScheduledTrial&)>& trial_error_px,
    const std::function<std::int64_t(const std::string&, const std::string&)>& begin) {
    // The answer keys first: a bad option or an unreadable device stops before the headset.
    const study::ResponseSettings responses =
        resolve_responses(protocol.responses, options.keys, options.response_device);
    vk_core::ContextOptions context_options = global.context_options();
    const bool window = want_window(options, context_options);
    ParticipantAnswers answers(responses, window, observer != nullptr);
    if (responses.enabled) {
        std::cerr << "answers: " << study::describe_responses(responses) << "\n";
        if (!window && responses.device.empty()) {
            std::cerr << "the answer keys are read from the experimenter window, and there is "
                         "none (--window off, or no display): only the controller answers\n";
        }
    }
    // OpenXR goes before Vulkan on every way out (headset_device.h); what renders is declared
    // after the device, so it goes before both.
    const headset::HeadsetDevice device = open_headset(options, global, context_options);
    headset::OpenXrHeadset& headset = device.headset();
    const vk_core::Context& ctx = device.vulkan();
    std::cerr << "device: " << ctx.device_info().name << "\n";
    headset.create_session(ctx, options.resolution_scale).value_or_throw();
    const vk::Extent2D extent = headset.eye_extent();
    std::cerr << "eye swapchains: " << extent.width << " x " << extent.height << "\n";
    std::unique_ptr<window::ExperimenterWindow> experimenter;
    if (window) experimenter = window::ExperimenterWindow::create(ctx, {}, extent).value_or_throw();
    if (experimenter) experimenter->set_response_keys(window_bindings(responses));

    const std::int64_t session_id = begin(headset.runtime_name(), ctx.device_info().name);
    // Sessions of schema version 1 recorded no detail: they rendered at the default, low.
    study::RenderSettings render = store.session(session_id).value_or_throw().render;
    if (render.detail.empty()) render.detail = "low";
    StudyRenderers renderers(ctx, protocol, extent, render, std::move(imported));
    bool finished = false;
    std::string loss;  // the lost runtime's message; empty if it was not lost
    {
        HeadsetLoop loop(options, protocol, store, session_id, headset, ctx, experimenter.get(),
                         renderers, observer, trial_error_px, answers);
        loop.run();
        finished = loop.finished();
        if (headset.lost()) loss = loop.loss_message();
        ctx.device().waitIdle();
    }
    experimenter.reset();
    // Here rather than in the destructor: what the validation layers say of it counts below.
    headset.destroy_session();
    fail_on_validation_messages(ctx, headset.validation_messages(), global);
    const study::SessionInfo end = store.session(session_id).value_or_throw();
    // A runtime lost after the session completed took nothing from it.
    if (!finished && !loss.empty()) throw RuntimeLost(loss);
    if (!finished) {
        // Not an error of the study's data (everything decided is stored), but the session did
        // not finish: the exit status says so, for scripts that run sessions.
        throw UserError("the OpenXR session ended (" +
                        std::string(headset::session_phase_name(headset.phase())) +
                        ") before the study did; `monoplane study resume --db ...` continues at "
                        "the first undecided trial");
    }
    return end.status;
}

}  // namespace monoplane::app
