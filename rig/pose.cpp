#include "rig/pose.h"

#include <glm/ext/matrix_transform.hpp>
#include <glm/ext/quaternion_trigonometric.hpp>
#include <glm/gtc/quaternion.hpp>

namespace monoplane::rig {

glm::dquat orientation_from_yaw_pitch(double yaw_rad, double pitch_rad) {
    const glm::dquat yaw = glm::angleAxis(yaw_rad, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dquat pitch = glm::angleAxis(pitch_rad, glm::dvec3(1.0, 0.0, 0.0));
    return yaw * pitch;
}

glm::dmat4 to_matrix(const Pose& pose) {
    glm::dmat4 m = glm::mat4_cast(pose.orientation);
    m[3] = glm::dvec4(pose.position, 1.0);
    return m;
}

glm::dmat4 view_matrix(const Pose& head, const glm::dvec3& offset_in_head) {
    const glm::dmat4 world_from_eye = glm::translate(to_matrix(head), offset_in_head);
    return glm::inverse(world_from_eye);
}

}  // namespace monoplane::rig
