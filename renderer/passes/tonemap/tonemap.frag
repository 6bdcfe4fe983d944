#version 460
#extension GL_GOOGLE_include_directive : require
// HDR -> display (renderer/passes/tonemap/tone_mapping.glsl).
#include "renderer/passes/tonemap/tone_mapping.glsl"

layout(set = 0, binding = 0) uniform sampler2D hdr;
layout(push_constant) uniform Push { float exposure; };
layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

void main() {
    // uv * size is the pixel centre (i + 0.5): its floor is the texel, read exactly.
    ivec2 texel = ivec2(in_uv * vec2(textureSize(hdr, 0)));
    vec3 color = texelFetch(hdr, texel, 0).rgb;
    out_color = vec4(monoplane_tone_map(color, exposure), 1.0);
}
