#include "app/window/gaze_marker.h"

#include "rig/eye_image.h"

namespace monoplane::window {

std::optional<ImageUv> gaze_in_eye_image(const glm::dvec3& direction, double eye_cant_rad,
                                         const rig::Tangents& tangents) {
    const std::optional<rig::EyeImagePoint> p =
        rig::eye_image_point(direction, eye_cant_rad, tangents);
    if (!p) return std::nullopt;
    return ImageUv{p->u, p->v};
}

}  // namespace monoplane::window
