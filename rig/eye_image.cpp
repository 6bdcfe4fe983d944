#include "rig/eye_image.h"

#include <cmath>

namespace monoplane::rig {

std::optional<EyeImagePoint> eye_image_point(const glm::dvec3& direction, double cant,
                                             const Tangents& tangents) {
    // Into the eye's frame: the inverse of its turn, a rotation by -cant about +y.
    const double c = std::cos(cant);
    const double s = std::sin(cant);
    const double x = c * direction.x - s * direction.z;
    const double y = direction.y;
    const double ahead = -(s * direction.x + c * direction.z);
    if (ahead <= 1e-6 * std::sqrt(x * x + y * y + ahead * ahead)) return std::nullopt;
    EyeImagePoint p;
    p.tan_x = x / ahead;
    p.tan_y = y / ahead;
    p.u = (p.tan_x - tangents.left) / (tangents.right - tangents.left);
    p.v = (tangents.up - p.tan_y) / (tangents.up - tangents.down);
    return p;
}

}  // namespace monoplane::rig
