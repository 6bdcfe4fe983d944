// Where a gaze sample lands in the left eye's image as seen from the seat (docs/gaze.md, "The
// report's gaze section"): the report draws every scene's gaze over one picture, its left-eye
// view from the seat (the default viewpoint), so samples from a moving head are brought into that
// one view. The frame log gives the head relative to the seat and the gaze in the head's frame;
// the gaze point is where the ray from the head's centre meets the depth that the gaze met (at
// infinity for the sky), and the seat's left eye (x = -ipd/2, looking along -z) sees it through
// the HMD profile's left-eye tangents.
#pragma once

#include <optional>

#include "analysis/dataset.h"
#include "rig/eye_image.h"

namespace monoplane::analysis {

// The left eye at the seat: its offset from the head's centre and its frustum as tangents in
// OpenXR's convention (tan_left < 0 < tan_right, tan_down < 0 < tan_up; +y up). Defaults: the
// built-in "vive" profile's left eye (hmd/profiles/vive.toml); the app fills the session's.
struct SeatEye {
    double ipd = 0.064;  // metres; the left eye sits at x = -ipd / 2 in the head's frame
    double tan_left = -1.391937;
    double tan_right = 1.247409;
    double tan_down = -1.468819;
    double tan_up = 1.464287;
    // A canted display's yaw of the left eye about +y, radians, positive turning it left.
    double cant = 0.0;
};

// A point of the left eye's image (rig/eye_image.h).
using EyeImagePoint = rig::EyeImagePoint;

// The gaze point of `sample` in the seat's frame projected into `eye`. None when the point lies
// beside or behind the eye (a head turned away from the seat's view), or the gaze ray does not
// run forward (direction z >= 0 with a depth).
std::optional<EyeImagePoint> project_into_left_eye(const GazeSampleRow& sample, const SeatEye& eye);

}  // namespace monoplane::analysis
