// The host's per-frame data for device buffers (view constants, culling planes, draw order),
// carried inside the frame's command buffer (vkCmdUpdateBuffer) instead of written through a
// mapping: with frames in flight (frame_ring.h) the host fills frame n+1's values while the GPU
// still reads frame n's from the same buffer, and each frame reads its own.
// The previous frame's reads of those buffers come before the updates through FrameRing::begin's
// barrier. When may this be called: stage() between frames; record() once per frame, outside any
// render pass, before the first command that reads the buffers.
#pragma once

#include <cstddef>
#include <vector>

#include "renderer/vk/buffer.h"

namespace monoplane::vk_core {

class FrameUploads {
  public:
    // Copies `bytes` (a multiple of 4, at an offset that is one) for `target`, a buffer made
    // with transfer-destination usage (every kDeviceLocal buffer has it). A later stage() of
    // the same range in the same frame wins, as a second write would.
    void stage(const Buffer& target, const void* data, vk::DeviceSize bytes,
               vk::DeviceSize offset = 0);
    // Records the staged updates with a barrier that makes them visible to every later read
    // (uniform, storage, indirect), and forgets them.
    void record(const vk::raii::CommandBuffer& cmd);
    bool empty() const { return updates_.empty(); }

  private:
    struct Update {
        vk::Buffer target;
        vk::DeviceSize offset;
        std::size_t first;  // in bytes_
        std::size_t size;
    };
    std::vector<Update> updates_;
    std::vector<std::byte> bytes_;
};

}  // namespace monoplane::vk_core
