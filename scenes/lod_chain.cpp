#include "scenes/lod_chain.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <span>
#include <thread>

#include <meshoptimizer.h>
#include <glm/geometric.hpp>

namespace monoplane::scenes {
namespace {

// A level must drop at least this share of the previous level's triangles to be worth a slot.
constexpr double kMinReduction = 0.15;

// meshopt_simplify's error is the distance to the planes of the triangles a vertex collapsed
// across (a quadric), which a curved surface's chords undercut: on a sphere the level's true
// deviation from the full-detail mesh reaches 1.42x it (tests/unit/lod_chain_test.cpp). Levels
// record the error times this margin, so a budget in pixels holds for curved surfaces too.
constexpr float kQuadricErrorMargin = 1.5f;

// Colour channels (8-bit) two vertices of one triangle may differ by and still count as one
// colour: smaller steps are below what a display shows.
constexpr int kColourTolerance = 2;

// The chunk's triangles and the vertex range they use.
struct ChunkMesh {
    std::span<const std::uint32_t> indices;
    const Vertex* vertices = nullptr;
    std::size_t vertex_count = 0;
    // Whether the surface's look varies across shared vertices: vertex colours or materials that
    // differ along a triangle's edge, or a texture (its coordinates are a vertex attribute too).
    bool look_varies = false;
    double area = 0.0;  // m^2, the triangles' total
};

int channel_step(std::uint32_t a, std::uint32_t b) {
    int largest = 0;
    for (int shift = 0; shift < 32; shift += 8) {
        largest = std::max(largest, std::abs(static_cast<int>((a >> shift) & 0xffu) -
                                             static_cast<int>((b >> shift) & 0xffu)));
    }
    return largest;
}

// Area, and whether colours or materials change along any edge.
void measure_surface(ChunkMesh& mesh) {
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        const Vertex* corner[3];
        for (int k = 0; k < 3; ++k) corner[k] = &mesh.vertices[mesh.indices[i + k]];
        mesh.area +=
            0.5 * glm::length(glm::cross(glm::dvec3(corner[1]->position - corner[0]->position),
                                         glm::dvec3(corner[2]->position - corner[0]->position)));
        for (int k = 0; k < 3; ++k) {
            const Vertex& a = *corner[k];
            const Vertex& b = *corner[(k + 1) % 3];
            mesh.look_varies = mesh.look_varies || a.material_packed != b.material_packed ||
                               channel_step(a.albedo_rgba8, b.albedo_rgba8) > kColourTolerance;
        }
    }
}

ChunkMesh chunk_mesh(const Scene& scene, const Chunk& chunk) {
    ChunkMesh mesh;
    mesh.indices = std::span(scene.indices).subspan(chunk.first_index, chunk.index_count);
    mesh.vertices = scene.vertices.data() + chunk.vertex_offset;
    std::uint32_t highest = 0;
    for (std::uint32_t index : mesh.indices) highest = std::max(highest, index);
    mesh.vertex_count = mesh.indices.empty() ? 0 : std::size_t{highest} + 1;
    measure_surface(mesh);
    mesh.look_varies = mesh.look_varies || chunk.texture >= 0;
    return mesh;
}

// The edge of an equilateral triangle of the level's mean area: how far a colour, material or
// texture feature carried by a vertex the level dropped may move (the simplifier weighs
// positions only; meshoptimizer 0.18 has no attribute-aware simplification).
double mean_edge_length(const ChunkMesh& mesh, std::size_t index_count) {
    const double triangle_area = mesh.area / static_cast<double>(index_count / 3);
    return std::sqrt(4.0 / std::sqrt(3.0) * triangle_area);
}

// Appends the chunk's levels to the chain.
void build_chunk_levels(const ChunkMesh& mesh, LodChain& chain) {
    ChunkLods& lods = chain.chunks.emplace_back();
    lods.first_level = static_cast<std::uint32_t>(chain.levels.size());
    if (mesh.indices.size() < 6 * std::size_t{kMinLodTriangles}) return;
    const float* positions = &mesh.vertices->position.x;
    // meshopt_simplify's errors are relative to this extent.
    const float scale = meshopt_simplifyScale(positions, mesh.vertex_count, sizeof(Vertex));
    std::vector<std::uint32_t> simplified(mesh.indices.size());
    std::size_t previous_count = mesh.indices.size();
    float previous_error = 0.0f;
    for (std::uint32_t level = 1; level < kMaxLodLevels; ++level) {
        const std::size_t target = (mesh.indices.size() >> level) / 3 * 3;
        if (target < 3 * std::size_t{kMinLodTriangles}) break;
        float relative_error = 0.0f;
        // An error target of 1 (the whole extent) lets the count decide; the error it reaches
        // is what the level records.
        const std::size_t count =
            meshopt_simplify(simplified.data(), mesh.indices.data(), mesh.indices.size(), positions,
                             mesh.vertex_count, sizeof(Vertex), target, 1.0f,
                             meshopt_SimplifyLockBorder, &relative_error);
        if (count == 0 || static_cast<double>(count) >
                              (1.0 - kMinReduction) * static_cast<double>(previous_count)) {
            break;
        }
        LodLevel& out = chain.levels.emplace_back();
        out.first_index = static_cast<std::uint32_t>(chain.indices.size());
        out.index_count = static_cast<std::uint32_t>(count);
        float error = kQuadricErrorMargin * relative_error * scale;
        if (mesh.look_varies) {
            error = std::max(error, static_cast<float>(mean_edge_length(mesh, count)));
        }
        out.error_m = std::max(previous_error, error);
        chain.indices.insert(chain.indices.end(), simplified.begin(),
                             simplified.begin() + static_cast<std::ptrdiff_t>(count));
        previous_count = count;
        previous_error = out.error_m;
        ++lods.level_count;
    }
}

// The chains of chunks [begin, end), with indices and levels counted from zero.
LodChain build_range(const Scene& scene, std::size_t begin, std::size_t end) {
    LodChain chain;
    chain.chunks.reserve(end - begin);
    for (std::size_t c = begin; c < end; ++c) {
        const Chunk& chunk = scene.chunks[c];
        // Cut-out and blended chunks keep their full detail only. A masked chunk's silhouette is
        // its texture's alpha, which the simplifier (positions only) never sees: a level would
        // drag the texture coordinates, and with them the holes of a fence or the outline of a
        // leaf, across the surface. A blended chunk is ordered back to front as a whole and
        // writes no depth, so its triangles are never sorted among themselves: a coarser level
        // that folds triangles over one another would blend them twice, in no defined order.
        if (chunk.alpha_mode != AlphaMode::kOpaque) {
            ChunkLods& lods = chain.chunks.emplace_back();
            lods.first_level = static_cast<std::uint32_t>(chain.levels.size());
            continue;
        }
        build_chunk_levels(chunk_mesh(scene, chunk), chain);
    }
    return chain;
}

// Appends part (built after `into`'s chunks) with its offsets moved past into's.
void append(LodChain& into, const LodChain& part) {
    const auto index_base = static_cast<std::uint32_t>(into.indices.size());
    const auto level_base = static_cast<std::uint32_t>(into.levels.size());
    into.indices.insert(into.indices.end(), part.indices.begin(), part.indices.end());
    for (LodLevel level : part.levels) {
        level.first_index += index_base;
        into.levels.push_back(level);
    }
    for (ChunkLods lods : part.chunks) {
        lods.first_level += level_base;
        into.chunks.push_back(lods);
    }
}

}  // namespace

LodChain build_lod_chain(const Scene& scene) {
    // Chunks simplify independently: one contiguous range per hardware thread, joined in chunk
    // order, so the chain is the same whatever the number of threads.
    const std::size_t count = scene.chunks.size();
    const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1,
                                                        std::max<std::size_t>(count / 64, 1));
    std::vector<LodChain> parts(threads);
    std::vector<std::thread> workers;
    for (std::size_t t = 0; t < threads; ++t) {
        workers.emplace_back([&, t] {
            parts[t] = build_range(scene, count * t / threads, count * (t + 1) / threads);
        });
    }
    for (std::thread& worker : workers) worker.join();
    LodChain chain;
    for (const LodChain& part : parts) append(chain, part);
    return chain;
}

}  // namespace monoplane::scenes
