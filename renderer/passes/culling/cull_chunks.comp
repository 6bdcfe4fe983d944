#version 460
#extension GL_GOOGLE_include_directive : require
// Sorts the scene's chunks into the views that need them (Fink et al. 2019, Sect. 4.4): the eyes'
// lists (inside an eye frustum, whose far plane is m in hybrid modes) and C's list (inside C's
// frustum, whose near plane is m - eps). A chunk straddling the plane lands in all three. A fourth
// list holds the chunks of either eye's list, for single-pass stereo. Phase 1 re-sorts C's list
// with occlusion culling against the merged depth pyramid of both eyes.
//
// One workgroup walks the chunks in the frame's draw order (nearest first, from the CPU: early
// depth testing then rejects most hidden fragments before they are shaded) in blocks; a prefix
// sum per block compacts each view's list in that order, so the draw order (and any depth tie)
// follows the order given and matches the CPU reference.
#include "renderer/passes/culling/cull_constants.h"

layout(local_size_x = 256) in;

layout(std430, set = 0, binding = 0) readonly buffer Chunks { ChunkRecord chunks[]; };
struct DrawCommand {
    uint index_count;
    uint instance_count;
    uint first_index;
    int vertex_offset;
    uint first_instance;
};
layout(std430, set = 0, binding = 1) writeonly buffer Commands { DrawCommand commands[]; };
layout(std430, set = 0, binding = 2) buffer Counts { uint counts[MONOPLANE_COUNT_WORDS]; };
// The frame's planes and matrices, read from a storage buffer rather than a uniform buffer: an
// LLVM-based driver (lavapipe) inlines uniform values that this shader stores and reuses into
// the compiled code, and would compile a new variant whenever the head turned the planes (the
// layout is the same under std430: every member is 16 bytes).
layout(std430, set = 0, binding = 3) readonly buffer Constants { CullConstants cull; };
// Reversed-Z depth, minimum (farthest) over each texel's region of both eyes; mip 0 is level 2.
layout(set = 0, binding = 4) uniform sampler2D merged_depth;
// Per chunk: the MONOPLANE_ROUTE_* bits of this frame, for the debug view "routing".
layout(std430, set = 0, binding = 5) buffer Routing { uint routing[]; };
// The frame's draw order: a permutation of the chunk indices.
layout(std430, set = 0, binding = 6) readonly buffer Order { uint order[]; };
// Every chunk's levels of detail (ChunkRecord.lod indexes it), and each chunk's level of the
// last frame per view group (MONOPLANE_LOD_*), for the hysteresis.
layout(std430, set = 0, binding = 7) readonly buffer Levels { LodRecord levels[]; };
layout(std430, set = 0, binding = 8) buffer LodState { uint lod_state[]; };
layout(push_constant) uniform Push { uint phase; };  // 0: frustum, 1: C's occlusion culling

const uint kBlock = 256;
// One running list per view list and alpha class: sub-list s = class * MONOPLANE_CULL_LISTS + list.
const uint kSublists = MONOPLANE_CULL_LISTS * MONOPLANE_CLASSES;
shared uint scan[kSublists][kBlock];
shared uint written[kSublists];

// Planes of modes::frustum_planes: left, right, bottom, top, far (reversed Z: z >= 0), near.
const uint kFarPlane = 4u;
const uint kNoPlane = 6u;

// skip: a plane not tested (kFarPlane: the eyes' lists of blended chunks in hybrid), or kNoPlane.
bool outside_frustum(uint view, vec3 lo, vec3 hi, uint skip) {
    for (uint i = 0; i < 6; ++i) {
        if (i == skip) continue;
        vec4 p = cull.planes[view * 6 + i];
        // The box corner furthest along the plane's normal (a select per component).
        vec3 corner = mix(lo, hi, greaterThanEqual(p.xyz, vec3(0.0)));
        if (dot(p.xyz, corner) + p.w < 0.0) return true;
    }
    return false;
}

bool outside_frustum(uint view, vec3 lo, vec3 hi) {
    return outside_frustum(view, lo, hi, kNoPlane);
}

