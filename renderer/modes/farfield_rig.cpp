#include "renderer/modes/farfield_rig.h"

#include <algorithm>
#include <cmath>

#include "rig/projection.h"

namespace monoplane::modes {

FarfieldRig build_farfield_rig(const std::array<rig::Tangents, 2>& eyes, int eye_width,
                               int eye_height, double ipd, double mono_plane, double far) {
    FarfieldRig r;
    const rig::Tangents& l = eyes[0];
    const rig::Tangents& rt = eyes[1];
    r.tangents = {std::min(l.left, rt.left), std::max(l.right, rt.right), std::min(l.down, rt.down),
                  std::max(l.up, rt.up)};
    // The left eye's pixel density (pixels per tangent); an engine assumes both eyes share it.
    const double density_x = eye_width / (l.right - l.left);
    const double density_y = eye_height / (l.up - l.down);
    r.width = static_cast<int>(std::ceil((r.tangents.right - r.tangents.left) * density_x));
    r.height = static_cast<int>(std::ceil((r.tangents.up - r.tangents.down) * density_y));
    r.projection = rig::projection_reversed_z(r.tangents, mono_plane, far);
    for (int e = 0; e < 2; ++e) {
        const double eye_x = (e == 0 ? -0.5 : 0.5) * ipd;
        // A point on the mono plane seen at eye tangent t lies at x = eye_x + t m, which C sees
        // at tangent t + eye_x / m: the same pixel shifted by a constant, here rounded.
        const double shift_x = (eyes[e].left - r.tangents.left + eye_x / mono_plane) * density_x;
        const double shift_y = (r.tangents.up - eyes[e].up) * density_y;
        r.offsets[e] = {static_cast<int>(std::lround(shift_x)),
                        static_cast<int>(std::lround(shift_y))};
    }
    return r;
}

}  // namespace monoplane::modes
