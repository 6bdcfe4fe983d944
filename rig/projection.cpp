#include "rig/projection.h"

#include "common/programming_error.h"

namespace monoplane::rig {

glm::dmat4 projection_reversed_z(const Tangents& t, double near, double far) {
    MONOPLANE_EXPECTS(t.left < t.right && t.down < t.up && 0.0 < near && near < far);
    // ndc_x = (2 tan_x - (r + l)) / (r - l) with tan_x = x / -z, so that tan_left -> -1.
    // ndc_y flips sign because Vulkan's y points down: tan_up -> -1.
    // depth = (n z / (f - n) + n f / (f - n)) / -z: 1 at z = -n, 0 at z = -f.
    glm::dmat4 p(0.0);  // glm is column-major: p[column][row]
    p[0][0] = 2.0 / (t.right - t.left);
    p[2][0] = (t.right + t.left) / (t.right - t.left);
    p[1][1] = -2.0 / (t.up - t.down);
    p[2][1] = -(t.up + t.down) / (t.up - t.down);
    p[2][2] = near / (far - near);
    p[3][2] = near * far / (far - near);
    p[2][3] = -1.0;
    return p;
}

}  // namespace monoplane::rig
