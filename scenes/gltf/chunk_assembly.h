// Imported geometry into the scene's chunks (the unit of culling and of indirect draws,
// docs/scenes.md). The triangles of each look (texture, alpha mode and cut-off; for blended
// triangles also the primitive instance, since blended chunks are ordered back to front as
// wholes) are split by a k-d tree over their centres, always at the median along the longest
// axis, until a cell holds at most the target; each cell is a chunk, spatially compact by
// construction whatever the meshes' sizes (one huge mesh or thousands of small ones). meshoptimizer
// then orders each chunk's triangles for the GPU's vertex cache, and its vertices are stored in
// first-use order.
//
// Why not meshopt_buildMeshlets' clusters as pieces: on large regular meshes its last meshlets
// gather left-over triangles from all over the mesh (measured: chunks spanning a 300 m grid),
// and a chunk's box must be tight for culling to work.
#pragma once

#include <cstdint>
#include <functional>

#include "scenes/gltf/imported_geometry.h"
#include "scenes/scene.h"

namespace monoplane::scenes::gltf {

// Chunks hold at least this many triangles where the geometry has that many (target clamped).
inline constexpr std::uint32_t kMinChunkTarget = 64;

// Writes scene.vertices, indices, chunks (tight bounds, one texture, alpha mode and cut-off
// each, blended ones one primitive instance each), texcoords (only if some chunk is textured)
// and bounds. Chunks get at most target_triangles (clamped to [kMinChunkTarget,
// kMaxChunkTriangles]) and, where there are more, at least half of that. progress(triangles_done)
// is called now and then. Deterministic: the same geometry gives the same bytes.
void assemble_chunks(const ImportedGeometry& geometry, std::uint32_t target_triangles, Scene& scene,
                     const std::function<void(std::size_t)>& progress = {});

}  // namespace monoplane::scenes::gltf
