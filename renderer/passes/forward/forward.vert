#version 460
#extension GL_GOOGLE_include_directive : require
#include "renderer/passes/shared/view_constants.h"
#include "renderer/passes/shared/scene_vertex.glsl"

layout(std140, set = 0, binding = 0) uniform ViewBlock { ViewConstants view; };

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec3 out_albedo;
layout(location = 3) flat out uint out_material;

void main() {
    out_world = in_position;
    out_normal = in_normal;
    out_albedo = in_albedo.rgb;
    out_material = in_material;
    gl_Position = view.view_proj * vec4(in_position, 1.0);
}
