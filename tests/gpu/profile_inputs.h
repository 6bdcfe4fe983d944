// A frame's inputs for an HMD profile seen from a head pose: what most GPU tests render.
#pragma once

#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "rig/pose.h"

namespace monoplane::testing {

// The profile's eyes (tangents, cant) and IPD at `head`, with mono plane m (hybrid modes).
inline modes::FrameInputs profile_inputs(const hmd::HmdProfile& profile, const rig::Pose& head,
                                         double m = 8.0) {
    modes::FrameInputs inputs;
    inputs.views.head = head;
    inputs.views.ipd = profile.ipd;
    inputs.views.left = profile.left;
    inputs.views.right = profile.right;
    inputs.views.cant = hmd::cant_radians(profile);
    inputs.mono_plane = m;
    return inputs;
}

}  // namespace monoplane::testing
