// The launcher window's contents (Dear ImGui calls): one panel per step of the model, the roster
// and the keyboard shortcuts. Separate from the window (launcher_window.cpp) so that the drawing
// reads as the model's steps, and the window as its frame loop. The frame, the keys and the
// footer are in launcher_panels.cpp, each step's panel in its launcher_panels_<step>.cpp.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include "app/lab/frame_time_job.h"
#include "app/lab/launcher_controls.h"
#include "app/lab/launcher_model.h"
#include "app/lab/launcher_window.h"
#include "app/window/desktop_window.h"

namespace monoplane::lab {

class LauncherPanels {
  public:
    LauncherPanels(LauncherModel& model, LauncherUi& ui, LauncherActions actions)
        : model_(model), ui_(ui), actions_(std::move(actions)) {}

    // A key press of the frame about to be drawn: Tab and Shift+Tab (the next or previous
    // control) and the shortcuts (Ctrl+Right next step, Ctrl+Left back, Ctrl+Enter Start, Ctrl+H
    // check the headset, Ctrl+E Export, Ctrl+R Analyse, Ctrl+Q quit). Between
    // DesktopWindow::poll_events() and new_frame().
    void key(const window::KeyPress& press);
    // Draws the whole window for the model as it stands, acting on what was clicked. Between
    // DesktopWindow::new_frame() and end_frame().
    void draw();

    // Start or Resume was chosen: the request (the model is in its Session step). Once.
    std::optional<LaunchRequest> take_launch() { return std::exchange(launch_, std::nullopt); }
    bool quit_requested() const { return quit_; }

    // "Check the headset" (or Ctrl+H) was chosen in the Headset step: the window runs the check
    // (run_check) after this frame. Once.
    bool take_check_request() { return std::exchange(check_requested_, false); }
    // Runs the headset check through the app (LauncherActions::check_headset), `turn` drawing
    // each of its frames (check_key, draw_check), and puts its outcome in the model's headset
    // report. Between frames, never inside one.
    void run_check(const std::function<CheckAnswer(const HeadsetCheckTurn&)>& turn);
    // A key press while the check runs: Ctrl+F the headset fits, Escape cancels, Ctrl+Q cancels
    // and quits.
    void check_key(const window::KeyPress& press);
    // Draws the whole window while the check runs (the check's panel with Fits and Cancel);
    // returns what the experimenter asked. Between new_frame() and end_frame().
    CheckAnswer draw_check(const HeadsetCheckTurn& turn);
    // The window was closed while the check runs: it is cancelled.
    void cancel_check() { check_answer_ = CheckAnswer::Cancel; }
    // The experimenter's answer since the last turn, for a turn without a frame drawn. Once.
    CheckAnswer take_check_answer() { return std::exchange(check_answer_, CheckAnswer::Continue); }

  private:
    void draw_steps();
    // The chosen protocol, under the steps on every step.
    void draw_protocol_line();
    void choose_typed_protocol();
    void draw_participant_problems();
    // Start, greyed when disabled, with the reason or the command line under it.
    void draw_start_button();
    void draw_command_line();
    void draw_roster_line(const RosterLine& line);
    void next_participant();
    void draw_database();
    void draw_protocol();
    void draw_participant();
    void draw_variable(const VariableField& field);
    void draw_headset();
    void draw_headset_report();
    void draw_eye_gaze(const HeadsetReport& report);
    void draw_check_result();
    // The session settings (session_settings_panel.cpp): the performance preset, its frame-time
    // estimate with the verdict, and Measure / Cancel.
    void draw_session_settings();
    // The answer keys (--keys): the protocol's, default or none.
    void draw_keys_choice();
    void draw_estimates();
    void draw_verdict();
    void draw_measurement();
    void measure_frame_time();
    // Takes a finished measurement's outcome into the model. Each frame.
    void poll_measurement();
    // Whether anyone can answer, from what the check saw of the controller (`profile` bound
    // after `frames` frames): the warning, or empty.
    std::string answers_warning(const std::string& profile, std::int64_t frames) const;
    // The same, into the headset report's answer_warning.
    void judge_answers(const std::string& profile, std::int64_t frames);
    // Refuses (with the footer's message) what must not run beside the measurement.
    bool measuring_refuses(const char* what);
    // Probes the chosen headset when the step is entered or the choice changed.
    void probe_if_needed();
    void request_check();
    void draw_start();
    void draw_summary();
    void draw_roster();
    void draw_footer();
    // Focuses the next item when the step was just entered.
    void focus_on_entry();
    // Focuses the item just drawn (a button) when the step was just entered.
    void focus_item_on_entry();
    void next_step();
    void go_to(LauncherStep step);
    void choose_protocol(const std::filesystem::path& path);
    void start();
    void export_data();
    void analyse();
    // Keeps a refusal for the footer; true when `result` succeeded.
    bool note(const Result<void>& result);

    LauncherModel& model_;
    LauncherUi& ui_;
    LauncherActions actions_;
    std::optional<LaunchRequest> launch_;
    bool quit_ = false;
    std::optional<LauncherStep> focused_step_;  // the step whose entry focus was set
    std::optional<std::string> probed_choice_;  // the headset probed since the step was entered
    bool check_requested_ = false;
    bool check_focused_ = false;                        // Fits has the keyboard focus
    CheckAnswer check_answer_ = CheckAnswer::Continue;  // the experimenter's, for the next turn
    ControlRing controls_;
    // After actions_: destroyed (cancelled and joined) before the probe it runs.
    FrameTimeJob frame_time_job_;
    std::optional<LauncherStep> drawn_step_;  // the step of the last frame (stale messages go)
    float footer_height_ = 0.0f;              // as the last frame drew it
};

}  // namespace monoplane::lab
