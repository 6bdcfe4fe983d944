// Where the participant looks, in the image of the eye the experimenter window mirrors: the eye
// tracker's gaze direction (head space) through that eye's frustum. Pure, so that the geometry
// is unit-tested apart from the window.
#pragma once

#include <array>
#include <optional>

#include <glm/vec3.hpp>

#include "rig/tangents.h"

namespace monoplane::window {

// A point of an eye's image: u from its left edge (0) to its right edge (1), v from its top (0)
// to its bottom (1), as the mirror shows it.
using ImageUv = std::array<double, 2>;

// The point of an eye's image where the gaze `direction` appears: `direction` in the head's space
// (OpenXR's VIEW space: -z ahead, +y up, +x right), for an eye turned by `eye_cant_rad` about the
// head's +y (positive turning it left, as rig/pose.h's yaw) with the frustum `tangents` (in the
// eye's own, turned frame, as XrFovf). Outside 0..1 when the participant looks beyond this
// eye's field; none when the direction points beside or behind the eye.
//
// The gaze ray starts at the midpoint between the eyes, the eye sits ipd/2 to its side: to put
// the fixated point exactly into this eye's image one would need the depth the ray meets. The
// direction is taken as a point at infinity instead, which needs no depth and is what the
// experimenter needs: the parallax it ignores is atan(ipd/2 / distance), 0.6 degrees at 3 m and
// under 0.2 degrees beyond 10 m (about a pixel of the mirror or less); in the left eye's image a
// near fixated point lies that much to the right of the marker.
std::optional<ImageUv> gaze_in_eye_image(const glm::dvec3& direction, double eye_cant_rad,
                                         const rig::Tangents& tangents);

}  // namespace monoplane::window
