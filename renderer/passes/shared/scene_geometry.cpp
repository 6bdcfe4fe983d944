#include "renderer/passes/shared/scene_geometry.h"

#include "common/programming_error.h"

namespace monoplane::passes {

namespace {

std::vector<std::uint32_t> all_indices(const scenes::Scene& scene, const scenes::LodChain& lods) {
    std::vector<std::uint32_t> indices;
    indices.reserve(scene.indices.size() + lods.indices.size());
    indices.insert(indices.end(), scene.indices.begin(), scene.indices.end());
    indices.insert(indices.end(), lods.indices.begin(), lods.indices.end());
    return indices;
}

}  // namespace

SceneGeometry::SceneGeometry(const vk_core::Context& ctx, const scenes::Scene& scene,
                             const scenes::LodChain& lods)
    : vertices_(vk_core::make_device_buffer(ctx, std::span(scene.vertices),
                                            vk::BufferUsageFlagBits::eVertexBuffer)),
      indices_(vk_core::make_device_buffer(ctx,
                                           std::span<const std::uint32_t>(all_indices(scene, lods)),
                                           vk::BufferUsageFlagBits::eIndexBuffer)),
      chunk_count_(scene.chunks.size()) {}

void SceneGeometry::bind(const vk::raii::CommandBuffer& cmd) const {
    cmd.bindVertexBuffers(0, vertices_.handle(), vk::DeviceSize{0});
    cmd.bindIndexBuffer(indices_.handle(), 0, vk::IndexType::eUint32);
}

std::vector<vk::VertexInputBindingDescription> SceneGeometry::vertex_bindings() {
    return {vk::VertexInputBindingDescription(0, sizeof(scenes::Vertex))};
}

std::vector<vk::VertexInputAttributeDescription> SceneGeometry::vertex_attributes() {
    using V = scenes::Vertex;
    return {
        {0, 0, vk::Format::eR32G32B32Sfloat, offsetof(V, position)},
        {1, 0, vk::Format::eR32G32B32Sfloat, offsetof(V, normal)},
        {2, 0, vk::Format::eR8G8B8A8Unorm, offsetof(V, albedo_rgba8)},
        {3, 0, vk::Format::eR32Uint, offsetof(V, material_packed)},
    };
}

std::vector<vk::VertexInputAttributeDescription> SceneGeometry::position_attribute() {
    return {vertex_attributes().front()};
}

DrawList::DrawList(const vk_core::Context& ctx, std::size_t max_draws)
    : commands_(ctx, std::max<std::size_t>(max_draws, 1) * sizeof(vk::DrawIndexedIndirectCommand),
                vk::BufferUsageFlagBits::eIndirectBuffer, vk_core::MemoryUse::kHostVisible),
      max_draws_(static_cast<std::uint32_t>(max_draws)) {}

void DrawList::assign(const scenes::Scene& scene, std::span<const std::uint32_t> chunk_indices) {
    MONOPLANE_EXPECTS(chunk_indices.size() <= max_draws_);
    auto* out = reinterpret_cast<vk::DrawIndexedIndirectCommand*>(commands_.mapped());
    for (std::size_t i = 0; i < chunk_indices.size(); ++i) {
        const scenes::Chunk& chunk = scene.chunks[chunk_indices[i]];
        // The first instance names the chunk, as the culling pass's commands do (shaders that
        // read per-chunk data, the alpha test's texture and cut-off, find it there).
        out[i] = vk::DrawIndexedIndirectCommand(chunk.index_count, 1, chunk.first_index,
                                                chunk.vertex_offset, chunk_indices[i]);
    }
    count_ = static_cast<std::uint32_t>(chunk_indices.size());
}

IndirectDraws DrawList::indirect() const {
    IndirectDraws draws;
    draws.commands = commands_.handle();
    draws.max_draws = count_;
    return draws;
}

}  // namespace monoplane::passes
