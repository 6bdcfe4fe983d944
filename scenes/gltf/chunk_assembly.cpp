#include "scenes/gltf/chunk_assembly.h"

#include <algorithm>
#include <limits>
#include <tuple>
#include <vector>

#include <meshoptimizer.h>

#include "common/programming_error.h"
#include "scenes/chunk_builder.h"

namespace monoplane::scenes::gltf {
namespace {

// What every triangle of a chunk shares: its texture and how it covers what lies behind it.
// Blended triangles also share their batch (primitive instance): the renderer orders blended
// chunks back to front, never the triangles within one, so two panes of glass must not share a
// chunk. Ordered by texture first, so a scene that is opaque throughout chunks as it did before
// alpha modes were read.
struct ChunkLook {
    std::int32_t texture = -1;
    AlphaMode alpha_mode = AlphaMode::kOpaque;
    float alpha_cutoff = 0.5f;
    std::int64_t batch = -1;  // kBlend only: into ImportedGeometry::batches

    static ChunkLook of(const ImportedGeometry& geometry, std::size_t batch_index) {
        const GeometryBatch& batch = geometry.batches[batch_index];
        const bool blend = batch.alpha_mode == AlphaMode::kBlend;
        return {batch.texture, batch.alpha_mode, batch.alpha_cutoff,
                blend ? static_cast<std::int64_t>(batch_index) : -1};
    }
    auto key() const { return std::tuple(texture, alpha_mode, alpha_cutoff, batch); }
    bool operator<(const ChunkLook& other) const { return key() < other.key(); }
    bool operator==(const ChunkLook& other) const { return key() == other.key(); }
};

// A triangle to place: its centre (the split key) and its number in ImportedGeometry order.
struct TriangleRef {
    glm::vec3 centre;
    std::uint32_t triangle;
};

// Splits refs[begin, end) at the median along the longest axis of their centres until each part
// has at most `target` triangles; appends the parts' [begin, end) to cells.
void split(std::vector<TriangleRef>& refs, std::size_t begin, std::size_t end, std::uint32_t target,
           std::vector<std::pair<std::size_t, std::size_t>>& cells) {
    if (end - begin <= target) {
        cells.emplace_back(begin, end);
        return;
    }
    glm::vec3 low(std::numeric_limits<float>::max());
    glm::vec3 high(std::numeric_limits<float>::lowest());
    for (std::size_t i = begin; i < end; ++i) {
        low = glm::min(low, refs[i].centre);
        high = glm::max(high, refs[i].centre);
    }
    const glm::vec3 extent = high - low;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    const std::size_t middle = begin + (end - begin) / 2;
    // The triangle number breaks ties, so the order is total and each side's set of triangles
    // is the same with every standard library (nth_element leaves the order within a side open;
    // chunks sort their triangles afterwards).
    std::nth_element(refs.begin() + static_cast<std::ptrdiff_t>(begin),
                     refs.begin() + static_cast<std::ptrdiff_t>(middle),
                     refs.begin() + static_cast<std::ptrdiff_t>(end),
                     [axis](const TriangleRef& a, const TriangleRef& b) {
                         return a.centre[axis] < b.centre[axis] ||
                                (a.centre[axis] == b.centre[axis] && a.triangle < b.triangle);
                     });
    split(refs, begin, middle, target, cells);
    split(refs, middle, end, target, cells);
}

// Per-chunk scratch: which chunk last used each global vertex, and where.
class ChunkWriter {
  public:
    ChunkWriter(const ImportedGeometry& geometry, const std::vector<std::uint32_t>& corners,
                bool textured, Scene& scene)
        : geometry_(geometry),
          corners_(corners),
          textured_(textured),
          scene_(scene),
          stamp_(geometry.vertices.size(), 0u),
          local_(geometry.vertices.size(), 0u) {}

    void write(std::vector<std::uint32_t>& triangles, const ChunkLook& look) {
        std::sort(triangles.begin(), triangles.end());
        // Chunk-local indices in first-use order, then the GPU-friendly triangle order.
        ++chunk_;
        globals_.clear();
        indices_.clear();
        for (const std::uint32_t t : triangles) {
            for (std::uint32_t k = 0; k < 3; ++k)
                indices_.push_back(local_index(corners_[3 * t + k]));
        }
        optimized_.resize(indices_.size());
        meshopt_optimizeVertexCache(optimized_.data(), indices_.data(), indices_.size(),
                                    globals_.size());
        // Vertices in the order the optimised triangles first use them (what
        // meshopt_optimizeVertexFetch would do), so the GPU reads them nearly in sequence.
        ++chunk_;
        const std::vector<std::uint32_t> by_first_use = globals_;
        globals_.clear();
        Chunk chunk;
        chunk.first_index = static_cast<std::uint32_t>(scene_.indices.size());
        chunk.vertex_offset = static_cast<std::int32_t>(scene_.vertices.size());
        chunk.index_count = static_cast<std::uint32_t>(optimized_.size());
        chunk.texture = look.texture;
        chunk.alpha_mode = look.alpha_mode;
        chunk.alpha_cutoff = look.alpha_cutoff;
        for (const std::uint32_t old_local : optimized_) {
            const std::uint32_t global = by_first_use[old_local];
            const std::size_t before = globals_.size();
            const std::uint32_t index = local_index(global);
            if (globals_.size() != before) {
                scene_.vertices.push_back(geometry_.vertices[global]);
                if (textured_) scene_.texcoords.push_back(geometry_.texcoords[global]);
            }
            scene_.indices.push_back(index);
        }
        chunk.bounds = bounds_of(scene_.vertices.data() + chunk.vertex_offset, globals_.size());
        scene_.chunks.push_back(chunk);
    }

