// The eye depth writer's push constants (eye_depth_writer.h), declared once for C++ and GLSL
// (16-byte members only, so the C++ layout is the std430 one; the static_assert keeps it so).
#ifndef MONOPLANE_EYE_DEPTH_CONSTANTS_H
#define MONOPLANE_EYE_DEPTH_CONSTANTS_H

#ifdef __cplusplus
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
namespace monoplane::headset {
using mat4 = glm::mat4;
using vec4 = glm::vec4;
#endif

struct EyeDepthConstants {
    // Upper 3x3: the rotation taking a direction in the eye's frame to the head's (the inverse
    // of head -> eye); identity for parallel eyes.
    mat4 eye_to_head;
    vec4 tangents;  // the eye's frustum: x left, y right, z up, w down (tan of XrFovf's angles)
    // x: the encoding's near, metres (window depth 1; 0 is infinity); y: how far the eye lies
    // in front of the eyes' plane, metres (0 for eyes on the plane); zw: unused.
    vec4 encoding;
};

#ifdef __cplusplus
static_assert(sizeof(EyeDepthConstants) == 64 + 2 * 16, "layout shared with GLSL");
}  // namespace monoplane::headset
#endif

#endif
