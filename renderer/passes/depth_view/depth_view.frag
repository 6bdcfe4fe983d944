#version 460
#extension GL_GOOGLE_include_directive : require
// The depth debug view (depth_view_unit.cpp): each pixel's linear depth d, in metres, shown as a
// brightness falling with log10 d from 1 m (bright) to 1000 m (dark), warm where the content lies
// nearer than the mono plane m and cool at or beyond it (drawn by C in hybrid); black for the
// sky. Stereo, and hybrid frames that draw no C, pass m = MONOPLANE_SKY_LINEAR_DEPTH: everything
// is near.
#include "renderer/passes/shared/view_constants.h"

layout(set = 0, binding = 0) uniform sampler2D linear_depth;
layout(push_constant) uniform Push { float mono_plane; };
layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

void main() {
    // uv * size is the pixel centre (i + 0.5): its floor is the texel, read exactly.
    ivec2 texel = ivec2(in_uv * vec2(textureSize(linear_depth, 0)));
    float d = texelFetch(linear_depth, texel, 0).r;
    // The sky, as the SSAO and the depth histogram tell it (ssao_common.glsl).
    if (d >= 0.5 * MONOPLANE_SKY_LINEAR_DEPTH) {
        out_color = vec4(0.0, 0.0, 0.0, 1.0);
        return;
    }
    float t = clamp(log(max(d, 1.0e-6)) / log(1000.0), 0.0, 1.0);
    float g = 1.0 - 0.75 * t;
    vec3 hue = d < mono_plane ? vec3(1.0, 0.85, 0.6) : vec3(0.6, 0.8, 1.0);
    out_color = vec4(g * hue, 1.0);
}
