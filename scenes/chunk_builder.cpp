#include "scenes/chunk_builder.h"

#include <algorithm>
#include <limits>
#include <numeric>

#include <glm/geometric.hpp>

#include "common/programming_error.h"

namespace monoplane::scenes {

Aabb bounds_of(const Vertex* vertices, std::size_t count) {
    Aabb box{glm::vec3(std::numeric_limits<float>::max()),
             glm::vec3(std::numeric_limits<float>::lowest())};
    for (std::size_t i = 0; i < count; ++i) {
        box.min = glm::min(box.min, vertices[i].position);
        box.max = glm::max(box.max, vertices[i].position);
    }
    return box;
}

Aabb merge(const Aabb& a, const Aabb& b) {
    return {glm::min(a.min, b.min), glm::max(a.max, b.max)};
}

ChunkBuilder::ChunkBuilder(std::uint32_t target_max_triangles)
    : target_max_triangles_(std::min(target_max_triangles, kMaxChunkTriangles)) {
    MONOPLANE_EXPECTS(target_max_triangles_ > 0);
}

void ChunkBuilder::begin_piece(std::uint32_t flags) {
    close_piece();
    Piece piece;
    piece.flags = flags;
    piece.first_vertex = static_cast<std::uint32_t>(vertices_.size());
    piece.first_index = static_cast<std::uint32_t>(indices_.size());
    pieces_.push_back(piece);
    piece_open_ = true;
}

std::uint32_t ChunkBuilder::piece_vertex_count() const {
    MONOPLANE_EXPECTS(piece_open_);
    return static_cast<std::uint32_t>(vertices_.size()) - pieces_.back().first_vertex;
}

std::uint32_t ChunkBuilder::add_vertex(const Vertex& vertex) {
    const std::uint32_t index = piece_vertex_count();
    vertices_.push_back(vertex);
    return index;
}

void ChunkBuilder::add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    MONOPLANE_EXPECTS(piece_open_);
    const std::uint32_t base = pieces_.back().first_vertex;
    MONOPLANE_EXPECTS(base + std::max({a, b, c}) < vertices_.size());
    const Vertex& va = vertices_[base + a];
    const Vertex& vb = vertices_[base + b];
    const Vertex& vc = vertices_[base + c];
    const glm::vec3 face = glm::cross(vb.position - va.position, vc.position - va.position);
    const glm::vec3 normal = va.normal + vb.normal + vc.normal;
    if (glm::dot(face, normal) < 0.0f) std::swap(b, c);
    indices_.insert(indices_.end(), {a, b, c});
}

void ChunkBuilder::close_piece() {
    if (!piece_open_) return;
    piece_open_ = false;
    Piece& piece = pieces_.back();
    piece.vertex_count = static_cast<std::uint32_t>(vertices_.size()) - piece.first_vertex;
    piece.index_count = static_cast<std::uint32_t>(indices_.size()) - piece.first_index;
    MONOPLANE_EXPECTS(piece.index_count / 3 <= kMaxChunkTriangles);
    if (piece.index_count == 0) {  // nothing to draw: forget its vertices too
        vertices_.resize(piece.first_vertex);
        pieces_.pop_back();
        return;
    }
    const Aabb box = bounds_of(vertices_.data() + piece.first_vertex, piece.vertex_count);
    piece.centre = 0.5f * (box.min + box.max);
}

