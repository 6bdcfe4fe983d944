#include "tests/text/freetype_reference.h"

#include <algorithm>
#include <cmath>

namespace monoplane::testing {

FreeTypeReference::FreeTypeReference(const char* path) {
    FT_Init_FreeType(&library_);
    if (FT_New_Face(library_, path, 0, &face_) != 0) face_ = nullptr;
}

FreeTypeReference::~FreeTypeReference() {
    if (face_ != nullptr) FT_Done_Face(face_);
    FT_Done_FreeType(library_);
}

double FreeTypeReference::cap_height_em() const {
    FT_Load_Char(face_, 'H', FT_LOAD_NO_SCALE);
    FT_BBox box;
    FT_Outline_Get_CBox(&face_->glyph->outline, &box);
    return double(box.yMax) / face_->units_per_EM;
}

std::u32string utf32(const std::string& utf8) {
    std::u32string out;
    for (std::size_t i = 0; i < utf8.size();) {
        const auto lead = static_cast<unsigned char>(utf8[i]);
        const int n = lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
        char32_t c = n == 1 ? lead : lead & (0xFF >> (n + 1));
        for (int k = 1; k < n; ++k) c = (c << 6) | (static_cast<unsigned char>(utf8[i + k]) & 0x3F);
        out += c;
        i += static_cast<std::size_t>(n);
    }
    return out;
}

FreeTypeReference::Image FreeTypeReference::render(const std::vector<std::string>& lines,
                                                   double em_px, int padding) {
    const FT_F26Dot6 size = std::lround(em_px * 64.0);
    FT_Set_Char_Size(face_, 0, size, 72, 72);
    const double em = size / 64.0;
    const int ascent = static_cast<int>(std::lround(ascender_em() * em));
    const int line = static_cast<int>(std::lround(line_spacing_em() * em));
    // The pens' ends first: the image is as wide as the widest line's advances.
    double widest = 0.0;
    for (const std::string& text : lines) {
        double pen = 0.0;
        for (const char32_t c : utf32(text)) {
            FT_Load_Char(face_, c, FT_LOAD_NO_HINTING);
            pen += face_->glyph->linearHoriAdvance / 65536.0;
        }
        widest = std::max(widest, pen);
    }
    Image image;
    image.width = static_cast<int>(std::ceil(widest)) + 2 * padding;
    image.height = static_cast<int>(lines.size()) * line + 2 * padding;
    image.coverage.assign(std::size_t(image.width) * image.height, 0);
    for (std::size_t l = 0; l < lines.size(); ++l) {
        const int baseline = padding + ascent + static_cast<int>(l) * line;
        double pen = padding;
        for (const char32_t c : utf32(lines[l])) {
            FT_Load_Char(face_, c, FT_LOAD_NO_HINTING);
            FT_Render_Glyph(face_->glyph, FT_RENDER_MODE_NORMAL);
            const FT_Bitmap& b = face_->glyph->bitmap;
            const int x0 = static_cast<int>(std::lround(pen)) + face_->glyph->bitmap_left;
            const int y0 = baseline - face_->glyph->bitmap_top;
            for (int r = 0; r < int(b.rows); ++r) {
                for (int k = 0; k < int(b.width); ++k) {
                    const int x = x0 + k;
                    const int y = y0 + r;
                    if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
                    std::uint8_t& t = image.coverage[std::size_t(y) * image.width + x];
                    t = std::max(t, b.buffer[r * b.pitch + k]);
                }
            }
            pen += face_->glyph->linearHoriAdvance / 65536.0;
        }
    }
    return image;
}

}  // namespace monoplane::testing
