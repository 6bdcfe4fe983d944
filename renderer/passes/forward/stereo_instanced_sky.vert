#version 460
#extension GL_ARB_shader_viewport_layer_array : require
// The sky's full-screen triangle (shared/fullscreen.vert) for instanced stereo: drawn with two
// instances from instance 0, so the instance is the eye, and each copy goes to its eye's layer.
layout(location = 0) out vec2 out_uv;
layout(location = 5) flat out int out_view;  // read by sky_shading.glsl as in_view
void main() {
    vec2 uv = vec2((gl_VertexIndex << 1) & 2, gl_VertexIndex & 2);
    out_uv = uv;
    gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
    out_view = gl_InstanceIndex;
    gl_Layer = gl_InstanceIndex;
}
