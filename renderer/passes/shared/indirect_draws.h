// Draws and passes whose extent the GPU decides: indirect draw commands with a GPU-written count,
// and predicates (VK_EXT_conditional_rendering) that skip commands when the GPU culling left
// nothing for them. Together they let one command buffer serve every culling outcome without a
// round trip to the CPU (papers/000 Sect. 4.4).
#pragma once

#include <cstdint>
#include <functional>
#include <optional>

#include "renderer/vk/vulkan.h"

namespace monoplane::passes {

// The commands recorded under a predicate run when the 32-bit value at buffer + offset is
// non-zero (inverted: when it is zero).
struct Predicate {
    vk::Buffer buffer;
    vk::DeviceSize offset = 0;
    bool inverted = false;
};

// Records `commands` inside conditional rendering when a predicate is given, plainly otherwise.
void with_predicate(const vk::raii::CommandBuffer& cmd, const std::optional<Predicate>& predicate,
                    const std::function<void()>& commands);

// A list of vk::DrawIndexedIndirectCommand and, when `count` is set, a GPU-written number of
// them (vkCmdDrawIndexedIndirectCount); without `count` all max_draws are drawn.
struct IndirectDraws {
    vk::Buffer commands;
    vk::DeviceSize commands_offset = 0;
    vk::Buffer count;
    vk::DeviceSize count_offset = 0;
    std::uint32_t max_draws = 0;

    void record(const vk::raii::CommandBuffer& cmd) const;
};

// A view's chunk list by alpha class (scenes::AlphaMode): what a forward pass draws with each of
// its pipelines (the culling pass writes them, renderer/passes/culling).
struct ChunkDraws {
    IndirectDraws opaque;
    IndirectDraws masked;
    IndirectDraws blended;  // back to front (the frame's draw order, modes::draw_order)
};

}  // namespace monoplane::passes
