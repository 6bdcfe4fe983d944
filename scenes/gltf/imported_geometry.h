// World-space triangles collected from a glTF scene's mesh instances, before chunking
// (chunk_assembly.h): one batch per primitive instance, so that a batch has one texture and one
// alpha mode.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

#include "scenes/scene.h"

namespace monoplane::scenes::gltf {

struct GeometryBatch {
    std::size_t first_vertex = 0;  // into ImportedGeometry::vertices
    std::uint32_t vertex_count = 0;
    std::size_t first_index = 0;  // into ImportedGeometry::indices, values batch-relative
    std::size_t index_count = 0;
    std::int32_t texture = -1;                  // Scene::textures index, or -1
    AlphaMode alpha_mode = AlphaMode::kOpaque;  // the material's (Chunk::alpha_mode)
    float alpha_cutoff = 0.5f;                  // kMask only (Chunk::alpha_cutoff)
};

struct ImportedGeometry {
    // Triangles wind counter-clockwise about their vertex normals already (scene.h).
    std::vector<Vertex> vertices;
    std::vector<glm::vec2> texcoords;  // parallel to vertices; (0, 0) where untextured
    std::vector<std::uint32_t> indices;
    std::vector<GeometryBatch> batches;

    std::size_t triangle_count() const { return indices.size() / 3; }
};

}  // namespace monoplane::scenes::gltf
