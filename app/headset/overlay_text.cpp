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

// stb_easy_font's documentation puts a character at about 270 bytes of vertices; the buffer
// allows more, so that no long line is cut short.
constexpr std::size_t kVertexBytesPerChar = 512;

std::string printable(const std::string& line) {
    std::string out = line;
    for (char& c : out) {
        if (c < 32 || c > 126) c = '?';
    }
    return out;
}

std::uint32_t pixels(int units, double scale) {
    return static_cast<std::uint32_t>(std::max(0L, std::lround(units * scale)));
}

}  // namespace

int text_width_units(const std::string& line) {
    std::string text = printable(line);
    return stb_easy_font_width(text.data());
}

modes::RgbaImage render_text(const std::vector<std::string>& lines, const TextStyle& style) {
    int width_units = 0;
    for (const std::string& line : lines)
        width_units = std::max(width_units, text_width_units(line));
    const double s = style.scale;
    modes::RgbaImage image;
    image.width = pixels(width_units + 2 * style.padding, s);
    image.height = pixels(static_cast<int>(lines.size()) * kLineUnits + 2 * style.padding, s);
    image.pixels.resize(std::size_t{image.width} * image.height * 4);
    const auto paint = [&image](std::size_t pixel, const Rgba8& colour) {
        std::copy(colour.begin(), colour.end(), &image.pixels[pixel * 4]);
    };
    for (std::size_t p = 0; p < image.pixels.size() / 4; ++p) paint(p, style.background);
    const auto width = static_cast<int>(image.width);
    const auto height = static_cast<int>(image.height);
    std::vector<FontVertex> quads;
    for (std::size_t l = 0; l < lines.size(); ++l) {
        std::string text = printable(lines[l]);
        quads.resize(std::max<std::size_t>(64, text.size() * kVertexBytesPerChar / 16));
        const int count = stb_easy_font_print(
            static_cast<float>(style.padding),
            static_cast<float>(style.padding + (static_cast<int>(l) * kLineUnits)), text.data(),
            nullptr, quads.data(), static_cast<int>(quads.size() * sizeof(FontVertex)));
        for (int q = 0; q < count; ++q) {
            // Each quad is an axis-aligned rectangle; its corners 0 and 2 are opposite.
            const FontVertex& a = quads[static_cast<std::size_t>(q) * 4];
            const FontVertex& c = quads[static_cast<std::size_t>(q) * 4 + 2];
            const int x0 = static_cast<int>(std::lround(std::min(a.x, c.x) * s));
            const int x1 = static_cast<int>(std::lround(std::max(a.x, c.x) * s));
            const int y0 = static_cast<int>(std::lround(std::min(a.y, c.y) * s));
            const int y1 = static_cast<int>(std::lround(std::max(a.y, c.y) * s));
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
