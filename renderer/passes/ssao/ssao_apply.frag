#version 460
// hdr *= AO: the pipeline blends the output into the target as dst * src (colour) and keeps the
// target's alpha.
layout(set = 0, binding = 0) uniform sampler2D ao;
layout(push_constant) uniform Push { vec2 area; };
layout(location = 0) in vec2 in_uv;  // pixel centre / area
layout(location = 0) out vec4 out_factor;

void main() {
    float a = texelFetch(ao, ivec2(in_uv * area), 0).r;
    out_factor = vec4(a, a, a, 1.0);
}
