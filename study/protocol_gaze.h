// Eye gaze in the frame log (docs/protocols.md, "[gaze]"; docs/gaze.md): whether a headset
// session records, per displayed frame, where the participant looked. Gaze is personal data: it
// is recorded only when the protocol asks, and only where the runtime offers
// XR_EXT_eye_gaze_interaction and its system tracks the eyes (the session says so otherwise).
#pragma once

#include <string>

#include "common/toml/toml_keys.h"

namespace monoplane::study {

struct GazeSettings {
    bool record = false;
    bool operator==(const GazeSettings&) const = default;
};

// The protocol's [gaze] table, if any: `record = true|false`.
void read_gaze(const TomlScope& root, GazeSettings& gaze, TomlProblems& problems);

// What `protocol check` says of it: off, or what recording needs of the runtime.
std::string describe_gaze(const GazeSettings& gaze);

}  // namespace monoplane::study
