#include "app/window/gaze_marker.h"

#include <cmath>

namespace monoplane::window {

std::optional<ImageUv> gaze_in_eye_image(const glm::dvec3& direction, double eye_cant_rad,
                                         const rig::Tangents& tangents) {
    // Into the eye's frame: the inverse of its turn, a rotation by -cant about +y.
    const double c = std::cos(eye_cant_rad);
    const double s = std::sin(eye_cant_rad);
    const double x = c * direction.x - s * direction.z;
    const double y = direction.y;
    const double ahead = -(s * direction.x + c * direction.z);
    // Beside or behind the eye the direction meets no point of its image plane; near it, the
    // tangents grow without bound (1e-6: a tangent of a million).
    if (ahead <= 1e-6 * std::sqrt(x * x + y * y + ahead * ahead)) return std::nullopt;
    const double tan_x = x / ahead;
    const double tan_y = y / ahead;
    return ImageUv{(tan_x - tangents.left) / (tangents.right - tangents.left),
                   (tangents.up - tan_y) / (tangents.up - tangents.down)};
}

}  // namespace monoplane::window
