#include "analysis/gaze_projection.h"

#include <glm/ext/quaternion_double.hpp>
#include <glm/gtc/quaternion.hpp>

namespace monoplane::analysis {

std::optional<EyeImagePoint> project_into_left_eye(const GazeSampleRow& sample,
                                                   const SeatEye& eye) {
    const std::array<double, 7>& h = sample.head;
    // The log stores floats: the orientation is normalised before it turns anything.
    const glm::dquat orientation = glm::normalize(glm::dquat(h[3], h[4], h[5], h[6]));
    const glm::dvec3 d(sample.direction[0], sample.direction[1], sample.direction[2]);
    glm::dvec3 from_eye;  // the gaze point relative to the left eye, or its direction for the sky
    if (sample.depth_m) {
        // depth_m is measured along the head's -z, so the ray reaches it after depth / -d.z.
        if (!(d.z < 0.0)) return std::nullopt;
        const glm::dvec3 point =
            glm::dvec3(h[0], h[1], h[2]) + orientation * (d * (*sample.depth_m / -d.z));
        from_eye = point + glm::dvec3(eye.ipd / 2.0, 0.0, 0.0);
    } else {
        from_eye = orientation * d;  // at infinity: the eye's offset does not matter
    }
    return rig::eye_image_point(from_eye, eye.cant,
                                {eye.tan_left, eye.tan_right, eye.tan_down, eye.tan_up});
}

}  // namespace monoplane::analysis
