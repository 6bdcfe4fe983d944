// Lines of text as an 8-bit coverage image: FreeType's anti-aliased glyphs (unhinted, so that
// sizes and advances scale exactly with the pixel size) at the pen positions the font's
// advances give. One glyph per code point, left to right: no kerning, no shaping
// (complex_scripts.h lists what that excludes).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "text/font.h"

namespace monoplane::text {

struct CoverageImage {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    std::vector<std::uint8_t> coverage;  // row-major, top row first; 255: fully inside a glyph

    std::uint8_t at(std::uint32_t x, std::uint32_t y) const { return coverage[y * width + x]; }
};

// Where rasterise_lines puts the text, in pixels, for a font at em_px pixels per em.
struct LineGeometry {
    double em_px = 0.0;  // em_px as FreeType takes it: rounded to 1/64 pixel
    int ascent_px = 0;   // the first baseline's distance below the text's top
    int line_px = 0;     // baseline to baseline
    int padding_px = 0;  // background on every side
};

// The geometry for lines of `font` at em_px pixels per em with `padding_px` around them:
// ascent and line spacing from the font's metrics, rounded to whole pixels so that every line's
// baseline is on a pixel row.
LineGeometry line_geometry(const Font& font, double em_px, int padding_px);

// Draws `lines` (UTF-8) top to bottom, left-aligned. The image is ceil(widest line) + 2 *
// padding wide and lines * line_px + 2 * padding high. Line l's baseline is at row padding +
// ascent_px + l * line_px; each glyph's pen position is padding + the advances before it
// (advance * em_px, summed unrounded) and its bitmap is placed at the pen rounded to a whole
// pixel. Where glyphs overlap the larger coverage wins. A character the font lacks draws as its
// missing-glyph box; tabs as spaces; carriage returns not at all.
CoverageImage rasterise_lines(const Font& font, const std::vector<std::string>& lines,
                              const LineGeometry& geometry);

}  // namespace monoplane::text
