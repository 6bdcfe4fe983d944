// Device memory: one allocation per buffer or image, or one shared by a renderer's transient
// images whose lifetimes within a frame do not overlap (vk_core::AliasedMemory, planned by
// graph::plan_aliasing). Every allocation is counted while it lives, by what it holds (images or
// buffers), so a run can say how much device memory it holds (`render --json`'s and bench.json's
// "device_memory"; a study's renderers share each scene's geometry: study run prints the figure).
#pragma once

#include <cstddef>
#include <cstdint>

#include "renderer/vk/context.h"

namespace monoplane::vk_core {

// What an allocation holds, for the counts.
enum class MemoryKind : std::uint8_t { kImage, kBuffer };

// An allocation whose size counts in live_device_bytes() until it is freed (or moved from).
class DeviceMemory {
  public:
    DeviceMemory() = default;
    DeviceMemory(std::nullptr_t) {}  // NOLINT(google-explicit-constructor): like vk::raii
    DeviceMemory(vk::raii::DeviceMemory memory, vk::DeviceSize bytes,
                 MemoryKind kind = MemoryKind::kImage);
    DeviceMemory(DeviceMemory&& other) noexcept;
    DeviceMemory& operator=(DeviceMemory&& other) noexcept;
    DeviceMemory(const DeviceMemory&) = delete;
    DeviceMemory& operator=(const DeviceMemory&) = delete;
    ~DeviceMemory();

    vk::DeviceMemory operator*() const { return *memory_; }
    void* map() const { return memory_.mapMemory(0, VK_WHOLE_SIZE); }
    vk::DeviceSize bytes() const { return bytes_; }

  private:
    void release();

    vk::raii::DeviceMemory memory_{nullptr};
    vk::DeviceSize bytes_ = 0;
    MemoryKind kind_ = MemoryKind::kImage;
};

// May be called once the resource exists; throws vk::SystemError if no memory type fits. `kind`
// says what the memory will hold (images unless told: buffers allocate through vk_core::Buffer).
DeviceMemory allocate_memory(const Context& ctx, const vk::MemoryRequirements& needs,
                             vk::MemoryPropertyFlags properties,
                             MemoryKind kind = MemoryKind::kImage);

// The bytes of every DeviceMemory alive in this process, over all contexts. Any thread.
std::uint64_t live_device_bytes();
// The same, of the allocations that hold images, and of those that hold buffers.
std::uint64_t live_device_bytes(MemoryKind kind);

}  // namespace monoplane::vk_core
