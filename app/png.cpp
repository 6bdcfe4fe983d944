#include "app/png.h"

#include <stb_image_write.h>

namespace monoplane::app {

Result<void> write_png(const std::filesystem::path& path, const modes::RgbaImage& image) {
    const int ok =
        stbi_write_png(path.c_str(), static_cast<int>(image.width), static_cast<int>(image.height),
                       4, image.pixels.data(), static_cast<int>(image.width * 4));
    if (!ok) return Error{"could not write " + path.string()};
    return Ok{};
}

std::string png_bytes(const modes::RgbaImage& image) {
    std::string out;
    stbi_write_png_to_func(
        [](void* context, void* data, int size) {
            static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                                       static_cast<std::size_t>(size));
        },
        &out, static_cast<int>(image.width), static_cast<int>(image.height), 4, image.pixels.data(),
        static_cast<int>(image.width * 4));
    return out;
}

}  // namespace monoplane::app
