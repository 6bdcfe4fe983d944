#include "renderer/passes/culling/chunk_lists.h"

#include <algorithm>

#include <cstring>

#include <glm/geometric.hpp>

#include "common/programming_error.h"

namespace monoplane::passes {
namespace {

constexpr vk::DeviceSize kCommandSize = sizeof(vk::DrawIndexedIndirectCommand);

template <typename T>
std::uint32_t bits_of(T value) {
    static_assert(sizeof(T) == sizeof(std::uint32_t));
    std::uint32_t bits = 0;
    std::memcpy(&bits, &value, sizeof(bits));
    return bits;
}

std::uint32_t alpha_class(const scenes::Chunk& chunk) {
    switch (chunk.alpha_mode) {
        case scenes::AlphaMode::kOpaque:
            return MONOPLANE_CLASS_OPAQUE;
        case scenes::AlphaMode::kMask:
            return MONOPLANE_CLASS_MASKED;
        case scenes::AlphaMode::kBlend:
            return MONOPLANE_CLASS_BLENDED;
    }
    return MONOPLANE_CLASS_OPAQUE;
}

std::vector<ChunkRecord> chunk_records(const scenes::Scene& scene, const scenes::LodChain& lods) {
    std::vector<ChunkRecord> records;
    records.reserve(scene.chunks.size());
    std::uint32_t first_level = 0;
    for (std::size_t c = 0; c < scene.chunks.size(); ++c) {
        const scenes::Chunk& chunk = scene.chunks[c];
        const std::uint32_t level_count = 1 + lods.chunks.at(c).level_count;
        records.push_back(
            {glm::vec4(chunk.bounds.min, 0.0f), glm::vec4(chunk.bounds.max, 0.0f),
             glm::uvec4(chunk.index_count, chunk.first_index, bits_of(chunk.vertex_offset),
                        chunk.flags | (alpha_class(chunk) << MONOPLANE_CHUNK_CLASS_SHIFT)),
             glm::uvec4(first_level, level_count, 0u, 0u)});
        first_level += level_count;
    }
    if (records.empty()) records.push_back({});  // buffers may not be empty
    return records;
}

// Per chunk its level 0 (the chunk itself), then the chain's levels, in chunk_records' order.
std::vector<LodRecord> level_records(const scenes::Scene& scene, const scenes::LodChain& lods) {
    const auto chain_base = static_cast<std::uint32_t>(scene.indices.size());
    std::vector<LodRecord> records;
    for (std::size_t c = 0; c < scene.chunks.size(); ++c) {
        const scenes::Chunk& chunk = scene.chunks[c];
        records.push_back({glm::uvec4(chunk.index_count, chunk.first_index, bits_of(0.0f), 0u)});
        const scenes::ChunkLods& chain = lods.chunks.at(c);
        for (std::uint32_t l = 0; l < chain.level_count; ++l) {
            const scenes::LodLevel& level = lods.levels.at(chain.first_level + l);
            records.push_back({glm::uvec4(level.index_count, chain_base + level.first_index,
                                          bits_of(level.error_m), 0u)});
        }
    }
    if (records.empty()) records.push_back({});
    return records;
}

// The six planes of a reversed-Z clip space 0 <= z <= w (Gribb and Hartmann), normalised in
// double precision before they become floats.
void write_planes(const glm::dmat4& view_proj, vec4* out) {
    const glm::dmat4 t = glm::transpose(view_proj);  // t[i] is row i of view_proj
    const std::array<glm::dvec4, 6> planes = {t[3] + t[0], t[3] - t[0], t[3] + t[1],
                                              t[3] - t[1], t[2],        t[3] - t[2]};
    for (std::size_t i = 0; i < planes.size(); ++i) {
        const double length = glm::length(glm::dvec3(planes[i]));
        out[i] = glm::vec4(length > 0.0 ? planes[i] / length : planes[i]);
    }
}

}  // namespace

std::array<std::uint32_t, MONOPLANE_CLASSES> ChunkLists::class_sizes(const scenes::Scene& scene) {
    std::array<std::uint32_t, MONOPLANE_CLASSES> sizes{};
    for (const scenes::Chunk& chunk : scene.chunks) ++sizes.at(alpha_class(chunk));
    return sizes;
}

std::uint32_t ChunkLists::class_base(std::uint32_t alpha_class) const {
    std::uint32_t base = 0;
    for (std::uint32_t c = 0; c < alpha_class; ++c) base += class_sizes_.at(c);
    return base;
}

vk_core::Buffer ChunkLists::make_chunk_table(const vk_core::Context& ctx,
                                             const scenes::Scene& scene,
                                             const scenes::LodChain& lods) {
    return vk_core::make_device_buffer(ctx,
                                       std::span<const ChunkRecord>(chunk_records(scene, lods)),
                                       vk::BufferUsageFlagBits::eStorageBuffer);
}

vk_core::Buffer ChunkLists::make_level_table(const vk_core::Context& ctx,
                                             const scenes::Scene& scene,
                                             const scenes::LodChain& lods) {
    return vk_core::make_device_buffer(ctx, std::span<const LodRecord>(level_records(scene, lods)),
                                       vk::BufferUsageFlagBits::eStorageBuffer);
}

ChunkLists::ChunkLists(const vk_core::Context& ctx, const scenes::Scene& scene,
                       const vk_core::Buffer& chunk_table, const vk_core::Buffer& level_table)
    : chunk_count_(static_cast<std::uint32_t>(scene.chunks.size())),
      class_sizes_(class_sizes(scene)),
      chunks_(chunk_table),
      levels_(level_table),
      // Level 0 for every chunk and group until the first frame chooses.
      lod_state_(vk_core::make_device_buffer(
          ctx,
          std::span<const std::uint32_t>(std::vector<std::uint32_t>(
              std::size_t{std::max(chunk_count_, 1u)} * MONOPLANE_LOD_GROUPS, 0u)),
          vk::BufferUsageFlagBits::eStorageBuffer)),
      commands_(ctx,
                vk::DeviceSize{MONOPLANE_CULL_LISTS} * std::max(chunk_count_, 1u) * kCommandSize,
                vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eIndirectBuffer |
                    vk::BufferUsageFlagBits::eTransferSrc,
                vk_core::MemoryUse::kDeviceLocal),
      counts_(ctx, MONOPLANE_COUNT_WORDS * sizeof(std::uint32_t),
              vk::BufferUsageFlagBits::eStorageBuffer | vk::BufferUsageFlagBits::eIndirectBuffer |
                  vk::BufferUsageFlagBits::eConditionalRenderingEXT |
                  vk::BufferUsageFlagBits::eTransferSrc,
              vk_core::MemoryUse::kDeviceLocal),
      routing_(ctx, vk::DeviceSize{std::max(chunk_count_, 1u)} * sizeof(std::uint32_t),
               vk::BufferUsageFlagBits::eStorageBuffer, vk_core::MemoryUse::kDeviceLocal),
      order_(ctx, vk::DeviceSize{std::max(chunk_count_, 1u)} * sizeof(std::uint32_t),
             vk::BufferUsageFlagBits::eStorageBuffer, vk_core::MemoryUse::kDeviceLocal),
      constants_(ctx, sizeof(CullConstants), vk::BufferUsageFlagBits::eStorageBuffer,
                 vk_core::MemoryUse::kDeviceLocal),
      commands_readback_(ctx, commands_.size(), vk::BufferUsageFlagBits::eTransferDst,
                         vk_core::MemoryUse::kHostVisible) {
    for (vk_core::Buffer& readback : counts_readback_) {
        readback = vk_core::Buffer(ctx, counts_.size(), vk::BufferUsageFlagBits::eTransferDst,
                                   vk_core::MemoryUse::kHostVisible);
    }
}

void ChunkLists::set_frame(const CullFrame& frame, vk_core::FrameUploads& uploads) {
    CullConstants c{};
    std::uint32_t views = 0;
    for (std::uint32_t v = 0; v < MONOPLANE_CULL_VIEWS; ++v) {
        if (!frame.view_proj[v]) continue;
        views |= 1u << v;
        write_planes(*frame.view_proj[v], &c.planes[std::size_t{v} * 6]);
    }
    std::uint32_t honour = 0;
    if (frame.honour_force_mono) honour |= MONOPLANE_CULL_HONOUR_FORCE_MONO;
    if (frame.honour_force_stereo) honour |= MONOPLANE_CULL_HONOUR_FORCE_STEREO;
    if (frame.split_blended) honour |= MONOPLANE_CULL_SPLIT_BLENDED;
    c.config = glm::uvec4(chunk_count_, views, frame.both_eyes_instances, honour);
    if (frame.view_proj[MONOPLANE_CULL_MONO]) {
        c.mono_view_proj = glm::mat4(*frame.view_proj[MONOPLANE_CULL_MONO]);
    }
    c.occlusion = glm::vec4(
        static_cast<float>(frame.mono_viewport.x), static_cast<float>(frame.mono_viewport.y),
        static_cast<float>(frame.hidden_depth_threshold), static_cast<float>(frame.pyramid_mips));
    for (std::size_t v = 0; v < frame.lod_views.size(); ++v) {
        const plan::LodView& lod = frame.lod_views[v];
        c.lod_views[2 * v] = glm::vec4(glm::vec3(lod.position), lod.pixels_per_tangent);
        c.lod_views[2 * v + 1] = glm::vec4(glm::vec3(lod.forward), lod.max_tangent_squared);
    }
    c.lod = glm::vec4(static_cast<float>(frame.lod_error_px),
                      static_cast<float>(plan::kLodCoarsenFraction), 0.0f, 0.0f);
    c.classes = glm::uvec4(class_base(MONOPLANE_CLASS_OPAQUE), class_base(MONOPLANE_CLASS_MASKED),
                           class_base(MONOPLANE_CLASS_BLENDED), 0u);
    uploads.stage(constants_, &c, sizeof(c));
}

void ChunkLists::set_draw_order(std::span<const std::uint32_t> order,
                                vk_core::FrameUploads& uploads) {
    // The draw order is a permutation of the chunks.
    MONOPLANE_EXPECTS(order.size() == chunk_count_);
    if (!order.empty()) uploads.stage(order_, order.data(), order.size_bytes());
}

IndirectDraws ChunkLists::draws(CullView view, std::uint32_t alpha_class) const {
    const auto v = static_cast<std::uint32_t>(view);
    IndirectDraws draws;
    draws.commands = commands_.handle();
    draws.commands_offset =
        (vk::DeviceSize{v} * chunk_count_ + class_base(alpha_class)) * kCommandSize;
    draws.count = counts_.handle();
    draws.count_offset = vk::DeviceSize{count_word(v, alpha_class)} * sizeof(std::uint32_t);
    draws.max_draws = class_sizes_.at(alpha_class);
    return draws;
}

ChunkDraws ChunkLists::chunk_draws(CullView view) const {
    return {draws(view, MONOPLANE_CLASS_OPAQUE), draws(view, MONOPLANE_CLASS_MASKED),
            draws(view, MONOPLANE_CLASS_BLENDED)};
}

std::uint32_t ChunkLists::count_word(std::uint32_t list, std::uint32_t alpha_class) {
    return MONOPLANE_COUNT_WORD(list, alpha_class);
}

Predicate ChunkLists::predicate(std::uint32_t word, bool inverted) const {
    return {counts_.handle(), vk::DeviceSize{word} * sizeof(std::uint32_t), inverted};
}

std::array<std::uint32_t, MONOPLANE_COUNT_WORDS> ChunkLists::counts(std::uint32_t slot) const {
    std::array<std::uint32_t, MONOPLANE_COUNT_WORDS> values{};
    std::memcpy(values.data(), counts_readback_.at(slot).mapped(), sizeof(values));
    return values;
}

std::vector<vk::DrawIndexedIndirectCommand> ChunkLists::drawn_commands(CullView view,
                                                                       std::uint32_t slot) const {
    const auto v = static_cast<std::uint32_t>(view);
    const std::array<std::uint32_t, MONOPLANE_COUNT_WORDS> words = counts(slot);
    const auto* list =
        reinterpret_cast<const vk::DrawIndexedIndirectCommand*>(commands_readback_.mapped()) +
        std::size_t{v} * chunk_count_;
    std::vector<vk::DrawIndexedIndirectCommand> commands;
    for (std::uint32_t c = 0; c < MONOPLANE_CLASSES; ++c) {
        const auto* first = list + class_base(c);
        commands.insert(commands.end(), first, first + words.at(count_word(v, c)));
    }
    return commands;
}

std::vector<std::uint32_t> ChunkLists::drawn_chunks(CullView view, std::uint32_t slot) const {
    std::vector<std::uint32_t> chunks;
    for (const vk::DrawIndexedIndirectCommand& command : drawn_commands(view, slot)) {
        chunks.push_back(command.firstInstance);
    }
    return chunks;
}

}  // namespace monoplane::passes
