#include "app/headset/overlay_text.h"

#include <cmath>
#include <iostream>
#include <memory>

#include "common/result.h"
#include "text/font_cache.h"

namespace monoplane::headset {

const text::Font& style_font(const TextStyle& style) {
    Result<std::shared_ptr<const text::Font>> font = text::cached_font(style.font);
    if (font.ok()) return *font.value();
    // Still readable (the missing characters as boxes) rather than no page at all.
    std::cerr << "warning: " << font.error().message << "; the headset's text uses "
              << text::kDefaultFontPath << "\n";
    return *text::cached_font(text::kDefaultFontPath).value_or_throw();
}

text::LineGeometry text_geometry(const TextStyle& style) {
    const text::Font& font = style_font(style);
    return text::line_geometry(font, style.capital_px / font.metrics().cap_height,
                               style.padding_px);
}

modes::RgbaImage render_text(const std::vector<std::string>& lines, const TextStyle& style) {
    const text::CoverageImage coverage =
        text::rasterise_lines(style_font(style), lines, text_geometry(style));
    modes::RgbaImage image;
    image.width = coverage.width;
    image.height = coverage.height;
    image.pixels.resize(coverage.coverage.size() * 4);
    for (std::size_t p = 0; p < coverage.coverage.size(); ++p) {
        const double c = coverage.coverage[p] / 255.0;
        for (std::size_t k = 0; k < 4; ++k) {
            const double from = style.background[k];
            image.pixels[p * 4 + k] =
                static_cast<std::uint8_t>(std::lround(from + (style.ink[k] - from) * c));
        }
    }
    return image;
}

}  // namespace monoplane::headset
