#version 460
#extension GL_GOOGLE_include_directive : require
// HDR -> display: exposure, then the ACES filmic fit of Narkowicz (2015); the sRGB attachment
// applies the transfer function on store.
layout(set = 0, binding = 0) uniform sampler2D hdr;
layout(push_constant) uniform Push { float exposure; };
layout(location = 0) in vec2 in_uv;
layout(location = 0) out vec4 out_color;

vec3 aces(vec3 x) {
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
    // uv * size is the pixel centre (i + 0.5): its floor is the texel, read exactly.
    ivec2 texel = ivec2(in_uv * vec2(textureSize(hdr, 0)));
    vec3 color = texelFetch(hdr, texel, 0).rgb;
    out_color = vec4(aces(color * exposure), 1.0);
}
