// Writing the window's pixels to a PNG file.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "common/result.h"

namespace monoplane::window {

// `rgba` holds width * height tightly packed RGBA8 pixels, top row first.
Result<void> write_rgba_png(const std::filesystem::path& png, std::uint32_t width,
                            std::uint32_t height, const std::vector<std::uint8_t>& rgba);

}  // namespace monoplane::window
