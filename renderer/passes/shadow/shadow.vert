#version 460
#extension GL_GOOGLE_include_directive : require
// Depth-only rendering of the scene from the sun (orthographic). MONOPLANE_ALPHA_TEST: the
// variant for alphaMode MASK chunks, which hands alpha_test.frag what it needs, so cut-outs cast
// cut-out shadows (the draw's first instance is its chunk, as in the forward pass).
layout(location = 0) in vec3 in_position;
layout(push_constant) uniform Push { mat4 light_view_proj; };
#ifdef MONOPLANE_ALPHA_TEST
layout(location = 2) in vec4 in_albedo;
#define MONOPLANE_SCENE_TEXTURES_VERTEX
#include "renderer/passes/shared/scene_textures.glsl"
layout(location = 2) out vec4 out_albedo;
layout(location = 6) out vec2 out_uv;
layout(location = 7) flat out uvec4 out_texture;
layout(location = 8) flat out float out_alpha_cutoff;
#endif

void main() {
    gl_Position = light_view_proj * vec4(in_position, 1.0);
#ifdef MONOPLANE_ALPHA_TEST
    out_albedo = in_albedo;
    fetch_texture(out_texture, out_uv);
    out_alpha_cutoff = fetch_alpha_cutoff();
#endif
}
