#include "renderer/vk/memory.h"

#include <atomic>
#include <utility>

namespace monoplane::vk_core {
namespace {

// Per MemoryKind.
std::atomic<std::uint64_t> g_live_bytes[2] = {0, 0};

std::atomic<std::uint64_t>& live(MemoryKind kind) {
    return g_live_bytes[static_cast<int>(kind)];
}

}  // namespace

DeviceMemory::DeviceMemory(vk::raii::DeviceMemory memory, vk::DeviceSize bytes, MemoryKind kind)
    : memory_(std::move(memory)), bytes_(bytes), kind_(kind) {
    live(kind_) += bytes_;
}

DeviceMemory::DeviceMemory(DeviceMemory&& other) noexcept
    : memory_(std::move(other.memory_)),
      bytes_(std::exchange(other.bytes_, 0)),
      kind_(other.kind_) {}

DeviceMemory& DeviceMemory::operator=(DeviceMemory&& other) noexcept {
    if (this != &other) {
        release();
        memory_ = std::move(other.memory_);
        bytes_ = std::exchange(other.bytes_, 0);
        kind_ = other.kind_;
    }
    return *this;
}

DeviceMemory::~DeviceMemory() {
    release();
}

void DeviceMemory::release() {
    memory_ = nullptr;
    live(kind_) -= std::exchange(bytes_, 0);
}

DeviceMemory allocate_memory(const Context& ctx, const vk::MemoryRequirements& needs,
                             vk::MemoryPropertyFlags properties, MemoryKind kind) {
    const auto memory = ctx.physical_device().getMemoryProperties();
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        const bool allowed = (needs.memoryTypeBits & (1u << i)) != 0;
        if (allowed && (memory.memoryTypes[i].propertyFlags & properties) == properties) {
            return DeviceMemory(
                vk::raii::DeviceMemory(ctx.device(), vk::MemoryAllocateInfo(needs.size, i)),
                needs.size, kind);
        }
    }
    throw vk::SystemError(vk::make_error_code(vk::Result::eErrorOutOfDeviceMemory),
                          "no memory type with the requested properties");
}

std::uint64_t live_device_bytes() {
    return live_device_bytes(MemoryKind::kImage) + live_device_bytes(MemoryKind::kBuffer);
}

std::uint64_t live_device_bytes(MemoryKind kind) {
    return live(kind).load();
}

}  // namespace monoplane::vk_core
