// A borrowed 8-bit image as the renderer reads it back (row-major, tightly packed, no row
// padding), so callers pass their buffers to the metrics without copying. This library has no
// Vulkan and no renderer headers (docs/architecture.md), hence its own view type instead of
// modes::RgbaImage; rgba_view() adapts that type (or any with the same members) in place.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace monoplane::quality {

struct ImageView {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    // 1 (grey), 3 (RGB) or 4 (RGBA; alpha is ignored by the metrics).
    std::uint32_t channels = 4;
    // width * height * channels bytes; the viewed buffer must outlive every use of the view.
    std::span<const std::uint8_t> pixels;
};

// RGBA view of anything with width, height and a contiguous pixels container, e.g.
// modes::RgbaImage, without naming that type here. The image must outlive the view.
template <class Image>
ImageView rgba_view(const Image& image) {
    return ImageView{static_cast<std::uint32_t>(image.width),
                     static_cast<std::uint32_t>(image.height), 4,
                     std::span<const std::uint8_t>(image.pixels)};
}

// True when channels is 1, 3 or 4, the size is not zero, and pixels holds exactly
// width * height * channels bytes. The metrics check this and return an error otherwise.
bool is_well_formed(const ImageView& image);

// "WxH", and "WxH with C channels and N bytes", for the metrics' error messages.
std::string size_text(const ImageView& image);
std::string describe(const ImageView& image);

}  // namespace monoplane::quality