// Whether the whole box lies outside the plane's half-space (its corner furthest along the
// normal does).
bool wholly_outside(vec4 p, vec3 lo, vec3 hi) {
    vec3 corner = mix(lo, hi, greaterThanEqual(p.xyz, vec3(0.0)));
    return dot(p.xyz, corner) + p.w < 0.0;
}

// True when every eye pixel that would read the box's part of C is covered by content nearer
// than m - eps (Sect. 4.4, "Occlusion Culling"): the box's screen rectangle in C selects the
// pyramid level at which it spans at most 2 x 2 texels.
bool hidden_in_both_eyes(vec3 lo, vec3 hi) {
    vec2 area = cull.occlusion.xy;
    vec2 rect_min = vec2(1e30);
    vec2 rect_max = vec2(-1e30);
    for (int i = 0; i < 8; ++i) {
        vec3 corner = vec3((i & 1) != 0 ? hi.x : lo.x, (i & 2) != 0 ? hi.y : lo.y,
                           (i & 4) != 0 ? hi.z : lo.z);
        vec4 clip = cull.mono_view_proj * vec4(corner, 1.0);
        // A box reaching behind C has no bounded rectangle: keep it.
        if (clip.w <= 1e-4) return false;
        vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * area;
        rect_min = min(rect_min, pixel);
        rect_max = max(rect_max, pixel);
    }
    rect_min = clamp(rect_min, vec2(0.0), area - 1.0);
    rect_max = clamp(rect_max, vec2(0.0), area - 1.0);
    // Level 2 of the paper: 4 x 4 pixels per texel.
    ivec2 first = ivec2(rect_min) >> 2;
    ivec2 last = ivec2(rect_max) >> 2;
    int mips = int(cull.occlusion.w);
    int mip = 0;
    while (mip + 1 < mips && (last.x - first.x > 1 || last.y - first.y > 1)) {
        ++mip;
        first >>= 1;
        last >>= 1;
    }
    ivec2 size = textureSize(merged_depth, mip);
    first = min(first, size - 1);
    last = min(last, size - 1);
    float farthest = 1.0;
    for (int y = first.y; y <= last.y; ++y) {
        for (int x = first.x; x <= last.x; ++x) {
            farthest = min(farthest, texelFetch(merged_depth, ivec2(x, y), mip).r);
        }
    }
    return farthest > cull.occlusion.z;
}

// The projected error (pixels) of error_m metres at the box's nearest point in view v
// (renderer/plan/lod_selection.h: error f (1 + tan^2 theta) / d); +inf inside the box.
float projected_error_px(uint v, vec3 lo, vec3 hi, float error_m) {
    vec4 camera = cull.lod_views[2 * v];
    vec4 axis = cull.lod_views[2 * v + 1];
    vec3 to_nearest = clamp(camera.xyz, lo, hi) - camera.xyz;
    float distance_squared = dot(to_nearest, to_nearest);
    if (distance_squared <= 0.0) return 1.0 / 0.0;
    float along = dot(to_nearest, axis.xyz);
    float tangent_squared = axis.w;
    if (along > 0.0) {
        float across_squared = distance_squared - along * along;
        tangent_squared = min(tangent_squared, across_squared / (along * along));
    }
    return error_m * camera.w * (1.0 + tangent_squared) * inversesqrt(distance_squared);
}

// The coarsest of the chunk's levels within budget_px in every view of `views` (a bit mask).
uint coarsest_within(ChunkRecord chunk, uint views, float budget_px) {
    uint level = 0u;
    for (uint l = 1u; l < chunk.lod.y; ++l) {
        float error_m = uintBitsToFloat(levels[chunk.lod.x + l].draw.z);
        bool fits = true;
        for (uint v = 0u; v < MONOPLANE_CULL_VIEWS; ++v) {
            if ((views & (1u << v)) == 0u) continue;
            fits = fits && projected_error_px(v, chunk.bounds_min.xyz, chunk.bounds_max.xyz,
                                              error_m) <= budget_px;
        }
        if (!fits) break;  // errors grow along the chain
        level = l;
    }
    return level;
}

