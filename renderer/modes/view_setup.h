// What a mode needs to know about the viewer for one frame: the head pose and each eye's
// calibrated frustum (from an HMD profile or, later, from OpenXR's xrLocateViews).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/ext/matrix_double4x4.hpp>

#include "rig/pose.h"
#include "rig/rig.h"
#include "rig/tangents.h"

namespace monoplane::modes {

struct StereoViewInputs {
    rig::Pose head;
    double ipd = 0.064;
    rig::Tangents left;  // each in its eye's own frame
    rig::Tangents right;
    double near = 0.1;  // the paper's values (papers/000 Sect. 5.1)
    double far = 1000.0;
    // Canted displays: each eye's yaw about the head's +y axis, radians,
    // positive turning it left; [0] left, [1] right. Zero: parallel eyes.
    std::array<double, 2> cant = {0.0, 0.0};
};

enum class Eye { kLeft = 0, kRight = 1 };
inline const char* eye_name(Eye eye) {
    return eye == Eye::kLeft ? "left" : "right";
}

// The eye's position in the head frame: x = -ipd/2 (left) or +ipd/2 (right).
glm::dvec3 eye_offset(Eye eye, double ipd);
// View matrix (eye-from-world) of one eye: the head pose, the eye's offset, its cant.
glm::dmat4 eye_view(const StereoViewInputs& inputs, Eye eye);
// World -> clip (reversed Z, near..far) of one eye.
glm::dmat4 eye_view_proj(const StereoViewInputs& inputs, Eye eye);

// The rig's inputs for these eyes at an eye size in pixels (a mode's render targets): the
// frusta, ipd, clip range and cants. The mono plane, overlap and grazing angle keep RigInputs'
// defaults; the caller sets them for its frame.
rig::RigInputs rig_inputs_for(const StereoViewInputs& views, int eye_width, int eye_height);

// An 8-bit RGBA image read back from the GPU, rows top to bottom, sRGB-encoded.
struct RgbaImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> pixels;  // width * height * 4
};

}  // namespace monoplane::modes
