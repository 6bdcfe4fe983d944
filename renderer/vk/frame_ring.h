// Frames in flight: a ring of command buffers, each with the fence of its last submission, so
// that the host records frame n+1 while the GPU still runs frame n. Whoever records into a slot
// keeps per-slot copies of everything the host reads after a frame (query results, read-back
// counts); what the host writes for a frame rides in the frame's command buffer (FrameUploads),
// so no host-written buffer is shared by two frames in flight.
//
// Ordering: begin() records one full memory barrier first, so each frame's commands start after
// every earlier submission's writes on the queue (frames overlap on the host, not on the GPU);
// images and buffers may therefore be shared between frames without per-slot copies.
//
// Resources an in-flight frame uses must not be destroyed or have their descriptor sets rewritten
// until the frame has completed: wait_all() first (renderers do so before a rare reallocation).
// When may this be called: from one thread at a time; the Context must outlive the ring.
#pragma once

#include <array>
#include <cstdint>

#include "renderer/vk/context.h"

namespace monoplane::vk_core {

class FrameRing {
  public:
    static constexpr std::uint32_t kFramesInFlight = 2;

    explicit FrameRing(const Context& ctx);
    FrameRing(const FrameRing&) = delete;
    FrameRing& operator=(const FrameRing&) = delete;
    // Waits for every frame in flight: their command buffers and what they use stay valid.
    ~FrameRing();

    // The slot the next begin() records into. Its previous frame may still be in flight: the
    // caller collects that frame (wait(), then its per-slot results) before begin().
    std::uint32_t next_slot() const { return next_; }
    bool in_flight(std::uint32_t slot) const { return slots_[slot].in_flight; }
    // Waits for the slot's submitted frame (no-op when none is in flight).
    void wait(std::uint32_t slot);
    // wait() for every slot, oldest frame first.
    void wait_all();

    // Begins recording the next slot (waiting for its previous frame if the caller has not):
    // resets its command buffer, records the frame-start barrier. Returns the slot.
    std::uint32_t begin();
    const vk::raii::CommandBuffer& commands(std::uint32_t slot) const {
        return slots_[slot].commands;
    }
    // Ends and submits the slot begun last, without waiting.
    void submit(std::uint32_t slot);

  private:
    struct Slot {
        vk::raii::CommandBuffer commands{nullptr};
        vk::raii::Fence fence{nullptr};
        bool in_flight = false;
    };
    const Context& ctx_;
    vk::raii::CommandPool pool_{nullptr};
    std::array<Slot, kFramesInFlight> slots_;
    std::uint32_t next_ = 0;
};

}  // namespace monoplane::vk_core
