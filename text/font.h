// A font file read with FreeType: which characters it draws, their advances and the metrics a
// page is laid out with, all in ems (font units divided by units per em) so that one measurement
// serves every pixel size.
#pragma once

#include <filesystem>
#include <memory>
#include <mutex>
#include <string>

#include "common/result.h"

struct FT_FaceRec_;

namespace monoplane::text {

// Debian's fonts-dejavu-core: Latin with diacritics, Greek, Cyrillic (no CJK).
inline constexpr const char* kDefaultFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

struct FontMetrics {
    // The height of a capital letter: the top of 'H''s outline (the OS/2 table's sCapHeight
    // where a font has no 'H'), the measure text_height_deg sizes.
    double cap_height = 0.0;
    double ascender = 0.0;      // above the baseline (the font's hhea/typo ascender)
    double descender = 0.0;     // below the baseline, negative
    double line_spacing = 0.0;  // baseline to baseline (ascender - descender + line gap)
};

class Font {
  public:
    // Opens a TrueType/OpenType file (the first face of a collection, .ttc). An error names the
    // file and what is wrong with it. Any time.
    static Result<Font> open(const std::filesystem::path& path);

    Font(Font&&) noexcept;
    Font& operator=(Font&&) noexcept;
    ~Font();

    const std::filesystem::path& path() const;
    // The font's family and style, "DejaVu Sans Book".
    std::string name() const;
    bool has_glyph(char32_t code_point) const;
    // The unhinted horizontal advance, ems; the missing-glyph box's for a character the font
    // lacks.
    double advance(char32_t code_point) const;
    const FontMetrics& metrics() const;

    // FreeType's face, for the rasteriser: used only while holding lock() (a face is not safe
    // to use from two threads at once).
    FT_FaceRec_* face() const;
    std::unique_lock<std::recursive_mutex> lock() const;

  private:
    struct State;
    explicit Font(std::unique_ptr<State> state);
    std::unique_ptr<State> state_;
};

}  // namespace monoplane::text
