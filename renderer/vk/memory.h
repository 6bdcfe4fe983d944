// Device memory: one dedicated allocation per buffer or image. monoplane creates few, large
// resources once per run, so a sub-allocator would add complexity without saving anything. Every
// allocation is counted while it lives, so a run can say how much device memory it holds (a
// study's renderers share each scene's geometry: study run prints the figure).
#pragma once

#include <cstddef>
#include <cstdint>

#include "renderer/vk/context.h"

namespace monoplane::vk_core {

// An allocation whose size counts in live_device_bytes() until it is freed (or moved from).
class DeviceMemory {
  public:
    DeviceMemory() = default;
    DeviceMemory(std::nullptr_t) {}  // NOLINT(google-explicit-constructor): like vk::raii
    DeviceMemory(vk::raii::DeviceMemory memory, vk::DeviceSize bytes);
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
};

// May be called once the resource exists; throws vk::SystemError if no memory type fits.
DeviceMemory allocate_memory(const Context& ctx, const vk::MemoryRequirements& needs,
                             vk::MemoryPropertyFlags properties);

// The bytes of every DeviceMemory alive in this process, over all contexts. Any thread.
std::uint64_t live_device_bytes();

}  // namespace monoplane::vk_core
