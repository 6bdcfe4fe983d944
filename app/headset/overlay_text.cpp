#include "app/headset/overlay_text.h"

#include <algorithm>
#include <cmath>

#include <stb/stb_easy_font.h>

namespace monoplane::headset {
namespace {

// One vertex of stb_easy_font's output: x, y, z as floats and a colour.
struct FontVertex {
    float x, y, z;
    std::uint8_t color[4];
};
static_assert(sizeof(FontVertex) == 16);

constexpr int kLineHeight = 12;  // font units per line, stb_easy_font's own spacing

std::string printable(const std::string& line) {
    std::string out = line;
    for (char& c : out) {
        if (c < 32 || c > 126) c = '?';
    }
    return out;
}

}  // namespace

modes::RgbaImage render_text(const std::vector<std::string>& lines, const TextStyle& style) {
    int width_units = 0;
    for (const std::string& line : lines) {
        std::string text = printable(line);
        width_units = std::max(width_units, stb_easy_font_width(text.data()));
    }
    const int s = style.scale;
    modes::RgbaImage image;
    image.width = static_cast<std::uint32_t>((width_units + 2 * style.padding) * s);
    image.height = static_cast<std::uint32_t>(
        (static_cast<int>(lines.size()) * kLineHeight + 2 * style.padding) * s);
    image.pixels.resize(std::size_t{image.width} * image.height * 4);
    const auto paint = [&image](std::size_t pixel, const Rgba8& colour) {
        std::copy(colour.begin(), colour.end(), &image.pixels[pixel * 4]);
    };
    for (std::size_t p = 0; p < image.pixels.size() / 4; ++p) paint(p, style.background);
    const auto scale = static_cast<float>(s);
    const auto width = static_cast<int>(image.width);
    const auto height = static_cast<int>(image.height);
    std::vector<FontVertex> quads(4096);
    for (std::size_t l = 0; l < lines.size(); ++l) {
        std::string text = printable(lines[l]);
        const int count = stb_easy_font_print(
            static_cast<float>(style.padding),
            static_cast<float>(style.padding + (static_cast<int>(l) * kLineHeight)), text.data(),
            nullptr, quads.data(), static_cast<int>(quads.size() * sizeof(FontVertex)));
        for (int q = 0; q < count; ++q) {
            // Each quad is an axis-aligned rectangle; its corners 0 and 2 are opposite.
            const FontVertex& a = quads[static_cast<std::size_t>(q) * 4];
            const FontVertex& c = quads[static_cast<std::size_t>(q) * 4 + 2];
            const int x0 = static_cast<int>(std::lround(std::min(a.x, c.x) * scale));
            const int x1 = static_cast<int>(std::lround(std::max(a.x, c.x) * scale));
            const int y0 = static_cast<int>(std::lround(std::min(a.y, c.y) * scale));
            const int y1 = static_cast<int>(std::lround(std::max(a.y, c.y) * scale));
            for (int y = std::max(0, y0); y < std::min(y1, height); ++y) {
                for (int x = std::max(0, x0); x < std::min(x1, width); ++x) {
                    paint(std::size_t(y) * image.width + std::size_t(x), style.ink);
                }
            }
        }
    }
    return image;
}

}  // namespace monoplane::headset
