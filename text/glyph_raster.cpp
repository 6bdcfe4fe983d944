#include "text/glyph_raster.h"

#include <algorithm>
#include <cmath>

#include <ft2build.h>
#include FT_FREETYPE_H

#include "text/line_break.h"
#include "text/utf8.h"

namespace monoplane::text {
namespace {

// FreeType's glyph slot bitmap composed into the image with its top-left corner at (x0, y0),
// keeping the larger coverage where glyphs overlap.
void compose(const FT_Bitmap& bitmap, int x0, int y0, CoverageImage& image) {
    for (unsigned row = 0; row < bitmap.rows; ++row) {
        const int y = y0 + static_cast<int>(row);
        if (y < 0 || y >= static_cast<int>(image.height)) continue;
        const unsigned char* source =
            bitmap.buffer + static_cast<std::ptrdiff_t>(row) * bitmap.pitch;
        for (unsigned column = 0; column < bitmap.width; ++column) {
            const int x = x0 + static_cast<int>(column);
            if (x < 0 || x >= static_cast<int>(image.width)) continue;
            std::uint8_t& target = image.coverage[static_cast<std::size_t>(y) * image.width + x];
            target = std::max(target, source[column]);
        }
    }
}

void draw_line(const Font& font, std::u32string_view line, double em_px, int baseline, int left,
               CoverageImage& image) {
    const FT_Face face = font.face();
    double pen = left;
    for (char32_t c : line) {
        if (c == U'\r') continue;
        if (c == U'\t') c = U' ';
        const double advance = font.advance(c) * em_px;
        const FT_UInt glyph = FT_Get_Char_Index(face, c);
        if (FT_Load_Glyph(face, glyph, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP) == 0 &&
            FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL) == 0) {
            const FT_GlyphSlot slot = face->glyph;
            compose(slot->bitmap, static_cast<int>(std::lround(pen)) + slot->bitmap_left,
                    baseline - slot->bitmap_top, image);
        }
        pen += advance;
    }
}

}  // namespace

LineGeometry line_geometry(const Font& font, double em_px, int padding_px) {
    LineGeometry g;
    g.em_px = std::max(1.0, std::round(em_px * 64.0)) / 64.0;
    g.ascent_px = static_cast<int>(std::lround(font.metrics().ascender * g.em_px));
    g.line_px = std::max(1, static_cast<int>(std::lround(font.metrics().line_spacing * g.em_px)));
    g.padding_px = padding_px;
    return g;
}

CoverageImage rasterise_lines(const Font& font, const std::vector<std::string>& lines,
                              const LineGeometry& geometry) {
    std::vector<std::u32string> decoded;
    double widest = 0.0;
    for (const std::string& line : lines) {
        decoded.push_back(decode_utf8_lenient(line));
        widest = std::max(widest, text_width_em(decoded.back(), font) * geometry.em_px);
    }
    CoverageImage image;
    image.width = static_cast<std::uint32_t>(std::ceil(widest)) + 2 * geometry.padding_px;
    image.height =
        static_cast<std::uint32_t>(lines.size() * geometry.line_px) + 2 * geometry.padding_px;
    image.coverage.assign(std::size_t{image.width} * image.height, 0);
    const auto lock = font.lock();
    const FT_Face face = font.face();
    FT_Set_Char_Size(face, 0, static_cast<FT_F26Dot6>(std::lround(geometry.em_px * 64.0)), 72, 72);
    for (std::size_t l = 0; l < decoded.size(); ++l) {
        const int baseline =
            geometry.padding_px + geometry.ascent_px + static_cast<int>(l) * geometry.line_px;
        draw_line(font, decoded[l], geometry.em_px, baseline, geometry.padding_px, image);
    }
    return image;
}

}  // namespace monoplane::text
