#version 460
#extension GL_GOOGLE_include_directive : require
// Single-pass stereo after de Sorbier et al. 2008 (papers/001, Sect. 4.1): the vertex shader
// processed each vertex once; here every triangle is emitted twice, projected with each eye's
// matrix into that eye's layer of a layered target. Each layer has its own depth buffer, so the
// depth test works as in two passes and the paper's painter's-algorithm workaround (Sect. 4.2,
// for one depth buffer shared by both images) is not needed.
// Variants: MONOPLANE_SHOW_ROUTING passes the chunk index on; MONOPLANE_SKY duplicates the
// sky's full-screen triangle, which is already in clip space.
#define MONOPLANE_STEREO_GS
#include "renderer/passes/shared/view_block.glsl"

layout(triangles) in;
layout(triangle_strip, max_vertices = 6) out;

layout(location = 5) flat out int out_view;  // the eye (and layer) of the emitted copy

#ifdef MONOPLANE_SKY
layout(location = 0) in vec2 in_uv[];
layout(location = 0) out vec2 out_uv;

void main() {
    for (int eye = 0; eye < 2; ++eye) {
        for (int i = 0; i < 3; ++i) {
            gl_Position = gl_in[i].gl_Position;
            gl_Layer = eye;
            out_uv = in_uv[i];
            out_view = eye;
            EmitVertex();
        }
        EndPrimitive();
    }
}
#else
layout(location = 0) in vec3 in_world[];
layout(location = 1) in vec3 in_normal[];
layout(location = 2) in vec4 in_albedo[];
layout(location = 3) in uint in_material[];
layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec4 out_albedo;
layout(location = 3) flat out uint out_material;
#ifdef MONOPLANE_SHOW_ROUTING
layout(location = 4) in uint in_chunk[];
layout(location = 4) flat out uint out_chunk;
#endif
layout(location = 6) in vec2 in_uv[];
layout(location = 7) in uvec4 in_texture[];
layout(location = 6) out vec2 out_uv;
layout(location = 7) flat out uvec4 out_texture;
layout(location = 8) in float in_alpha_cutoff[];
layout(location = 8) flat out float out_alpha_cutoff;

// Whether all three vertices lie beyond one clip plane (reversed Z: 0 <= z <= w inside): the
// rasteriser would draw nothing of the copy, so it is not emitted. Chunks are culled against the
// union of the eyes' frusta, so many triangles are visible in one eye only.
bool outside_one_plane(vec4 a, vec4 b, vec4 c) {
    return (a.x > a.w && b.x > b.w && c.x > c.w) || (a.x < -a.w && b.x < -b.w && c.x < -c.w) ||
           (a.y > a.w && b.y > b.w && c.y > c.w) || (a.y < -a.w && b.y < -b.w && c.y < -c.w) ||
           (a.z > a.w && b.z > b.w && c.z > c.w) || (a.z < 0.0 && b.z < 0.0 && c.z < 0.0);
}

void main() {
    for (int eye = 0; eye < 2; ++eye) {
        // precise, as in forward_vertex.glsl: the same rounding as two-pass stereo's.
        precise vec4 clip[3];
        for (int i = 0; i < 3; ++i) clip[i] = views[eye].view_proj * vec4(in_world[i], 1.0);
        if (outside_one_plane(clip[0], clip[1], clip[2])) continue;
        for (int i = 0; i < 3; ++i) {
            gl_Position = clip[i];
            gl_Layer = eye;
            out_world = in_world[i];
            out_normal = in_normal[i];
            out_albedo = in_albedo[i];
            out_material = in_material[i];
            out_uv = in_uv[i];
            out_texture = in_texture[i];
            out_alpha_cutoff = in_alpha_cutoff[i];
#ifdef MONOPLANE_SHOW_ROUTING
            out_chunk = in_chunk[i];
#endif
            out_view = eye;
            EmitVertex();
        }
        EndPrimitive();
    }
}
#endif
