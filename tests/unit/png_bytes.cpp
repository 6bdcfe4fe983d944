#include "tests/unit/png_bytes.h"

#include <fstream>
#include <stdexcept>
#include <string>

#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace monoplane::testing {

std::vector<unsigned char> png_bytes(int width, int height,
                                     const std::vector<unsigned char>& rgba) {
    std::vector<unsigned char> bytes;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            auto* out = static_cast<std::vector<unsigned char>*>(context);
            out->insert(out->end(), static_cast<unsigned char*>(data),
                        static_cast<unsigned char*>(data) + size);
        },
        &bytes, width, height, 4, rgba.data(), width * 4);
    if (bytes.empty()) {
        throw std::runtime_error("cannot encode a " + std::to_string(width) + " x " +
                                 std::to_string(height) + " PNG");
    }
    return bytes;
}

void write_png(const std::filesystem::path& path, int width, int height,
               const std::vector<unsigned char>& rgba) {
    const std::vector<unsigned char> bytes = png_bytes(width, height, rgba);
    std::ofstream out(path, std::ios::binary);
    out.write(reinterpret_cast<const char*>(bytes.data()),
              static_cast<std::streamsize>(bytes.size()));
    if (!out) throw std::runtime_error("cannot write " + path.string());
}

}  // namespace monoplane::testing