  private:
    std::uint32_t local_index(std::uint32_t global) {
        if (stamp_[global] != chunk_) {
            stamp_[global] = chunk_;
            local_[global] = static_cast<std::uint32_t>(globals_.size());
            globals_.push_back(global);
        }
        return local_[global];
    }

    const ImportedGeometry& geometry_;
    const std::vector<std::uint32_t>& corners_;
    bool textured_;
    Scene& scene_;
    std::uint32_t chunk_ = 0;  // a stamp: two per chunk, one per pass
    std::vector<std::uint32_t> stamp_;
    std::vector<std::uint32_t> local_;
    std::vector<std::uint32_t> globals_;  // local index -> global vertex
    std::vector<std::uint32_t> indices_;
    std::vector<std::uint32_t> optimized_;
};

}  // namespace

void assemble_chunks(const ImportedGeometry& geometry, std::uint32_t target_triangles, Scene& scene,
                     const std::function<void(std::size_t)>& progress) {
    MONOPLANE_EXPECTS(geometry.vertices.size() < std::numeric_limits<std::uint32_t>::max());
    MONOPLANE_EXPECTS(geometry.triangle_count() < std::numeric_limits<std::uint32_t>::max());
    const std::uint32_t target = std::clamp(target_triangles, kMinChunkTarget, kMaxChunkTriangles);

    // The distinct looks, in order, the batches of each (in file order, so its triangles come in
    // ascending order), and global vertex numbers of every triangle's corners.
    std::vector<ChunkLook> looks;
    looks.reserve(geometry.batches.size());
    for (std::size_t b = 0; b < geometry.batches.size(); ++b) {
        looks.push_back(ChunkLook::of(geometry, b));
    }
    std::sort(looks.begin(), looks.end());
    looks.erase(std::unique(looks.begin(), looks.end()), looks.end());
    std::vector<std::vector<std::size_t>> batches_of(looks.size());
    std::vector<std::uint32_t> corners(3 * geometry.triangle_count());
    for (std::size_t b = 0; b < geometry.batches.size(); ++b) {
        const GeometryBatch& batch = geometry.batches[b];
        for (std::size_t i = 0; i < batch.index_count; ++i) {
            corners[batch.first_index + i] = static_cast<std::uint32_t>(
                batch.first_vertex + geometry.indices[batch.first_index + i]);
        }
        const auto found = std::lower_bound(looks.begin(), looks.end(), ChunkLook::of(geometry, b));
        batches_of[static_cast<std::size_t>(found - looks.begin())].push_back(b);
    }

    scene.vertices.clear();
    scene.indices.clear();
    scene.chunks.clear();
    scene.texcoords.clear();
    scene.indices.reserve(geometry.indices.size());
    scene.vertices.reserve(geometry.vertices.size() + geometry.vertices.size() / 8);
    const bool textured = std::any_of(looks.begin(), looks.end(),
                                      [](const ChunkLook& look) { return look.texture >= 0; });
    ChunkWriter writer(geometry, corners, textured, scene);
    std::size_t done = 0;
    std::vector<TriangleRef> refs;
    std::vector<std::pair<std::size_t, std::size_t>> cells;
    std::vector<std::uint32_t> members;
    // Triangles of different textures, alpha modes or cut-offs (or blended triangles of different
    // primitive instances) never share a chunk: one k-d tree per look.
    // (Each look's triangles are gathered from its batches: a scan of every triangle per look
    // would be quadratic in a scene of many blended primitives, each a look of its own.)
    for (std::size_t l = 0; l < looks.size(); ++l) {
        refs.clear();
        for (const std::size_t b : batches_of[l]) {
            const GeometryBatch& batch = geometry.batches[b];
            for (std::size_t t = batch.first_index / 3;
                 t < (batch.first_index + batch.index_count) / 3; ++t) {
                const glm::vec3& p0 = geometry.vertices[corners[3 * t]].position;
                const glm::vec3& p1 = geometry.vertices[corners[3 * t + 1]].position;
                const glm::vec3& p2 = geometry.vertices[corners[3 * t + 2]].position;
                refs.push_back({(p0 + p1 + p2) / 3.0f, static_cast<std::uint32_t>(t)});
            }
        }
        cells.clear();
        split(refs, 0, refs.size(), target, cells);
        for (const auto& [begin, end] : cells) {
            members.clear();
            for (std::size_t i = begin; i < end; ++i) members.push_back(refs[i].triangle);
            writer.write(members, looks[l]);
            done += end - begin;
            if (progress) progress(done);
        }
    }
    scene.bounds = Aabb{};
    if (!scene.chunks.empty()) {
        scene.bounds = scene.chunks.front().bounds;
        for (const Chunk& chunk : scene.chunks) scene.bounds = merge(scene.bounds, chunk.bounds);
    }
}

}  // namespace monoplane::scenes::gltf
