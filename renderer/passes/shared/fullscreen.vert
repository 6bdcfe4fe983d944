#version 460
#extension GL_GOOGLE_include_directive : require
// One triangle covering the viewport, at reversed-Z depth 0 (the far plane), with uv in [0, 1].
layout(location = 0) out vec2 out_uv;
void main() {
    vec2 uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    out_uv = uv;
    gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
}
