// The chunk-culling pass's inputs and outputs, declared once for C++ and GLSL (std140/std430 with
// 16-byte members only, so the C++ layout is identical; static_asserts keep it that way).
#ifndef MONOPLANE_CULL_CONSTANTS_H
#define MONOPLANE_CULL_CONSTANTS_H

#ifdef __cplusplus
#include <cstdint>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
namespace monoplane::passes {
using mat4 = glm::mat4;
using vec4 = glm::vec4;
using uvec4 = glm::uvec4;
#endif

// Views of the culling pass, each with its frustum, and the draw lists it writes: list l starts
// at command l * chunk_count. The last list is no view of its own: the chunks in either eye's
// list, which single-pass stereo draws once for both eyes.
#define MONOPLANE_CULL_LEFT 0
#define MONOPLANE_CULL_RIGHT 1
#define MONOPLANE_CULL_MONO 2
#define MONOPLANE_CULL_VIEWS 3
#define MONOPLANE_CULL_BOTH_EYES 3
#define MONOPLANE_CULL_LISTS 4

// config.w bits
#define MONOPLANE_CULL_HONOUR_FORCE_MONO 1u    // kChunkForceMono chunks skip the eyes' lists
#define MONOPLANE_CULL_HONOUR_FORCE_STEREO 2u  // kChunkForceStereo chunks skip C's list
// Hybrid: a blended chunk wholly beyond m (both eyes' far plane) is C's alone; every other goes
// to the eyes alone, whose lists take it whatever their far plane: the eyes draw it after the
// composite (renderer/plan/frame_plan.h). Nothing blended is drawn twice into one eye, though C's
// region starts at m - eps: a blended surface has no depth the composite could choose by.
#define MONOPLANE_CULL_SPLIT_BLENDED 4u

// Alpha classes (scenes::AlphaMode), one pipeline each: every list holds its chunks class by
// class, class c of list l in the commands from l * chunk_count + CullConstants.classes[c] (the
// chunks of the classes before it counted at load), in the frame's order within each class.
#define MONOPLANE_CLASS_OPAQUE 0
#define MONOPLANE_CLASS_MASKED 1
#define MONOPLANE_CLASS_BLENDED 2
#define MONOPLANE_CLASSES 3
// ChunkRecord.draw.w: the chunk's flags in the low byte, its class in bits 8-9.
#define MONOPLANE_CHUNK_CLASS_SHIFT 8u

// Words of the counts buffer (uint32 each). The first four are each list's number of draws (word
// l counts list l); the others are predicates for conditional rendering, written by the frustum
// phase.
#define MONOPLANE_COUNT_LEFT 0
#define MONOPLANE_COUNT_RIGHT 1
#define MONOPLANE_COUNT_MONO 2
#define MONOPLANE_COUNT_BOTH_EYES 3
#define MONOPLANE_COUNT_MONO_CANDIDATES 4   // C's draws before occlusion culling
#define MONOPLANE_PRED_MONO_ANY 5           // C has chunks: C, its composite (else the eyes' sky)
#define MONOPLANE_PRED_MONO_DEPTH_TESTED 6  // and an eye has some: the pyramid, C's hidden mask
// Each list's draws of masked chunks (word + list), then of blended chunks; the words above count
// the opaque class.
#define MONOPLANE_COUNT_MASKED 7
#define MONOPLANE_COUNT_BLENDED 11
#define MONOPLANE_COUNT_WORDS 15
// The counts word of list l's draws of alpha class c.
#define MONOPLANE_COUNT_WORD(l, c)                                                              \
    ((c) == MONOPLANE_CLASS_OPAQUE                                                              \
         ? (l)                                                                                  \
         : ((c) == MONOPLANE_CLASS_MASKED ? MONOPLANE_COUNT_MASKED : MONOPLANE_COUNT_BLENDED) + \
               (l))

// Bits of the routing word each chunk gets per frame (the debug view "routing"): the lists it went
// to, and whether occlusion culling then took it out of C's.
#define MONOPLANE_ROUTE_LEFT 1u
#define MONOPLANE_ROUTE_RIGHT 2u
#define MONOPLANE_ROUTE_MONO 4u
#define MONOPLANE_ROUTE_HIDDEN 8u

// The level-of-detail view groups: both eyes choose one level together, C its own
// (renderer/plan/lod_selection.h). The per-chunk state buffer keeps each group's last level.
#define MONOPLANE_LOD_EYES 0
#define MONOPLANE_LOD_MONO 1
#define MONOPLANE_LOD_GROUPS 2

struct CullConstants {
    // Six planes per view (a, b, c, d; inside where a x + b y + c z + d >= 0), world space,
    // normalised so that (a, b, c) is a unit vector: distances in metres, float-safe.
    vec4 planes[MONOPLANE_CULL_VIEWS * 6];
    // x: chunk count; y: bit v set when view v is drawn this frame; z: instances per draw of the
    // both-eyes list (1, or 2 for instanced stereo; the phase is a push constant); w:
    // MONOPLANE_CULL_HONOUR_* bits.
    uvec4 config;
    mat4 mono_view_proj;  // world -> C's clip space (phase 1)
    // x, y: C's viewport in pixels (eq. 8); z: the eyes' reversed-Z depth of m - eps (a pyramid
    // value above it means every eye pixel that reads this part of C is covered by nearer
    // content); w: the pyramid's mip count (mip 0 is level 2 of the paper).
    vec4 occlusion;
    // Level of detail, per view v: lod_views[2 v] = (camera position, pixels per unit tangent),
    // lod_views[2 v + 1] = (unit view axis, tan^2 of the widest corner ray).
    vec4 lod_views[MONOPLANE_CULL_VIEWS * 2];
    // x: the error budget in pixels (0: level 0 always, --lod off); y: the share of it a coarser
    // level must meet before a chunk moves to it (hysteresis).
    vec4 lod;
    // The first command of each class within a list (MONOPLANE_CLASS_*); w unused.
    uvec4 classes;
};

// One chunk as the culling shader reads it (std430: 64 bytes).
struct ChunkRecord {
    vec4 bounds_min;  // xyz
    vec4 bounds_max;  // xyz
    // x: index count, y: first index, z: vertex offset (bit pattern of an int32), w: flags and
    // class (MONOPLANE_CHUNK_CLASS_SHIFT).
    uvec4 draw;
    // x: the chunk's first record in the level table, y: its number of levels (level 0, the
    // chunk itself, included).
    uvec4 lod;
};

// One level of detail of a chunk (std430: 16 bytes): x index count, y first index in the
// scene's index buffer, z the level's geometric error in metres (bit pattern of a float).
struct LodRecord {
    uvec4 draw;
};

#ifdef __cplusplus
static_assert(sizeof(CullConstants) == 18 * 16 + 16 + 64 + 16 + 6 * 16 + 16 + 16,
              "std430 layout shared with GLSL");
static_assert(sizeof(ChunkRecord) == 64, "std430 layout shared with GLSL");
static_assert(sizeof(LodRecord) == 16, "std430 layout shared with GLSL");
}  // namespace monoplane::passes
#endif

#endif
