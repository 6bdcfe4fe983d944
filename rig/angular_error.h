// Hybrid's error in visual angle (issue 20, docs/hybrid.md): pixels are the wrong unit
// across headsets (4 px on a Vive is not 4 px on a Vive Pro), arcminutes are what perception
// thresholds are stated in. Pure double-precision math over a built rig; no Vulkan.
//
// Symbols (head frame as in rig.h; t a horizontal tangent in an eye's own frame):
//   z        depth of a point, metres in front of the eyes' plane (z > m: hybrid maps it)
//   s, m, d  as in rig.h (C's offset behind the eyes, the mono plane, the IPD)
//   a, b     for parallel eyes the tangent hybrid shows for true tangent t is the line a t + b,
//            a = z (m + s) / (m (z + s)), b = x_e (m - z) / (m (z + s)) (x_e: the eye's x), the
//            central projection from C onto the plane (Fig. 2, centre right) seen by the eye;
//            at z = infinity a = 1 + s/m, b = -x_e/m.
#pragma once

#include <algorithm>
#include <array>

#include "rig/rig.h"

namespace monoplane::rig {

struct AngularError {
    // Per eye: the largest |atan(shown t) - atan(true t)| over the eye's field (both eyes'
    // larger), the angular counterpart of PixelError::horizontal_px.
    double eye_arcmin = 0.0;
    // The largest change of horizontal binocular disparity (the left eye's horizontal angle of a
    // point minus the right's) over the directions both eyes see: hybrid puts every point
    // beyond m on the plane, so at infinity it shows the plane's disparity, about d/m.
    double disparity_arcmin = 0.0;
};

// The errors of points at `depth` (may be +infinity, the supremum over depth). Zero for
// depth <= m and for a skipped C. Parallel eyes: the per-eye error in closed form (the maximum
// of atan(a t + b) - atan(t) over t is at an end of the field or at a root of
// (a - a^2) t^2 - 2 a b t + (a - 1 - b^2) = 0); the disparity by a dense search along the
// directions both eyes see, refined by golden sections. Canted eyes: a 33 x 33 grid of each
// field refined by a shrinking compass search (no closed form is at hand). Any time; pure.
AngularError angular_error_at_depth(const Rig& rig, double depth);

// angular_error_at_depth(rig, +infinity).
AngularError max_angular_error(const Rig& rig);

// Hybrid's error at one point, as each eye sees it (docs/gaze.md, the error where the gaze
// rests): the angle between eye e's direction to the point (what stereo shows) and its direction
// to the point's central projection from C onto the mono plane z = -m (what hybrid shows: Fig. 2,
// centre right; the plane-induced mapping of eq. 5), in arcmin. Exact for parallel and canted
// eyes; vertical offsets count, unlike AngularError::eye_arcmin's horizontal tangents.
struct PointAngularError {
    std::array<double, 2> eye_arcmin = {0.0, 0.0};  // [kLeft], [kRight]
    double larger_arcmin() const { return std::max(eye_arcmin[0], eye_arcmin[1]); }
};

// `point` in the head frame. Zero for a point no deeper than the plane (-point.z <= m: stereo
// content in hybrid too) and for a skipped C. Any time; pure.
PointAngularError angular_error_at_point(const Rig& rig, const glm::dvec3& point);

// The same for a point infinitely far along `direction` (head frame, any length, pointing ahead:
// direction.z < 0), such as the sky: both eyes see it along `direction` in stereo. Zero for a
// skipped C; a direction not ahead is a programming error.
PointAngularError angular_error_in_direction(const Rig& rig, const glm::dvec3& direction);

// Arcminutes in a radian (60 * 180 / pi).
inline constexpr double kArcminPerRadian = 3437.7467707849392;

}  // namespace monoplane::rig
