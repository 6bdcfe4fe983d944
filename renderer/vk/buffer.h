// A buffer with its own memory; host-visible buffers stay mapped for their lifetime.
#pragma once

#include <cstring>
#include <span>

#include "renderer/vk/context.h"
#include "renderer/vk/memory.h"

namespace monoplane::vk_core {

enum class MemoryUse {
    kDeviceLocal,  // filled through upload(); fastest for the GPU
    kHostVisible,  // mapped, coherent: per-frame constants, indirect commands, readback
};

class Buffer {
  public:
    Buffer() = default;
    Buffer(const Context& ctx, vk::DeviceSize size, vk::BufferUsageFlags usage, MemoryUse use);

    vk::Buffer handle() const { return *buffer_; }
    vk::DeviceSize size() const { return size_; }
    // Non-null only for kHostVisible buffers.
    std::byte* mapped() const { return mapped_; }

    // Copies into a host-visible buffer at a byte offset.
    void write(const void* data, vk::DeviceSize bytes, vk::DeviceSize offset = 0) const;

  private:
    vk::raii::Buffer buffer_{nullptr};
    DeviceMemory memory_{nullptr};
    vk::DeviceSize size_ = 0;
    std::byte* mapped_ = nullptr;
};

// A device-local buffer filled with `bytes` through a staging copy (waits for completion).
Buffer make_device_buffer(const Context& ctx, std::span<const std::byte> bytes,
                          vk::BufferUsageFlags usage);

template <class T>
Buffer make_device_buffer(const Context& ctx, std::span<const T> items,
                          vk::BufferUsageFlags usage) {
    return make_device_buffer(ctx, std::as_bytes(items), usage);
}

}  // namespace monoplane::vk_core
