// One headset session's frame loop (HeadsetLoop), shared by the files that define it:
// study_headset_loop.cpp (the turns and frames), study_headset_inputs.cpp (the participant's and
// the experimenter's inputs), study_headset_eyes.cpp (what the eyes are shown) and
// study_headset_window.cpp (the experimenter window). Only run_headset_session
// (study_headset.cpp) drives it.
#pragma once

#include <chrono>
#include <cstdint>
#include <ctime>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/commands/gaze_point.h"
#include "app/commands/headset_frame_log.h"
#include "app/commands/participant_answers.h"
#include "app/commands/screen_pages.h"
#include "app/commands/study_headset.h"
#include "app/commands/study_headset_seat.h"
#include "app/commands/study_renderers.h"
#include "app/headset/eye_compositor.h"
#include "app/headset/eye_depth_writer.h"
#include "app/headset/frame_times.h"
#include "app/headset/openxr_headset.h"
#include "app/window/experimenter_window.h"
#include "common/result.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/vk/frame_ring.h"
#include "study/live_session.h"
#include "study/observer_input.h"

namespace monoplane::app {

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
                ParticipantAnswers& answers);

    // Frames until the runtime ends the session (after the study, or when the window closes) or
    // is lost; then the frame log and the summaries.
    void run();

    bool finished() const { return live_->finished(); }

    // The one message of a lost runtime (runtime_lost.h): where the session stood. After run().
    std::string loss_message() const;

    // The protocol's end screen stays up for --end-s of display time (or until the experimenter
    // closes the window), so the participant reads it; an aborted session or one without an end
    // screen ends at once.
    bool end_screen_seen() const;

  private:
    using Clock = std::chrono::steady_clock;

    // What one frame rendered: the scene's renderer (or none) and what it returned.
    // A trial frame's scene as the renderer was given it: where the gaze points are found.
    struct TrialView {
        std::string scene;
        modes::StereoViewInputs views;  // the head placed in the scene
        double mono_plane = 0.0;        // the trial's m
    };
    struct Rendered {
        bool shown = false;
        modes::ModeRenderer* renderer = nullptr;
        std::vector<profile::FrameStats> completed;
        std::optional<TrialView> trial_view;
    };

    // The turns and frames (study_headset_loop.cpp).

    // One turn: the runtime's events, then a frame while the session runs. False once the
    // session is over: the runtime ended it, or lost it.
    bool turn();
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
    void frame();
    // This process's run of the session begins with the runtime's first frame, one display period
    // after the run's clock starts (study/session_runs.h).
    // The frame's gaze point (gaze_point.h), for a trial frame with a valid gaze sample in a
    // session that records gaze.
    std::optional<study::GazePointRecord> find_gaze_point(const headset::HeadsetFrame& frame,
                                                          const Rendered& rendered);
    void begin_run(const headset::HeadsetFrame& first);
    void report_progress(const study::LiveScreen& screen);
    // The last frames' GPU times into the log, the log to disk, the timing summary.
    void finish();
    void request_exit();
    void committed(const std::string& what);
    // Charges the time since the last step to `step`.
    void charge(headset::FrameStep step);

    // The inputs (study_headset_inputs.cpp).

    // The controller, then the experimenter's window (the participant's keys among its
    // commands), then a response device, then a simulated observer. Every press of the
    // participant is logged with its source before what it asks for is requested.
    void handle_inputs(std::int64_t now);
    // A key's time on the session's axis: its CLOCK_MONOTONIC time converted by the runtime
    // (XR_KHR_convert_timespec_time), else the time of the frame that read it (docs/data.md,
    // presses).
    std::int64_t key_time(const AnswerPress& press, std::int64_t frame_ns) const;
    // One press of the participant: logged, then requested as the controller's would be.
    void answer(const AnswerPress& press, std::int64_t time_ns);
    // Whether anyone can answer, once the runtime had its syncs to bind a controller: a change
    // goes to stderr and the log tail; while nobody can, the window's status line says so.
    void watch_binding();
    void window_command(const window::Command& c, std::int64_t now);
    void request(study::LiveInput input, std::int64_t time_ns);

    // What the eyes are shown (study_headset_eyes.cpp).

    // The screen into both eyes' swapchain images: the trial's scene through its renderer (the
    // eyes' copies ride in its submission), else the compositor's grey with overlays. No wait for
    // the GPU: each ring waits only for its frame two before.
    Rendered render(const headset::HeadsetFrame& frame, const LocatedHead& located,
                    const study::LiveScreen& screen, const rig::Pose& head);
    // The eye's depth beside its colour (XR_KHR_composition_layer_depth, docs/headsets.md): the
    // scene's as the renderer left it, or infinity without a scene; the overlays at infinity,
    // where their zero disparity puts them.
    void record_depth(const vk::raii::CommandBuffer& cmd, int e, vk::Image target,
                      const rig::Tangents& tangents, double cant,
                      const modes::ModeRenderer* renderer,
                      const std::vector<headset::EyeCompositor::Overlay>& overlays);
    // The label in a trial, the pause panel, the questionnaire item with its selection, or a page.
    std::vector<headset::EyeCompositor::Overlay> screen_overlays(const study::LiveScreen& screen,
                                                                 const headset::HeadsetFrame& f);

    // The experimenter window (study_headset_window.cpp).

    // The loss in the experimenter window as on stderr: its status line and log tail, one last
    // frame (the one --screenshot saves).
    void show_loss();
    void update_window(const headset::HeadsetFrame& frame, const study::LiveScreen& screen,
                       std::int64_t now);
    window::ExperimenterView window_view(const headset::HeadsetFrame& frame,
                                         const study::LiveScreen& screen, std::int64_t now) const;
    void save_screenshot();

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
    // [gaze] record on a runtime that tracks the eyes: where each trial frame's gaze rests.
    std::unique_ptr<GazePointFinder> gaze_points_;
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

}  // namespace monoplane::app
