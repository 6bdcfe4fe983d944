// The window of `monoplane lab`: draws the launcher's model (launcher_model.h) step by step with
// Dear ImGui on a desktop window (app/window/desktop_window.h) and forwards the experimenter's
// input to it. It decides nothing itself: what a step shows, what is valid and what Start hands
// on all come from the model. The window is closed while a session runs (the session opens its
// own experimenter window) and opened again for the summary, so what must outlive it is kept in
// LauncherUi.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/lab/frame_time_job.h"
#include "app/lab/launcher_model.h"
#include "app/window/desktop_window.h"
#include "common/result.h"
#include "renderer/vk/context.h"

namespace monoplane::lab {

// The headset check while it runs, as the window shows it (app::HeadsetCheckProgress's fields).
struct HeadsetCheckTurn {
    std::int64_t frames_shown = 0;
    double refresh_hz = 0.0;
    std::optional<double> ipd_m;
    std::string interaction_profile;
    bool gaze_tracked = false;
    std::int64_t gaze_frames = 0;  // frames shown with a valid gaze sample
};

// What the experimenter asks after each turn of the check (app::CheckRequest).
enum class CheckAnswer { Continue, Confirm, Cancel };

// What the launcher asks of the app that it cannot do itself (the same code as the commands).
struct LauncherActions {
    // The headset step: probes the runtime `study run --headset HEADSET` would use ("simulated"
    // or "openxr"; app::probe_headset with the lab's simulated-headset options). No runtime is
    // a report with runtime_available false and its message, not an error. Unset: not probed.
    std::function<Result<HeadsetReport>(const std::string& headset)> probe_headset;
    // The headset check on that runtime (app::run_headset_check): blocks until it ends, calling
    // `turn` on the calling thread every frame (the window draws itself and answers). Returns
    // the runtime's report with refresh rate, IPD and interaction profile, and check,
    // check_message and check_frames saying how it ended. Unset: no check offered.
    std::function<Result<HeadsetReport>(
        const std::string& headset,
        const std::function<CheckAnswer(const HeadsetCheckTurn&)>& turn)>
        check_headset;
    // The session settings' frame-time probe (lab::probe_frame_time on a device of its own, with
    // the program's device and validation options); the app fills in the HMD profile, and the
    // profile's eye size where the request has none. Runs on the window's worker thread.
    // Unset: no measurement offered.
    FrameTimeProbe probe_frame_time;
    // `study export` of the open database; returns the file written.
    std::function<Result<std::filesystem::path>()> export_data;
    // `analyze` of the open database; returns the report written.
    std::function<Result<std::filesystem::path>()> analyse;
};

// The launcher's state that outlives one opening of its window.
struct LauncherUi {
    std::filesystem::path state_file;        // --state-file: the model's state_json, kept current
    std::filesystem::path screenshot_dir;    // --screenshot-dir: NN-<step>.png per step shown
    std::string database_text;               // the Database step's path field
    std::string protocol_text;               // the Protocol step's file name field
    std::vector<std::string> summary_lines;  // summarize_session's, after a session
    std::string export_message;              // where Export wrote, or why it did not
    std::string analysis_message;            // likewise for Analyse
    std::string action_message;              // the last refused action (a step not done yet)
    int screenshots = 0;                     // numbers the screenshots across openings
    std::string last_state;                  // the state last written to state_file
};

// What ended an opening of the window.
struct LauncherExit {
    std::optional<LaunchRequest> launch;  // Start or Resume: the session to run; none: closed
};

// Writes `text` to `file` through a temporary file and a rename, so that a reader never sees a
// partial state. Any time.
Result<void> write_file_atomically(const std::filesystem::path& file, const std::string& text);

class LauncherWindow {
  public:
    // Opens the window on `ctx` (created with window::required_instance_extensions() and
    // required_device_extensions()); the model, ui and actions must outlive the window, which
    // must be destroyed before the Context. One window per process at a time.
    static Result<std::unique_ptr<LauncherWindow>> create(const vk_core::Context& ctx,
                                                          LauncherModel& model, LauncherUi& ui,
                                                          LauncherActions actions);
    ~LauncherWindow();

    // Draws frames and handles input until the experimenter starts (or resumes) a session or
    // closes the window (or presses Ctrl+Q). Once per opening.
    LauncherExit run();

  private:
    struct Impl;
    explicit LauncherWindow(std::unique_ptr<Impl> impl);
    std::unique_ptr<Impl> impl_;
};

}  // namespace monoplane::lab