void ChunkBuilder::split(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end,
                         std::vector<std::vector<std::uint32_t>>& groups) const {
    std::uint64_t triangles = 0;
    glm::vec3 low(std::numeric_limits<float>::max());
    glm::vec3 high(std::numeric_limits<float>::lowest());
    for (std::size_t i = begin; i < end; ++i) {
        const Piece& piece = pieces_[order[i]];
        triangles += piece.index_count / 3;
        low = glm::min(low, piece.centre);
        high = glm::max(high, piece.centre);
    }
    if (triangles <= target_max_triangles_ || end - begin == 1) {
        groups.emplace_back(order.begin() + static_cast<std::ptrdiff_t>(begin),
                            order.begin() + static_cast<std::ptrdiff_t>(end));
        return;
    }
    const glm::vec3 extent = high - low;
    const int axis =
        extent.x >= extent.y && extent.x >= extent.z ? 0 : (extent.y >= extent.z ? 1 : 2);
    // A full sort with the piece number as tie-break: std::nth_element's order of equal keys is
    // unspecified, and the chunking must be the same on every standard library.
    std::sort(order.begin() + static_cast<std::ptrdiff_t>(begin),
              order.begin() + static_cast<std::ptrdiff_t>(end),
              [&](std::uint32_t a, std::uint32_t b) {
                  const float ka = pieces_[a].centre[axis];
                  const float kb = pieces_[b].centre[axis];
                  return ka < kb || (ka == kb && a < b);
              });
    // Split where half of the triangles lie on each side.
    std::uint64_t running = 0;
    std::size_t middle = begin;
    while (middle < end - 1 &&
           2 * (running + pieces_[order[middle]].index_count / 3) <= triangles) {
        running += pieces_[order[middle]].index_count / 3;
        ++middle;
    }
    middle = std::clamp(middle, begin + 1, end - 1);
    split(order, begin, middle, groups);
    split(order, middle, end, groups);
}

void ChunkBuilder::emit_chunk(const std::vector<std::uint32_t>& group, Scene& scene) const {
    Chunk chunk;
    chunk.first_index = static_cast<std::uint32_t>(scene.indices.size());
    chunk.vertex_offset = static_cast<std::int32_t>(scene.vertices.size());
    std::uint32_t chunk_vertices = 0;
    for (const std::uint32_t piece_number : group) {
        const Piece& piece = pieces_[piece_number];
        scene.vertices.insert(scene.vertices.end(), vertices_.begin() + piece.first_vertex,
                              vertices_.begin() + piece.first_vertex + piece.vertex_count);
        for (std::uint32_t i = 0; i < piece.index_count; ++i) {
            scene.indices.push_back(chunk_vertices + indices_[piece.first_index + i]);
        }
        chunk_vertices += piece.vertex_count;
    }
    chunk.index_count = static_cast<std::uint32_t>(scene.indices.size()) - chunk.first_index;
    chunk.bounds = bounds_of(scene.vertices.data() + chunk.vertex_offset, chunk_vertices);
    chunk.flags = pieces_[group.front()].flags;
    scene.chunks.push_back(chunk);
}

void ChunkBuilder::build_into(Scene& scene) {
    close_piece();
    std::vector<std::uint32_t> order(pieces_.size());
    std::iota(order.begin(), order.end(), 0u);
    // Pieces with different routing flags never share a chunk: group them by flags first.
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
        return pieces_[a].flags < pieces_[b].flags;
    });
    std::vector<std::vector<std::uint32_t>> groups;
    for (std::size_t begin = 0; begin < order.size();) {
        std::size_t end = begin;
        while (end < order.size() && pieces_[order[end]].flags == pieces_[order[begin]].flags) {
            ++end;
        }
        split(order, begin, end, groups);
        begin = end;
    }

    scene.vertices.clear();
    scene.indices.clear();
    scene.chunks.clear();
    scene.vertices.reserve(vertices_.size());
    scene.indices.reserve(indices_.size());
    for (const auto& group : groups) emit_chunk(group, scene);

    scene.bounds = Aabb{};
    if (!scene.chunks.empty()) {
        scene.bounds = scene.chunks.front().bounds;
        for (const Chunk& chunk : scene.chunks) scene.bounds = merge(scene.bounds, chunk.bounds);
    }
    vertices_ = {};
    indices_ = {};
    pieces_ = {};
}

}  // namespace monoplane::scenes
