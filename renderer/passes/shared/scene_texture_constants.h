// The texture arrays of set 2 (scene_textures.h, scenes/texture_arrays.h), declared once for
// C++ and GLSL.
#ifndef MONOPLANE_SCENE_TEXTURE_CONSTANTS_H
#define MONOPLANE_SCENE_TEXTURE_CONSTANTS_H

#define MONOPLANE_TEXTURE_ARRAYS 7
#define MONOPLANE_TEXTURE_SMALLEST_SIDE 128u
#define MONOPLANE_NO_TEXTURE 0xffffffffu
// scenes::TextureWrap, in the slot's z (u) and w (v)
#define MONOPLANE_WRAP_REPEAT 0u
#define MONOPLANE_WRAP_CLAMP 1u
#define MONOPLANE_WRAP_MIRROR 2u
// The four samplers of binding 4, indexed by these bits: which axes clamp to the edge.
#define MONOPLANE_SAMPLER_CLAMP_U 1u
#define MONOPLANE_SAMPLER_CLAMP_V 2u
#define MONOPLANE_WRAP_SAMPLERS 4

#endif
