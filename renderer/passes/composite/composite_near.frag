#version 460
#extension GL_GOOGLE_include_directive : require
// The second draw of the composite that writes the display image: where the eye drew near
// content (its depth is not the cleared far value) the eye's own HDR colour, tone mapped as
// tonemap.frag would, so that every pixel of the display image is written once in one pass.
#include "renderer/passes/composite/composite_push.glsl"
#include "renderer/passes/tonemap/tone_mapping.glsl"

layout(set = 1, binding = 0) uniform sampler2D eye_hdr;  // read texel-exact

layout(location = 0) out vec4 out_color;

void main() {
    // The pixel centre's floor is the texel tonemap.frag reads.
    vec3 color = texelFetch(eye_hdr, ivec2(gl_FragCoord.xy), 0).rgb;
    out_color = vec4(monoplane_tone_map(color, offset_exposure.z), 1.0);
}
