#version 460
#extension GL_GOOGLE_include_directive : require
// Depth-only rendering of the scene from the sun (orthographic).
layout(location = 0) in vec3 in_position;
layout(push_constant) uniform Push { mat4 light_view_proj; };
void main() { gl_Position = light_view_proj * vec4(in_position, 1.0); }
