#include "renderer/vk/buffer.h"

#include "common/programming_error.h"
#include "renderer/vk/memory.h"

namespace monoplane::vk_core {

Buffer::Buffer(const Context& ctx, vk::DeviceSize size, vk::BufferUsageFlags usage, MemoryUse use)
    : size_(size) {
    if (use == MemoryUse::kDeviceLocal) usage |= vk::BufferUsageFlagBits::eTransferDst;
    buffer_ = vk::raii::Buffer(ctx.device(), vk::BufferCreateInfo({}, size, usage));
    const auto properties =
        use == MemoryUse::kHostVisible
            ? vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent
            : vk::MemoryPropertyFlags(vk::MemoryPropertyFlagBits::eDeviceLocal);
    memory_ =
        allocate_memory(ctx, buffer_.getMemoryRequirements(), properties, MemoryKind::kBuffer);
    buffer_.bindMemory(*memory_, 0);
    if (use == MemoryUse::kHostVisible) {
        mapped_ = static_cast<std::byte*>(memory_.map());
    }
}

void Buffer::write(const void* data, vk::DeviceSize bytes, vk::DeviceSize offset) const {
    MONOPLANE_EXPECTS(mapped_ && offset + bytes <= size_);
    std::memcpy(mapped_ + offset, data, bytes);
}

Buffer make_device_buffer(const Context& ctx, std::span<const std::byte> bytes,
                          vk::BufferUsageFlags usage) {
    const vk::DeviceSize size = std::max<vk::DeviceSize>(bytes.size(), 4);
    Buffer staging(ctx, size, vk::BufferUsageFlagBits::eTransferSrc, MemoryUse::kHostVisible);
    staging.write(bytes.data(), bytes.size());
    Buffer target(ctx, size, usage, MemoryUse::kDeviceLocal);
    ctx.submit_and_wait([&](const vk::raii::CommandBuffer& cmd) {
        cmd.copyBuffer(staging.handle(), target.handle(), vk::BufferCopy(0, 0, size));
    });
    return target;
}

}  // namespace monoplane::vk_core
