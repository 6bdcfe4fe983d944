// Per-view constants, declared once for C++ and GLSL (std140: every member is 16-byte aligned,
// so the C++ layout is identical; static_assert below keeps it that way).
#ifndef MONOPLANE_VIEW_CONSTANTS_H
#define MONOPLANE_VIEW_CONSTANTS_H

#ifdef __cplusplus
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
namespace monoplane::passes {
using mat4 = glm::mat4;
using vec4 = glm::vec4;
#endif

struct ViewConstants {
    mat4 view_proj;             // world -> this view's clip space (reversed Z)
    mat4 inv_view_proj;         // clip -> world, for sky rays
    mat4 light_view_proj;       // world -> shadow-map clip space
    vec4 camera_position;       // xyz: this view's eye position in the world
    vec4 sun_direction;         // xyz: unit vector towards the sun
    vec4 sun_radiance;          // rgb
    vec4 sky_zenith;            // rgb
    vec4 sky_horizon;           // rgb
    vec4 ground_albedo;         // rgb: seen below the horizon in reflections
    vec4 shadow_params;         // x: shadow texel size in uv, y: depth bias in light-depth units
    vec4 head_position;         // xyz: the head (centre of the eyes' plane), for linear depth
    vec4 head_forward;          // xyz: unit view direction shared by all cameras of the rig
    vec4 mono_camera_position;  // xyz: C, towards which the eyes' view vectors blend near m
    // x: m; y: width of the band below m over which an eye's view vector blends into C's
    // (Fink et al. Sect. 4.3; 0 disables it: stereo and C's own pass); z (C with the merged
    // depth pyramid): the eyes' reversed-Z depth of m - eps, above which C's fragment is hidden
    // in both eyes; w: unused.
    vec4 view_blend;
    // Screen-space velocity for TAA (Karis 2014; Fink et al. Sect. 4.5): world -> clip of this
    // view in this frame and in the previous one, both without the sub-pixel jitter that
    // view_proj carries, so a static scene seen from a static head has zero velocity.
    mat4 velocity_view_proj;
    mat4 prev_view_proj;
};

// Linear depth written for the sky: "nothing here" for later passes and tests.
#define MONOPLANE_SKY_LINEAR_DEPTH 1.0e30

#ifdef __cplusplus
static_assert(sizeof(ViewConstants) == 5 * 64 + 11 * 16, "std140 layout shared with GLSL");
}  // namespace monoplane::passes
#endif

#endif
