// Head and eye poses in the OpenXR view convention: right-handed, +x right, +y up, -z forward.
#pragma once

#include <glm/ext/matrix_double4x4.hpp>
#include <glm/ext/quaternion_double.hpp>
#include <glm/ext/vector_double3.hpp>

namespace monoplane::rig {

struct Pose {
    glm::dvec3 position{0.0};
    glm::dquat orientation{1.0, 0.0, 0.0, 0.0};  // w, x, y, z: identity looks down -z
};

// Orientation from yaw (about +y, positive turns left) then pitch (about +x, positive looks up).
glm::dquat orientation_from_yaw_pitch(double yaw_rad, double pitch_rad);

// World-from-local transform of a pose.
glm::dmat4 to_matrix(const Pose& pose);

// View matrix (local-from-world) of a camera displaced by offset_in_head (head frame) from the
// head pose: the eyes sit at (-ipd/2, 0, 0) and (+ipd/2, 0, 0).
glm::dmat4 view_matrix(const Pose& head, const glm::dvec3& offset_in_head);

}  // namespace monoplane::rig
