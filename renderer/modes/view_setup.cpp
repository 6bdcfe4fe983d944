#include "renderer/modes/view_setup.h"

#include "renderer/rig/projection.h"

namespace monoplane::modes {

glm::dvec3 eye_offset(Eye eye, double ipd) {
    return {eye == Eye::kLeft ? -0.5 * ipd : 0.5 * ipd, 0.0, 0.0};
}

glm::dmat4 eye_view_proj(const StereoViewInputs& inputs, Eye eye) {
    const rig::Tangents& tangents = eye == Eye::kLeft ? inputs.left : inputs.right;
    return rig::projection_reversed_z(tangents, inputs.near, inputs.far) *
           rig::view_matrix(inputs.head, eye_offset(eye, inputs.ipd));
}

}  // namespace monoplane::modes
