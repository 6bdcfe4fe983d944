#include "renderer/modes/view_setup.h"

#include <glm/ext/matrix_transform.hpp>

#include "rig/projection.h"

namespace monoplane::modes {

glm::dvec3 eye_offset(Eye eye, double ipd) {
    return {eye == Eye::kLeft ? -0.5 * ipd : 0.5 * ipd, 0.0, 0.0};
}

glm::dmat4 eye_view(const StereoViewInputs& inputs, Eye eye) {
    const glm::dmat4 parallel = rig::view_matrix(inputs.head, eye_offset(eye, inputs.ipd));
    const double cant = inputs.cant[static_cast<int>(eye)];
    if (cant == 0.0) return parallel;
    // The eye turned by R_y(cant) in the head frame: eye-from-world = R_y(cant)^T parallel.
    return glm::rotate(glm::dmat4(1.0), -cant, glm::dvec3(0.0, 1.0, 0.0)) * parallel;
}

glm::dmat4 eye_view_proj(const StereoViewInputs& inputs, Eye eye) {
    const rig::Tangents& tangents = eye == Eye::kLeft ? inputs.left : inputs.right;
    return rig::projection_reversed_z(tangents, inputs.near, inputs.far) * eye_view(inputs, eye);
}

rig::RigInputs rig_inputs_for(const StereoViewInputs& views, int eye_width, int eye_height) {
    rig::RigInputs in;
    in.eyes = {views.left, views.right};
    in.eye_width = eye_width;
    in.eye_height = eye_height;
    in.ipd = views.ipd;
    in.near = views.near;
    in.far = views.far;
    in.cant = views.cant;
    return in;
}

}  // namespace monoplane::modes
