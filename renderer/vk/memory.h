// Device memory: one dedicated allocation per buffer or image. monoplane creates few, large
// resources once per run, so a sub-allocator would add complexity without saving anything.
#pragma once

#include "renderer/vk/context.h"

namespace monoplane::vk_core {

// May be called once the resource exists; throws vk::SystemError if no memory type fits.
vk::raii::DeviceMemory allocate_memory(const Context& ctx, const vk::MemoryRequirements& needs,
                                       vk::MemoryPropertyFlags properties);

}  // namespace monoplane::vk_core
