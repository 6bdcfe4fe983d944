// `study run|resume --headset simulated|openxr`: the study core, the renderer and an OpenXR
// headset wired together (docs/headsets.md). Each trial renders its scene in the shown
// alternative's mode at the trial's m; a switch is drawn in the next frame and logged with the
// index of the frame that showed it; between trials a neutral screen; at the end the
// questionnaire, in the headset or entered by the experimenter in the window.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include <cstdint>
#include <functional>
#include <string>

#include "app/commands/commit_trace.h"
#include "app/commands/global_options.h"
#include "app/commands/study_scenes.h"
#include "hmd/profile.h"
#include "study/observer.h"
#include "study/protocol.h"
#include "study/study_store.h"

namespace monoplane::app {

struct HeadsetStudyOptions {
    std::string headset;                   // "simulated" or "openxr"
    std::string window = "auto";           // auto (when a display exists), on, off
    std::string detail;                    // scene detail; empty: the protocol's [render] detail
    double resolution_scale = 1.0;         // of the runtime's recommended eye size
    double neutral_s = 1.0;                // neutral screen between trials
    double end_s = 10.0;                   // the protocol's end screen stays up this long
    CommitTrace trace = CommitTrace::Off;  // each durable write on stdout
    std::string screenshot;                // PNG of the experimenter window (tests, docs)...
    std::int64_t screenshot_frame = -1;    // ...after this frame; -1: when the session ends
    // auto: each eye's depth goes with its colour when the runtime offers
    // XR_KHR_composition_layer_depth; off: never (docs/headsets.md, "Depth submission").
    std::string layer_depth = "auto";
    // The participant's answer keys over the protocol's [responses] (docs/study.md, "Answers from
    // a keyboard or response box"): --keys (default, none or switch=KEY,confirm=KEY) and
    // --response-device (an evdev device). Empty: the protocol's.
    std::string keys;
    std::string response_device;
    // Simulated runtime only:
    std::string sim_script;    // a simxr script; empty: one is written from the options below
    std::string hmd = "vive";  // the simulated headset's profile
    double sim_rate_hz = 90.0;
    std::string sim_head_motion = "seated";  // simxr's head_motion: still or seated
    std::string dump_frames;                 // folder for the submitted frames as PNG
};

// The OpenXR loader's runtime for one headset's instance (a probe, a check, a session): for
// "simulated", monoplane's simulated runtime with a script written from the options (or
// --sim-script), whatever runtime the machine has active, so a dry run never reaches a real
// headset; for "openxr", the environment as the program was given it. The loader reads
// XR_RUNTIME_JSON (and simxr SIMXR_SCRIPT) in xrCreateInstance: once the instance exists, or the
// selection goes, both are put back as they were and the written script is removed, so one
// choice never carries over to the next (the launcher offers simulated and openxr in turn).
// Create it just before the instance, on the thread that creates it; throws UserError for a
// --sim-script that does not exist or a script that cannot be written.
class RuntimeSelection {
  public:
    explicit RuntimeSelection(const HeadsetStudyOptions& options);
    ~RuntimeSelection();
    RuntimeSelection(const RuntimeSelection&) = delete;
    RuntimeSelection& operator=(const RuntimeSelection&) = delete;

    // The instance was created (or refused): the environment is as before from here on.
    void instance_created();

  private:
    std::optional<std::string> runtime_, script_variable_;  // as they were
    std::optional<std::filesystem::path> written_;          // the script written, if any
    bool restored_ = false;
};

// Runs the session's remaining trials and questionnaire on the headset. `begin` is called once
// the headset and device are known (runtime name, device name) and returns the session id (a
// new session, or the one being resumed). observer: answers for the participant (simulated
// runs), or null when a person holds the controller. imported: the protocol's glTF scenes,
// loaded (and their files recorded) before the session began.
study::SessionStatus run_headset_session(
    const HeadsetStudyOptions& options, const GlobalOptions& global, study::StudyStore& store,
    const study::Protocol& protocol, ImportedStudyScenes imported, study::Observer* observer,
    const std::function<double(const study::ScheduledTrial&)>& trial_error_px,
    const std::function<std::int64_t(const std::string& runtime, const std::string& device)>&
        begin);

}  // namespace monoplane::app
