// Level of detail: for each chunk a chain of simplified versions of its triangles, built with
// meshoptimizer's simplifier (meshopt_simplify), each with the geometric error it makes. The
// renderer's culling pass picks, per view and chunk, the coarsest level whose error, projected
// at the chunk's nearest point, stays within a pixel budget (renderer/plan/lod_selection.h).
//
// Levels reuse the chunk's vertices (the simplifier only drops triangles and re-links the
// rest), so a level is just another index range over the same vertex range: texture
// coordinates, colours and normals stay those of the kept vertices. Open borders are locked
// (meshopt_SimplifyLockBorder): a terrain tile keeps the edge it shares with its neighbours,
// so no crack opens between chunks drawn at different levels, and a surface split at a seam of
// duplicated vertices (hard edges, texture seams, material boundaries) keeps the seam.
//
// The simplifier weighs positions only. Where a chunk's look varies across shared vertices
// (vertex colours that change along an edge, several materials, a texture), a level moves those
// features by up to about its own edge length, and that length counts as the level's error: such
// a chunk simplifies only where its triangles are already smaller than the budget.
//
// When may this be called: any time, any thread; it reads the scene and allocates.
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/scene.h"

namespace monoplane::scenes {

// Level 0 is the chunk itself; a chain has at most this many levels in all.
inline constexpr std::uint32_t kMaxLodLevels = 8;

struct LodLevel {
    // Into LodChain::indices; chunk-relative like Scene::indices (add Chunk::vertex_offset).
    std::uint32_t first_index = 0;
    std::uint32_t index_count = 0;
    // Metres: an upper estimate of how far the level's surface lies from the chunk's full
    // surface (the simplifier's quadric error, made absolute by meshopt_simplifyScale, with a
    // margin for curved surfaces, lod_chain.cpp). Never below a finer level's error (the chain
    // keeps the running maximum), so "the coarsest level within a budget" is a prefix of the
    // chain.
    float error_m = 0.0f;
};

// Per chunk, its levels beyond level 0, coarsest last.
struct ChunkLods {
    std::uint32_t first_level = 0;  // into LodChain::levels
    std::uint32_t level_count = 0;  // 0: the chunk could not be simplified
};

struct LodChain {
    std::vector<std::uint32_t> indices;  // the simplified levels' triangles, level after level
    std::vector<LodLevel> levels;
    std::vector<ChunkLods> chunks;  // parallel to Scene::chunks

    std::size_t triangle_count() const { return indices.size() / 3; }
};

// Builds every chunk's chain: level k aims at 1/2^k of the chunk's triangles (simplified from
// the full chunk each time, so errors are measured against the original surface) and the chain
// ends where the simplifier cannot halve the previous level any more (locked borders), below
// kMinLodTriangles, or at kMaxLodLevels. Chunks whose alpha mode is not AlphaMode::kOpaque get
// no levels beyond level 0 (lod_chain.cpp says why). Deterministic: the same scene gives the same
// chain.
inline constexpr std::uint32_t kMinLodTriangles = 8;
LodChain build_lod_chain(const Scene& scene);

}  // namespace monoplane::scenes
