#version 460
#extension GL_GOOGLE_include_directive : require
// The sky behind the geometry: drawn after it where the depth buffer still holds the far plane.
#include "renderer/passes/shared/view_constants.h"
layout(std140, set = 0, binding = 0) uniform ViewBlock { ViewConstants view; };
#include "renderer/passes/shared/sky.glsl"

layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;
layout(location = 1) out float out_linear_depth;

void main() {
    vec2 ndc = in_uv * 2.0 - 1.0;
    vec4 near_point = view.inv_view_proj * vec4(ndc, 1.0, 1.0);
    vec4 far_point = view.inv_view_proj * vec4(ndc, 0.5, 1.0);
    vec3 direction = far_point.xyz / far_point.w - near_point.xyz / near_point.w;
    out_color = vec4(sky_radiance(direction, view), 1.0);
    out_linear_depth = MONOPLANE_SKY_LINEAR_DEPTH;
}
