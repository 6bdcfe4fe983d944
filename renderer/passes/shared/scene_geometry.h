// A scene's geometry on the GPU and the indirect draw lists that select chunks of it.
#pragma once

#include <span>
#include <vector>

#include "renderer/passes/shared/indirect_draws.h"
#include "renderer/vk/buffer.h"
#include "scenes/lod_chain.h"
#include "scenes/scene.h"

namespace monoplane::passes {

// Vertex and index buffers of a scenes::Scene, uploaded once. The index buffer holds the
// scene's indices, then its levels of detail's (scenes/lod_chain.h).
class SceneGeometry {
  public:
    SceneGeometry(const vk_core::Context& ctx, const scenes::Scene& scene,
                  const scenes::LodChain& lods);

    void bind(const vk::raii::CommandBuffer& cmd) const;
    std::size_t chunk_count() const { return chunk_count_; }

    // The vertex layout of scenes::Vertex for pipelines that draw scene geometry.
    static std::vector<vk::VertexInputBindingDescription> vertex_bindings();
    static std::vector<vk::VertexInputAttributeDescription> vertex_attributes();
    // Only the position (location 0), for depth-only passes: fetching less is cheaper and
    // validation warns about attributes a shader does not consume.
    static std::vector<vk::VertexInputAttributeDescription> position_attribute();

  private:
    vk_core::Buffer vertices_;
    vk_core::Buffer indices_;
    std::size_t chunk_count_ = 0;
};

// Indirect draw commands written by the CPU, one per chunk drawn, in a host-visible buffer sized
// for all chunks: for lists that do not change per frame (the shadow map draws every chunk).
// Per-view lists are written by the GPU culling pass (renderer/passes/culling).
class DrawList {
  public:
    DrawList(const vk_core::Context& ctx, std::size_t max_draws);

    // Replaces the list with the given chunks (chunk indices into scene.chunks); each command's
    // first instance is its chunk's index.
    void assign(const scenes::Scene& scene, std::span<const std::uint32_t> chunk_indices);
    void draw(const vk::raii::CommandBuffer& cmd) const { indirect().record(cmd); }
    IndirectDraws indirect() const;
    std::uint32_t count() const { return count_; }

  private:
    vk_core::Buffer commands_;
    std::uint32_t count_ = 0;
    std::uint32_t max_draws_ = 0;
};

}  // namespace monoplane::passes
