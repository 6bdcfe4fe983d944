// The one place that includes Vulkan-Hpp: its vk::raii types are the move-only RAII wrappers for
// every Vulkan object monoplane creates.
#pragma once

#include <vulkan/vulkan_raii.hpp>
