// The launcher's headset step (`monoplane lab`, docs/headsets.md): a probe of the OpenXR runtime
// (no session), and the headset check, a short session that shows the participant a calibration
// screen, not a trial, so the fit can be checked while the runtime reports what only a session
// knows: the refresh rate, the eyes' distance, the controllers' interaction profile and whether
// the eye tracker sees the participant's eyes.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "app/commands/global_options.h"
#include "app/commands/study_headset.h"
#include "app/headset/headset_probe.h"
#include "common/result.h"

namespace monoplane::app {

// The runtime `study run --headset simulated|openxr` would use, probed: simulated points the
// loader at simxr exactly as that command does (headset.hmd, sim_script, sim_rate_hz of
// `simulation`), openxr at the runtime that was selected when the program started. The process's
// environment is as before on return. No runtime is not an error (runtime_available false, with
// what to do in message); errors: a bad simulated script, or OpenXR validation messages with
// `validation`. Call from one thread, while no other XrInstance of the process is alive
// (no running check or session).
Result<headset::HeadsetProbe> probe_headset(bool simulated,
                                            const HeadsetStudyOptions& simulation = {},
                                            bool validation = false);

// How a headset check ended.
enum class CheckEnd {
    Confirmed,     // the participant pressed CONFIRM (or the experimenter confirmed for them)
    Cancelled,     // the experimenter cancelled
    TimedOut,      // no CONFIRM within timeout_s
    RuntimeEnded,  // the runtime ended the session first (STOPPING, EXITING)
    RuntimeLost,   // the session or instance was lost, or an OpenXR call failed mid-check
};
const char* check_end_name(CheckEnd end);

// What the calling window may do after each turn of the check's loop.
enum class CheckRequest { Continue, Confirm, Cancel };

// Where the check is, for the window to show while it runs.
struct HeadsetCheckProgress {
    std::int64_t frames_shown = 0;
    double elapsed_s = 0.0;  // wall-clock time since the session was created
    std::string phase;       // the session's state, "focused"
    double refresh_hz = 0.0;
    std::optional<double> ipd_m;
    std::string interaction_profile;
    headset::EyeGaze eye_gaze = headset::EyeGaze::Unknown;
    std::int64_t gaze_frames = 0;  // frames shown with a valid gaze sample
};

struct HeadsetCheckOptions {
    // headset: "simulated" or "openxr"; for simulated, hmd, sim_script, sim_rate_hz and
    // sim_head_motion as `study run` takes them; resolution_scale for the eye images.
    HeadsetStudyOptions headset;
    GlobalOptions
        global;  // Vulkan device; validation: Vulkan's and OpenXR's layers, as --validation
    double timeout_s = 120.0;  // wall clock: the check never waits longer for CONFIRM
    // Called on the calling thread once per turn of the loop (each frame, and every few
    // milliseconds while the runtime is not showing frames): the window draws itself and
    // returns the experimenter's Confirm or Cancel. Unset: Continue.
    std::function<CheckRequest(const HeadsetCheckProgress&)> on_turn;
};

struct HeadsetCheck {
    CheckEnd end = CheckEnd::RuntimeLost;
    std::string message;  // how it ended, in words the experimenter can act on
    std::string runtime;  // the runtime's name and version
    std::string system;
    int width = 0, height = 0;        // the eyes' images, pixels
    double refresh_hz = 0.0;          // 1 / the predicted display period; 0: no frame came
    std::optional<double> ipd_m;      // distance between the located eyes (xrLocateViews), metres
    std::string interaction_profile;  // the bound profile's path; "": none bound
    std::int64_t frames_shown = 0;    // frames whose calibration screen was submitted
    // Whether the headset tracks the eyes (the check asks for eye gaze where the runtime offers
    // it), and of the frames shown, those whose gaze sample was valid: a tracker that is there
    // but cannot see the participant's eyes (not calibrated, the headset badly fitted) shows as
    // few valid frames.
    headset::EyeGaze eye_gaze = headset::EyeGaze::Unknown;
    std::int64_t gaze_frames = 0;
};

// Runs the headset check on the runtime `options.headset.headset` names: a session over Vulkan
// (as a study session makes it) whose eyes show a neutral grey, a grid with a centre cross and
// the instruction to press CONFIRM once the text is sharp and the grid square, until the
// participant's CONFIRM (or on_turn's), on_turn's Cancel, the timeout, or the runtime ending or
// losing the session, whichever comes first. Every such end is a HeadsetCheck, never an error or
// a hang; errors: no runtime or headset (probe_headset says so first), no Vulkan device, a bad
// simulated script, or validation messages with global.validation. Call from one thread, while
// no other XrInstance or check of the process is alive; it blocks until the check ends.
Result<HeadsetCheck> run_headset_check(const HeadsetCheckOptions& options);

}  // namespace monoplane::app