// The group's level this frame: within the budget, coarser only once comfortably so
// (hysteresis); stored for the next frame.
uint choose_level(ChunkRecord chunk, uint index, uint group, uint views) {
    uint slot = index * MONOPLANE_LOD_GROUPS + group;
    float budget = cull.lod.x;
    if (budget <= 0.0 || views == 0u) return 0u;
    uint within = coarsest_within(chunk, views, budget);
    uint comfortably = coarsest_within(chunk, views, cull.lod.y * budget);
    uint level = clamp(lod_state[slot], comfortably, within);
    lod_state[slot] = level;
    return level;
}

void main() {
    uint lane = gl_LocalInvocationIndex;
    uint chunk_count = cull.config.x;
    uint views = cull.config.y;
    bool occlusion_phase = phase == 1u;
    bool honour_force_mono = (cull.config.w & MONOPLANE_CULL_HONOUR_FORCE_MONO) != 0u;
    bool honour_force_stereo = (cull.config.w & MONOPLANE_CULL_HONOUR_FORCE_STEREO) != 0u;
    bool split_blended = (cull.config.w & MONOPLANE_CULL_SPLIT_BLENDED) != 0u;
    if (lane < kSublists) written[lane] = 0u;
    barrier();

    for (uint base = 0; base < chunk_count; base += kBlock) {
        uint position = base + lane;
        uint index = position < chunk_count ? order[position] : 0u;
        bool visible[MONOPLANE_CULL_LISTS] = bool[](false, false, false, false);
        uint level[MONOPLANE_LOD_GROUPS] = uint[](0u, 0u);
        uint alpha_class = MONOPLANE_CLASS_OPAQUE;
        if (position < chunk_count) {
            ChunkRecord chunk = chunks[index];
            // Phase 0 chooses both groups' levels; phase 1 redraws C's list at C's choice.
            uint eye_views = views & ((1u << MONOPLANE_CULL_LEFT) | (1u << MONOPLANE_CULL_RIGHT));
            uint mono_views = views & (1u << MONOPLANE_CULL_MONO);
            if (!occlusion_phase) {
                level[MONOPLANE_LOD_EYES] =
                    choose_level(chunk, index, MONOPLANE_LOD_EYES, eye_views);
                level[MONOPLANE_LOD_MONO] =
                    choose_level(chunk, index, MONOPLANE_LOD_MONO, mono_views);
            } else if (cull.lod.x > 0.0) {
                level[MONOPLANE_LOD_MONO] =
                    lod_state[index * MONOPLANE_LOD_GROUPS + MONOPLANE_LOD_MONO];
            }
            vec3 lo = chunk.bounds_min.xyz;
            vec3 hi = chunk.bounds_max.xyz;
            uint flags = chunk.draw.w & 0xffu;
            alpha_class = chunk.draw.w >> MONOPLANE_CHUNK_CLASS_SHIFT;
            bool eyes_allowed = !(honour_force_mono && (flags & 1u) != 0u);
            bool mono_allowed = !(honour_force_stereo && (flags & 2u) != 0u);
            // Blended chunks in hybrid: C's when wholly beyond m (both eyes' far plane), else
            // the eyes', even where C's region (from m - eps) reaches them.
            uint eye_skip = kNoPlane;
            if (split_blended && alpha_class == MONOPLANE_CLASS_BLENDED) {
                bool beyond =
                    wholly_outside(cull.planes[MONOPLANE_CULL_LEFT * 6 + kFarPlane], lo, hi) &&
                    wholly_outside(cull.planes[MONOPLANE_CULL_RIGHT * 6 + kFarPlane], lo, hi);
                eyes_allowed = !beyond;
                mono_allowed = beyond;
                eye_skip = kFarPlane;
            }
            if (!occlusion_phase) {
                for (uint v = 0; v < MONOPLANE_CULL_MONO; ++v) {
                    visible[v] = (views & (1u << v)) != 0u && eyes_allowed &&
                                 !outside_frustum(v, lo, hi, eye_skip);
                }
                visible[MONOPLANE_CULL_BOTH_EYES] =
                    visible[MONOPLANE_CULL_LEFT] || visible[MONOPLANE_CULL_RIGHT];
            }
            visible[MONOPLANE_CULL_MONO] = (views & (1u << MONOPLANE_CULL_MONO)) != 0u &&
                                           mono_allowed &&
                                           !outside_frustum(MONOPLANE_CULL_MONO, lo, hi);
            if (!occlusion_phase) {
                routing[index] = (visible[MONOPLANE_CULL_LEFT] ? MONOPLANE_ROUTE_LEFT : 0u) |
                                 (visible[MONOPLANE_CULL_RIGHT] ? MONOPLANE_ROUTE_RIGHT : 0u) |
                                 (visible[MONOPLANE_CULL_MONO] ? MONOPLANE_ROUTE_MONO : 0u);
            } else if (visible[MONOPLANE_CULL_MONO] && hidden_in_both_eyes(lo, hi)) {
                visible[MONOPLANE_CULL_MONO] = false;
                routing[index] = (routing[index] & ~MONOPLANE_ROUTE_MONO) | MONOPLANE_ROUTE_HIDDEN;
            }
        }
        for (uint s = 0; s < kSublists; ++s) {
            uint v = s % MONOPLANE_CULL_LISTS;
            scan[s][lane] = visible[v] && s / MONOPLANE_CULL_LISTS == alpha_class ? 1u : 0u;
        }
        barrier();
        // Inclusive prefix sums (Hillis and Steele) of the block's visibility, per sub-list.
        for (uint offset = 1; offset < kBlock; offset <<= 1) {
            uint add[kSublists];
            for (uint s = 0; s < kSublists; ++s) {
                add[s] = lane >= offset ? scan[s][lane - offset] : 0u;
            }
            barrier();
            for (uint s = 0; s < kSublists; ++s) scan[s][lane] += add[s];
            barrier();
        }
        for (uint v = 0; v < MONOPLANE_CULL_LISTS; ++v) {
            if (!visible[v]) continue;
            ChunkRecord chunk = chunks[index];
            uint s = alpha_class * MONOPLANE_CULL_LISTS + v;
            uint slot = v * chunk_count + cull.classes[alpha_class] + written[s] + scan[s][lane] - 1u;
            LodRecord drawn = levels[chunk.lod.x +
                                     level[v == MONOPLANE_CULL_MONO ? MONOPLANE_LOD_MONO
                                                                    : MONOPLANE_LOD_EYES]];
            // first_instance carries the chunk index (the shaders ignore it): read-back lists
            // name their chunks.
            // The both-eyes list draws config.z instances of each chunk: 1 for the geometry
            // shader's and multiview's duplication, 2 for instanced stereo (one per eye).
            uint instances = v == MONOPLANE_CULL_BOTH_EYES ? max(cull.config.z, 1u) : 1u;
            commands[slot] =
                DrawCommand(drawn.draw.x, instances, drawn.draw.y, int(chunk.draw.z), index);
        }
        barrier();
        if (lane < kSublists) written[lane] += scan[lane][kBlock - 1];
        barrier();
    }

    if (lane == 0) {
        uint mono = 0u;
        uint near = 0u;
        for (uint c = 0; c < MONOPLANE_CLASSES; ++c) {
            uint base = c * MONOPLANE_CULL_LISTS;
            counts[MONOPLANE_COUNT_WORD(MONOPLANE_CULL_MONO, c)] =
                written[base + MONOPLANE_CULL_MONO];
            mono += written[base + MONOPLANE_CULL_MONO];
            if (occlusion_phase) continue;
            for (uint l = 0; l < MONOPLANE_CULL_LISTS; ++l) {
                if (l == MONOPLANE_CULL_MONO) continue;
                counts[MONOPLANE_COUNT_WORD(l, c)] = written[base + l];
            }
            near += written[base + MONOPLANE_CULL_LEFT] + written[base + MONOPLANE_CULL_RIGHT];
        }
        if (!occlusion_phase) {
            counts[MONOPLANE_COUNT_MONO_CANDIDATES] = mono;
            counts[MONOPLANE_PRED_MONO_ANY] = mono > 0u ? 1u : 0u;
            counts[MONOPLANE_PRED_MONO_DEPTH_TESTED] = mono > 0u && near > 0u ? 1u : 0u;
        }
    }
}
