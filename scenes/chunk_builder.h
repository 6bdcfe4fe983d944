// Collects a scene's geometry as small pieces (one object, one beam section, one terrain tile)
// and groups nearby pieces into chunks of a bounded triangle count: the unit of culling and of
// indirect draws (the paper's Sect. 5 needs a fine-grained subdivision).
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/scene.h"

namespace monoplane::scenes {

// No chunk grows beyond this, whatever the detail level (the renderer's per-chunk limit).
inline constexpr std::uint32_t kMaxChunkTriangles = 8192;

class ChunkBuilder {
  public:
    // Chunks get at most target_max_triangles (<= kMaxChunkTriangles) unless one piece is larger.
    explicit ChunkBuilder(std::uint32_t target_max_triangles);

    // Starts a piece: the vertices and triangles added until the next begin_piece() stay together
    // in one chunk. A piece has at most kMaxChunkTriangles triangles. Chunks group only pieces
    // with the same ChunkFlags.
    void begin_piece(std::uint32_t flags = kChunkNone);
    // Returns the vertex's index within the current piece.
    std::uint32_t add_vertex(const Vertex& vertex);
    // Indices within the current piece. The triangle is wound counter-clockwise about the mean of
    // its vertex normals (scene.h), whatever order the primitive passes them in.
    void add_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c);
    void add_quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        add_triangle(a, b, c);
        add_triangle(a, c, d);
    }
    std::uint32_t piece_vertex_count() const;
    std::size_t triangle_count() const { return indices_.size() / 3; }

    // Groups the pieces spatially (a triangle-weighted k-d split of piece centres) and writes
    // scene.vertices, indices, chunks and bounds. The builder is empty afterwards.
    void build_into(Scene& scene);

  private:
    struct Piece {
        std::uint32_t first_vertex = 0;
        std::uint32_t vertex_count = 0;
        std::uint32_t first_index = 0;
        std::uint32_t index_count = 0;
        glm::vec3 centre{0.0f};
        std::uint32_t flags = kChunkNone;
    };
    void close_piece();
    void split(std::vector<std::uint32_t>& order, std::size_t begin, std::size_t end,
               std::vector<std::vector<std::uint32_t>>& groups) const;
    void emit_chunk(const std::vector<std::uint32_t>& group, Scene& scene) const;

    std::uint32_t target_max_triangles_;
    std::vector<Vertex> vertices_;
    std::vector<std::uint32_t> indices_;  // piece-relative
    std::vector<Piece> pieces_;
    bool piece_open_ = false;
};

// A tight box around the vertices, for chunks and tests.
Aabb bounds_of(const Vertex* vertices, std::size_t count);
Aabb merge(const Aabb& a, const Aabb& b);

}  // namespace monoplane::scenes
