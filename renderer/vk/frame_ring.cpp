#include "renderer/vk/frame_ring.h"

namespace monoplane::vk_core {

FrameRing::FrameRing(const Context& ctx) : ctx_(ctx) {
    pool_ = vk::raii::CommandPool(
        ctx.device(), vk::CommandPoolCreateInfo(vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                ctx.queue_family()));
    vk::raii::CommandBuffers buffers(
        ctx.device(),
        vk::CommandBufferAllocateInfo(*pool_, vk::CommandBufferLevel::ePrimary, kFramesInFlight));
    for (std::uint32_t i = 0; i < kFramesInFlight; ++i) {
        slots_[i].commands = std::move(buffers[i]);
        slots_[i].fence = vk::raii::Fence(ctx.device(), vk::FenceCreateInfo());
    }
}

FrameRing::~FrameRing() {
    try {
        wait_all();
    } catch (const vk::SystemError&) {
        // The device is lost: nothing in flight will complete, and nothing waits for it.
    }
}

void FrameRing::wait(std::uint32_t slot) {
    Slot& s = slots_[slot];
    if (!s.in_flight) return;
    // A frame on llvmpipe at benchmark resolutions can take seconds: wait without a deadline.
    while (ctx_.device().waitForFences(*s.fence, VK_TRUE, UINT64_MAX) == vk::Result::eTimeout) {
    }
    ctx_.device().resetFences(*s.fence);
    s.in_flight = false;
}

void FrameRing::wait_all() {
    // next_ holds the oldest submission of a full ring.
    for (std::uint32_t i = 0; i < kFramesInFlight; ++i) wait((next_ + i) % kFramesInFlight);
}

std::uint32_t FrameRing::begin() {
    const std::uint32_t slot = next_;
    wait(slot);
    const vk::raii::CommandBuffer& cmd = slots_[slot].commands;
    cmd.reset();
    cmd.begin(vk::CommandBufferBeginInfo(vk::CommandBufferUsageFlagBits::eOneTimeSubmit));
    // Everything earlier on the queue (the last frame included) before anything of this frame:
    // images and buffers shared between frames need no other synchronisation.
    using Stage = vk::PipelineStageFlagBits2;
    using Access = vk::AccessFlagBits2;
    const vk::MemoryBarrier2 barrier(Stage::eAllCommands, Access::eMemoryWrite, Stage::eAllCommands,
                                     Access::eMemoryRead | Access::eMemoryWrite);
    cmd.pipelineBarrier2(vk::DependencyInfo({}, barrier));
    return slot;
}

void FrameRing::submit(std::uint32_t slot) {
    Slot& s = slots_[slot];
    s.commands.end();
    const vk::CommandBufferSubmitInfo cmd_info(*s.commands);
    ctx_.queue().submit2(vk::SubmitInfo2({}, {}, cmd_info, {}), *s.fence);
    s.in_flight = true;
    next_ = (slot + 1) % kFramesInFlight;
}

}  // namespace monoplane::vk_core
