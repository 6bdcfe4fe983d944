// Where a direction appears in an eye's image: through the eye's canted frame and its asymmetric
// frustum (rig/tangents.h). Shared by the experimenter window's gaze marker and the report's gaze
// density, which both place a gaze in an eye's image. When may this be called: any time; pure.
#pragma once

#include <optional>

#include <glm/ext/vector_double3.hpp>

#include "rig/tangents.h"

namespace monoplane::rig {

// A point of an eye's image: the tangents of its direction in the eye's own frame (+x right, +y
// up), and where they fall as a fraction of the image, u from the left edge and v from the top
// (0..1 inside; outside beyond the eye's field).
struct EyeImagePoint {
    double tan_x = 0.0;
    double tan_y = 0.0;
    double u = 0.0;
    double v = 0.0;
    bool inside() const { return u >= 0.0 && u < 1.0 && v >= 0.0 && v < 1.0; }
};

// `direction`: in the head's frame (-z ahead), from the eye to the point, or the point's direction
// when it lies at infinity. `cant`: the eye's yaw about the head's +y, radians, positive turning
// it left (RigInputs::cant). `tangents`: the eye's frustum in its own frame. None for a direction
// beside or behind the eye, where it meets no point of the image plane (within 1e-6 of it: a
// tangent of a million).
std::optional<EyeImagePoint> eye_image_point(const glm::dvec3& direction, double cant,
                                             const Tangents& tangents);

}  // namespace monoplane::rig
