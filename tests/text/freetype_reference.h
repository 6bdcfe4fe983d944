// FreeType's own rasterisation of a string, done here in the tests apart from text/: the glyphs
// loaded and rendered one by one (FT_Load_Char with FT_LOAD_RENDER, unhinted) and set down at
// pen positions that add up FreeType's linear advances. What monoplane draws is compared with it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

namespace monoplane::testing {

inline const char* const kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
// Debian's fonts-wqy-microhei: CJK with Latin (scripts/install-deps.sh installs it).
inline const char* const kWqyMicroHei = "/usr/share/fonts/truetype/wqy/wqy-microhei.ttc";

class FreeTypeReference {
  public:
    explicit FreeTypeReference(const char* path);
    ~FreeTypeReference();
    FreeTypeReference(const FreeTypeReference&) = delete;
    FreeTypeReference& operator=(const FreeTypeReference&) = delete;

    bool ok() const { return face_ != nullptr; }
    // The top of 'H''s unscaled outline over units per em.
    double cap_height_em() const;
    double ascender_em() const { return double(face_->ascender) / face_->units_per_EM; }
    double descender_em() const { return double(face_->descender) / face_->units_per_EM; }
    double line_spacing_em() const { return double(face_->height) / face_->units_per_EM; }
    // The character's unscaled advance over units per em.
    double advance_em(char32_t c) const {
        FT_Load_Char(face_, c, FT_LOAD_NO_SCALE);
        return double(face_->glyph->advance.x) / face_->units_per_EM;
    }

    struct Image {
        int width = 0;
        int height = 0;
        std::vector<std::uint8_t> coverage;
    };
    // `lines` at em_px pixels per em (26.6 as FreeType takes it), `padding` pixels around:
    // baselines at padding + round(ascender) + l * round(line spacing), each glyph's bitmap at
    // the rounded pen position, overlaps keeping the larger coverage.
    Image render(const std::vector<std::string>& lines, double em_px, int padding);

  private:
    FT_Library library_ = nullptr;
    FT_Face face_ = nullptr;
};

// The code points of UTF-8 text (valid text only; the tests write their own).
std::u32string utf32(const std::string& utf8);

}  // namespace monoplane::testing
