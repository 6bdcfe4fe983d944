#include "renderer/passes/shared/indirect_draws.h"

namespace monoplane::passes {

void with_predicate(const vk::raii::CommandBuffer& cmd, const std::optional<Predicate>& predicate,
                    const std::function<void()>& commands) {
    if (!predicate) {
        commands();
        return;
    }
    vk::ConditionalRenderingFlagsEXT flags;
    if (predicate->inverted) flags = vk::ConditionalRenderingFlagBitsEXT::eInverted;
    cmd.beginConditionalRenderingEXT(
        vk::ConditionalRenderingBeginInfoEXT(predicate->buffer, predicate->offset, flags));
    commands();
    cmd.endConditionalRenderingEXT();
}

void IndirectDraws::record(const vk::raii::CommandBuffer& cmd) const {
    constexpr auto stride = static_cast<std::uint32_t>(sizeof(vk::DrawIndexedIndirectCommand));
    if (max_draws == 0) return;
    if (count) {
        cmd.drawIndexedIndirectCount(commands, commands_offset, count, count_offset, max_draws,
                                     stride);
    } else {
        cmd.drawIndexedIndirect(commands, commands_offset, max_draws, stride);
    }
}

}  // namespace monoplane::passes
