// PNG files the tests write (textures of the glTF files they build): one copy of stb_image_write
// for every test, in the library monoplane_test_png (tests/CMakeLists.txt), which needs no Vulkan.
#pragma once

#include <filesystem>
#include <vector>

namespace monoplane::testing {

// The PNG encoding of width x height tightly packed RGBA8 texels, top row first. Throws
// std::runtime_error if stb_image_write cannot encode them.
std::vector<unsigned char> png_bytes(int width, int height, const std::vector<unsigned char>& rgba);

// png_bytes written to `path`; throws std::runtime_error if the file cannot be written.
void write_png(const std::filesystem::path& path, int width, int height,
               const std::vector<unsigned char>& rgba);

}  // namespace monoplane::testing
