// What the launcher shows of the headset before a session (`monoplane lab`, docs/headsets.md):
// the OpenXR runtime the loader finds, its headset and the eye image size it recommends, learnt
// from an instance and a system alone (no Vulkan device, no session), or why there is none.
#pragma once

#include <optional>
#include <string>

#include "common/result.h"

namespace monoplane::headset {

class OpenXrHeadset;

// Whether the headset tracks the participant's gaze, as a protocol's [gaze] record needs:
// Tracked (the runtime offers XR_EXT_eye_gaze_interaction and its system supports it),
// NotTracked (the runtime offers the extension but this headset has no eye tracker, or it is
// off), NotOffered (the runtime has no eye gaze at all); Unknown before a runtime was asked.
enum class EyeGaze { Unknown, NotOffered, NotTracked, Tracked };
// "" (Unknown), "not offered", "not tracked", "tracked": the launcher's state and tests.
const char* eye_gaze_name(EyeGaze gaze);
// A sentence for the experimenter: what it means for a protocol that records gaze.
std::string eye_gaze_text(EyeGaze gaze);

// For a headset created with eye gaze asked for (OpenXrHeadset::create's eye_gaze).
EyeGaze eye_gaze_support(const OpenXrHeadset& headset);

struct HeadsetProbe {
    bool runtime_available = false;  // an OpenXR runtime with a headset monoplane can drive
    std::string runtime;             // the runtime's name and version, "Monado 21.0.0"
    std::string system;              // the headset's system name
    int width = 0, height = 0;       // recommended image size of each eye, pixels
    // Known only once a session runs (the headset check measures them): a probe leaves them
    // unset. refresh_hz 0: not known.
    double refresh_hz = 0.0;
    std::optional<double> ipd_m;
    std::string interaction_profile;  // "": none bound
    EyeGaze eye_gaze = EyeGaze::Unknown;
    // Why the runtime is not available and what to do (empty when it is).
    std::string message;
};

// The runtime the OpenXR loader selects now (XR_RUNTIME_JSON, else the machine's active
// runtime), probed through an instance that is destroyed before returning. No runtime, or a
// runtime without a headset or without Vulkan support, is a probe with runtime_available false
// and a message saying what to do and that the simulated headset remains available (so is a
// missing OpenXR validation layer when `validation` asks for it); an error only when that layer
// reported something. May be called any time no other XrInstance of this process is alive (runtimes
// allow one); it blocks for as long as the runtime takes to answer (milliseconds, or seconds
// while SteamVR starts).
Result<HeadsetProbe> probe_runtime(bool validation);

}  // namespace monoplane::headset
