// A view frustum as four tangents (OpenXR XrFovf angles through tan):
// tan_left < 0 < tan_right and tan_down < 0 < tan_up for a normal headset.
#pragma once

namespace monoplane::rig {

struct Tangents {
    double left = -1.0;
    double right = 1.0;
    double down = -1.0;
    double up = 1.0;
    bool operator==(const Tangents&) const = default;
};

}  // namespace monoplane::rig
