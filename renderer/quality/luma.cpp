#include "renderer/quality/luma.h"

#include <cstddef>
#include <string>

#include "common/programming_error.h"

namespace monoplane::quality {

std::string size_text(const ImageView& image) {
    return std::to_string(image.width) + "x" + std::to_string(image.height);
}

std::string describe(const ImageView& image) {
    return size_text(image) + " with " + std::to_string(image.channels) + " channels and " +
           std::to_string(image.pixels.size()) + " bytes";
}

bool is_well_formed(const ImageView& image) {
    const bool known_layout = image.channels == 1 || image.channels == 3 || image.channels == 4;
    if (!known_layout || image.width == 0 || image.height == 0) return false;
    const std::size_t bytes = std::size_t{image.width} * image.height * image.channels;
    return image.pixels.size() == bytes;
}

std::vector<double> luma(const ImageView& image) {
    MONOPLANE_EXPECTS(is_well_formed(image));
    const std::size_t count = std::size_t{image.width} * image.height;
    std::vector<double> values(count);
    const std::uint8_t* p = image.pixels.data();
    if (image.channels == 1) {
        for (std::size_t i = 0; i < count; ++i) values[i] = p[i];
        return values;
    }
    for (std::size_t i = 0; i < count; ++i, p += image.channels) {
        values[i] = kLumaRed * p[0] + kLumaGreen * p[1] + kLumaBlue * p[2];
    }
    return values;
}

}  // namespace monoplane::quality
