// PNG files for rendered images (stb_image_write from Debian's libstb).
#pragma once

#include <filesystem>
#include <string>

#include "common/result.h"
#include "renderer/modes/view_setup.h"

namespace monoplane::app {

Result<void> write_png(const std::filesystem::path& path, const modes::RgbaImage& image);

// The same PNG in memory, for a file that embeds it (the report's gaze density figure).
std::string png_bytes(const modes::RgbaImage& image);

}  // namespace monoplane::app
