// The body of forward.vert and forward_show_routing.vert (compiled twice, and again for
// single-pass stereo: MONOPLANE_STEREO_MULTIVIEW projects into the view gl_ViewIndex names;
// MONOPLANE_STEREO_GS projects nothing, stereo_duplicate.geom does it once per eye;
// MONOPLANE_STEREO_INSTANCED runs once per vertex and eye, the eye being the instance within the
// draw, and sends the vertex to that eye's layer).
#ifdef MONOPLANE_STEREO_GS
#define MONOPLANE_VIEW_INDEX 0  // the eyes share everything this stage reads
#endif
#ifdef MONOPLANE_STEREO_INSTANCED
#extension GL_ARB_shader_viewport_layer_array : require
// The culling pass draws each chunk of the both-eyes list with two instances from the chunk's
// index (CullFrame::both_eyes_instances): instance 0 is the left eye, 1 the right.
#define MONOPLANE_VIEW_INDEX (gl_InstanceIndex - gl_BaseInstance)
#endif
#include "renderer/passes/shared/view_block.glsl"
#include "renderer/passes/shared/scene_vertex.glsl"
#define MONOPLANE_SCENE_TEXTURES_VERTEX
#include "renderer/passes/shared/scene_textures.glsl"

layout(location = 0) out vec3 out_world;
layout(location = 1) out vec3 out_normal;
layout(location = 2) out vec4 out_albedo;  // rgb, and alpha (scenes::AlphaMode)
layout(location = 3) flat out uint out_material;
#ifdef MONOPLANE_SHOW_ROUTING
layout(location = 4) flat out uint out_chunk;  // the draw's first instance: its chunk index
#endif
#ifdef MONOPLANE_STEREO_INSTANCED
layout(location = 5) flat out int out_view;  // the eye and layer, as stereo_duplicate.geom's
#endif
layout(location = 6) out vec2 out_uv;             // base-colour texture coordinate
layout(location = 7) flat out uvec4 out_texture;  // its slot (scene_textures.glsl)
layout(location = 8) flat out float out_alpha_cutoff;  // the chunk's (alphaMode MASK)

// The benchmark's vertex-heavy configuration (papers/001 Table 1: single-pass stereo gains most
// where vertices cost most): rounds of dependent per-vertex arithmetic, as skinning or procedural
// animation would cost. 0 (the default) compiles it out. The result is added times
// view.view_blend.w, which is always 0: the work cannot be skipped, the image does not change.
layout(constant_id = 0) const int kVertexWork = 0;

vec3 vertex_work(vec3 p) {
    vec3 sum = vec3(0.0);
    for (int i = 0; i < kVertexWork; ++i) sum += sin(p * float(i + 1) + sum.zxy);
    return sum;
}

void main() {
    vec3 world = in_position;
    if (kVertexWork > 0) world += view.view_blend.w * vertex_work(in_position);
    out_world = world;
    out_normal = in_normal;
    out_albedo = in_albedo;
    out_alpha_cutoff = fetch_alpha_cutoff();
    out_material = in_material;
    fetch_texture(out_texture, out_uv);
#ifdef MONOPLANE_SHOW_ROUTING
    out_chunk = uint(MONOPLANE_DRAWN_CHUNK);  // scene_textures.glsl
#endif
#ifdef MONOPLANE_STEREO_INSTANCED
    out_view = MONOPLANE_VIEW_INDEX;
    gl_Layer = MONOPLANE_VIEW_INDEX;
#endif
#ifndef MONOPLANE_STEREO_GS
    // precise (no fused multiply-add): stereo_duplicate.geom computes the same product and must
    // round it the same way, or a pixel on a triangle's edge may be covered in one form only. The
    // depth pre-pass (ForwardStep::kDepthPrepass) relies on it too: its pipeline and the shading
    // pipeline after it run this code and compare depths for equality. (`invariant gl_Position`
    // would say so in GLSL, but Mesa 22.3's SPIR-V reader warns on the decoration it produces.)
    precise vec4 clip = view.view_proj * vec4(world, 1.0);
    gl_Position = clip;
#endif
}
