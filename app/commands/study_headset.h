// `study run|resume --headset simulated|openxr`: the study core, the renderer and an OpenXR
// headset wired together (docs/headsets.md). Each trial renders its scene in the shown
// alternative's mode at the trial's m; a switch is drawn in the next frame and logged with the
// index of the frame that showed it; between trials a neutral screen; at the end the
// questionnaire, in the headset or entered by the experimenter in the window.
#pragma once

#include <filesystem>
#include <optional>

#include <cstdint>
#include <functional>
#include <string>

#include "app/commands/global_options.h"
#include "app/commands/study_scenes.h"
#include "hmd/profile.h"
#include "study/observer.h"
#include "study/protocol.h"
#include "study/study_store.h"

namespace monoplane::app {

struct HeadsetStudyOptions {
    std::string headset;                 // "simulated" or "openxr"
    std::string window = "auto";         // auto (when a display exists), on, off
    std::string detail;                  // scene detail; empty: the protocol's [render] detail
    double resolution_scale = 1.0;       // of the runtime's recommended eye size
    double neutral_s = 1.0;              // neutral screen between trials
    double end_s = 10.0;                 // the protocol's end screen stays up this long
    bool trace = false;                  // each durable write on stdout
    std::string screenshot;              // PNG of the experimenter window (tests, docs)...
    std::int64_t screenshot_frame = -1;  // ...after this frame; -1: when the session ends
    // auto: each eye's depth goes with its colour when the runtime offers
    // XR_KHR_composition_layer_depth; off: never (docs/headsets.md, "Depth submission").
    std::string layer_depth = "auto";
    // Simulated runtime only:
    std::string sim_script;    // a simxr script; empty: one is written from the options below
    std::string hmd = "vive";  // the simulated headset's profile
    double sim_rate_hz = 90.0;
    std::string sim_head_motion = "seated";  // simxr's head_motion: still or seated
    std::string dump_frames;                 // folder for the submitted frames as PNG
};

// Points the OpenXR loader at monoplane's simulated runtime and writes its script. Call before
// the headset is created. Returns the script it wrote (none with --sim-script): simxr reads it
// in xrCreateInstance, after which the caller removes it.
std::optional<std::filesystem::path> select_simulated_runtime(const HeadsetStudyOptions& options);

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
