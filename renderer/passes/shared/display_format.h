// The display images' format: 8-bit sRGB, what the tone mapping (and the composite that tone maps)
// writes, a headset's swapchain copies and the PNG files hold.
#pragma once

#include "renderer/vk/context.h"

namespace monoplane::passes {

constexpr vk::Format kDisplayFormat = vk::Format::eR8G8B8A8Srgb;

}  // namespace monoplane::passes
