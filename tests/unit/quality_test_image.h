// An RGBA test image for the quality metrics' tests (SSIM, drift).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace monoplane::quality::testing {

// Same members as modes::RgbaImage, so rgba_view is exercised the way the renderer uses it.
struct TestImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> pixels;

    std::uint8_t* at(std::uint32_t x, std::uint32_t y) {
        return &pixels[4 * (std::size_t{y} * width + x)];
    }
    const std::uint8_t* at(std::uint32_t x, std::uint32_t y) const {
        return &pixels[4 * (std::size_t{y} * width + x)];
    }
};

// One colour everywhere, opaque.
inline TestImage flat_image(std::uint32_t width, std::uint32_t height, std::uint8_t r,
                            std::uint8_t g, std::uint8_t b) {
    TestImage image{width, height, std::vector<std::uint8_t>(std::size_t{4} * width * height)};
    for (std::size_t i = 0; i < std::size_t{width} * height; ++i) {
        image.pixels[4 * i + 0] = r;
        image.pixels[4 * i + 1] = g;
        image.pixels[4 * i + 2] = b;
        image.pixels[4 * i + 3] = 255;
    }
    return image;
}

// A grey level everywhere.
inline TestImage flat_image(std::uint32_t width, std::uint32_t height, std::uint8_t value) {
    return flat_image(width, height, value, value, value);
}

}  // namespace monoplane::quality::testing
