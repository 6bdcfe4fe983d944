#include "app/window/screenshot.h"

// Static: the monoplane executable has its own stb_image_write implementation (app/png.cpp).
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>

#include <system_error>

#include "common/programming_error.h"

namespace monoplane::window {

Result<void> write_rgba_png(const std::filesystem::path& png, std::uint32_t width,
                            std::uint32_t height, const std::vector<std::uint8_t>& rgba) {
    MONOPLANE_EXPECTS(rgba.size() == std::size_t{width} * height * 4);
    if (png.has_parent_path()) {
        std::error_code error;
        std::filesystem::create_directories(png.parent_path(), error);
        if (error) {
            return Error{"cannot create the folder " + png.parent_path().string() + ": " +
                         error.message()};
        }
    }
    const int stride = static_cast<int>(width) * 4;
    if (stbi_write_png(png.c_str(), static_cast<int>(width), static_cast<int>(height), 4,
                       rgba.data(), stride) == 0) {
        return Error{"cannot write the screenshot " + png.string() +
                     " (is the folder writable and the disk not full?)"};
    }
    return Ok{};
}

}  // namespace monoplane::window
