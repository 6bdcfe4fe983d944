// Projection matrices for asymmetric frusta given as tangents, in Vulkan clip space with
// reversed Z: view-space point (x, y, z), z < 0 forward;
// depth 1 at the near plane, 0 at the far plane; clip-space y points down.
#pragma once

#include <glm/ext/matrix_double4x4.hpp>

#include "rig/tangents.h"

namespace monoplane::rig {

// Requires left < right, down < up, 0 < near < far (validated by callers: HMD profiles and the
// rig check their inputs and return errors, so this only asserts).
glm::dmat4 projection_reversed_z(const Tangents& tangents, double near, double far);

}  // namespace monoplane::rig
