// Set 2: an imported scene's base-colour textures (renderer/passes/shared/scene_textures.h).
// The vertex stage defines MONOPLANE_SCENE_TEXTURES_VERTEX before including this, the fragment
// stage MONOPLANE_SCENE_TEXTURES_FRAGMENT.
#include "renderer/passes/shared/scene_texture_constants.h"

#ifdef MONOPLANE_SCENE_TEXTURES_VERTEX
layout(std430, set = 2, binding = 0) readonly buffer Texcoords { vec2 texcoords[]; };
// Per chunk: x its texture (-1: none), y its alpha cut-off (float bits; scenes::Chunk).
layout(std430, set = 2, binding = 1) readonly buffer ChunkSurfaces { ivec2 chunk_surface[]; };
layout(std430, set = 2, binding = 2) readonly buffer TextureSlots { uvec4 texture_slots[]; };

// The chunk this draw draws: the culling pass puts its index in the draw's first instance. Instanced
// stereo draws two instances, one per eye, so there only the base instance is the chunk; the other
// forms draw one instance and need no draw parameters (shaderDrawParameters).
#ifdef MONOPLANE_STEREO_INSTANCED
#define MONOPLANE_DRAWN_CHUNK gl_BaseInstance
#else
#define MONOPLANE_DRAWN_CHUNK gl_InstanceIndex
#endif

// The texture of the chunk this draw draws as (array, layer, wrap_u, wrap_v), or
// MONOPLANE_NO_TEXTURE in x; and the vertex's coordinate, read only for textured chunks.
void fetch_texture(out uvec4 slot, out vec2 uv) {
    int texture_index = chunk_surface[MONOPLANE_DRAWN_CHUNK].x;
    slot = uvec4(MONOPLANE_NO_TEXTURE, 0u, 0u, 0u);
    uv = vec2(0.0);
    if (texture_index < 0) return;
    slot = texture_slots[texture_index];
    uv = texcoords[gl_VertexIndex];
}

// The alpha below which the chunk's fragments are dropped (alphaMode MASK; unused otherwise).
float fetch_alpha_cutoff() {
    return intBitsToFloat(chunk_surface[MONOPLANE_DRAWN_CHUNK].y);
}
#endif

#ifdef MONOPLANE_SCENE_TEXTURES_FRAGMENT
layout(set = 2, binding = 3) uniform texture2DArray base_colour_arrays[MONOPLANE_TEXTURE_ARRAYS];
// Samplers by the axes they clamp (MONOPLANE_SAMPLER_*): repeat or clamp-to-edge per axis, so
// the hardware's own addressing is exact at every mip level and under anisotropic filtering.
layout(set = 2, binding = 4) uniform sampler wrap_samplers[4];

// glTF's mirrored repeat folded into [0, 1] (a triangle wave), then clamped to the edge: the
// texels around a fold are the edge texels read twice, as a mirroring sampler reads them.
float mirrored(float u) {
    return 1.0 - abs(mod(u, 2.0) - 1.0);
}

vec4 sample_array(texture2DArray array, uint sampler_index, vec3 at, vec2 dx, vec2 dy) {
    switch (sampler_index) {
        case 0u: return textureGrad(sampler2DArray(array, wrap_samplers[0]), at, dx, dy);
        case 1u: return textureGrad(sampler2DArray(array, wrap_samplers[1]), at, dx, dy);
        case 2u: return textureGrad(sampler2DArray(array, wrap_samplers[2]), at, dx, dy);
        default: return textureGrad(sampler2DArray(array, wrap_samplers[3]), at, dx, dy);
    }
}

// glTF's base-colour alpha: the vertex's (factor x vertex colour) times the texture's.
float surface_alpha(float vertex_alpha, uvec4 slot, vec2 uv);

// Linear RGBA of the texture at uv. The gradients are those of the unfolded coordinate, so that
// folding does not make the level of detail jump at a fold.
vec4 base_colour_texture(uvec4 slot, vec2 uv) {
    vec2 dx = dFdx(uv);
    vec2 dy = dFdy(uv);
    vec2 at = vec2(slot.z == MONOPLANE_WRAP_MIRROR ? mirrored(uv.x) : uv.x,
                   slot.w == MONOPLANE_WRAP_MIRROR ? mirrored(uv.y) : uv.y);
    uint sampler_index = (slot.z != MONOPLANE_WRAP_REPEAT ? MONOPLANE_SAMPLER_CLAMP_U : 0u) |
                         (slot.w != MONOPLANE_WRAP_REPEAT ? MONOPLANE_SAMPLER_CLAMP_V : 0u);
    vec3 layer = vec3(at, float(slot.y));
    // Constant indices only: devices without descriptor indexing (lavapipe) need no feature.
    switch (slot.x) {
        case 0u: return sample_array(base_colour_arrays[0], sampler_index, layer, dx, dy);
        case 1u: return sample_array(base_colour_arrays[1], sampler_index, layer, dx, dy);
        case 2u: return sample_array(base_colour_arrays[2], sampler_index, layer, dx, dy);
        case 3u: return sample_array(base_colour_arrays[3], sampler_index, layer, dx, dy);
        case 4u: return sample_array(base_colour_arrays[4], sampler_index, layer, dx, dy);
        case 5u: return sample_array(base_colour_arrays[5], sampler_index, layer, dx, dy);
        default: return sample_array(base_colour_arrays[6], sampler_index, layer, dx, dy);
    }
}

float surface_alpha(float vertex_alpha, uvec4 slot, vec2 uv) {
    if (slot.x == MONOPLANE_NO_TEXTURE) return vertex_alpha;
    return vertex_alpha * base_colour_texture(slot, uv).a;
}

// Alpha to coverage for alphaMode MASK (MSAA): the alpha against the cut-off, sharpened to a ramp
// about one pixel wide, so the samples covered change where the alpha test would cut.
float coverage_alpha(float alpha, float cutoff) {
    return clamp((alpha - cutoff) / max(fwidth(alpha), 1e-4) + 0.5, 0.0, 1.0);
}
#endif
