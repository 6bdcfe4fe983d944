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

// Arcminutes in a radian (60 * 180 / pi).
inline constexpr double kArcminPerRadian = 3437.7467707849392;

}  // namespace monoplane::rig
