#include "renderer/vk/memory.h"

namespace monoplane::vk_core {

vk::raii::DeviceMemory allocate_memory(const Context& ctx, const vk::MemoryRequirements& needs,
                                       vk::MemoryPropertyFlags properties) {
    const auto memory = ctx.physical_device().getMemoryProperties();
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        const bool allowed = (needs.memoryTypeBits & (1u << i)) != 0;
        if (allowed && (memory.memoryTypes[i].propertyFlags & properties) == properties) {
            return vk::raii::DeviceMemory(ctx.device(), vk::MemoryAllocateInfo(needs.size, i));
        }
    }
    throw vk::SystemError(vk::make_error_code(vk::Result::eErrorOutOfDeviceMemory),
                          "no memory type with the requested properties");
}

}  // namespace monoplane::vk_core
