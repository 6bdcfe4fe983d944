// HMD profiles: a headset's per-eye frusta, per-eye render-target size and
// default IPD, read from TOML. Built-ins (vive, vive-pro, symmetric-90, symmetric-110, canted-15)
// are compiled in from hmd/profiles/; a file path is accepted anywhere a built-in name is.
//
// Tangent convention: OpenXR's XrFovf angles through tan, +y up, so
// tan_left < 0 < tan_right and tan_down < 0 < tan_up. OpenVR's GetProjectionRaw reports top and
// bottom in a y-down frame; the values Fink et al. 2019 quote for the Vive (t = -1.464287,
// b = 1.468819 for the left eye) are GetProjectionRaw's, so a profile stores tan_up = -t and
// tan_down = -b.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "rig/rig.h"
#include "rig/tangents.h"

namespace monoplane::hmd {

struct HmdProfile {
    std::string name;  // human-readable, the file's `name`
    double ipd = 0.0;  // metres: this headset's default, overridden by --ipd
    int width = 0;     // per-eye render target, pixels
    int height = 0;
    rig::Tangents left;  // in the left eye's own frame (turned by cant_deg[0] when canted)
    rig::Tangents right;
    // Canted displays: each eye's yaw about the head's +y axis, degrees, positive turning it
    // left ([rig::kLeft], [rig::kRight]); a canted headset has cant_deg[0] > 0 > cant_deg[1].
    std::array<double, 2> cant_deg = {0.0, 0.0};
    std::string source;  // "built-in vive" or the file path it was loaded from
};

// Parses and validates a profile's TOML text. Errors name source_name, the line and column where
// known, and the offending key (e.g. `left.tan_right`); all problems found are reported, one per
// line. May be called at any time; touches no file.
Result<HmdProfile> parse_hmd_profile(std::string_view toml_text, std::string_view source_name);

// A built-in name ("vive", ...) or else a path to a TOML file. Built-in names win over files of
// the same name in the working directory (pass "./vive" for the file). An unknown name that is no
// existing file gives an error listing the built-in names.
Result<HmdProfile> load_hmd_profile(std::string_view name_or_path);

// The rig's inputs for this headset at mono plane m: its frusta, per-eye size and default IPD;
// near, far, k and the allocation keep the rig's defaults for the caller to override.
rig::RigInputs rig_inputs(const HmdProfile& profile, double mono_plane);

// cant_deg in radians, as the rig and the renderer's views take it.
std::array<double, 2> cant_radians(const HmdProfile& profile);

// The built-in profile names, in the order they should be shown to users.
std::vector<std::string> builtin_hmd_names();

}  // namespace monoplane::hmd
