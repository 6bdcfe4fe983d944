// Text for the headset (the trial's label, the questionnaire, pages of text): lines rasterised on
// the CPU with FreeType (text/glyph_raster.h) into an RGBA image, the ink blended over the
// background by each pixel's glyph coverage, then shown by blitting that image into the eyes.
// Made only when the text changes, so it costs nothing per frame.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/modes/view_setup.h"
#include "text/font.h"
#include "text/glyph_raster.h"

namespace monoplane::headset {

using Rgba8 = std::array<std::uint8_t, 4>;

struct TextStyle {
    // The font file (a protocol's [text] font); the default draws Latin, Greek and Cyrillic.
    std::string font = text::kDefaultFontPath;
    // The height of a capital letter (the font's cap height), pixels. Fractional sizes serve
    // text sized in degrees of visual angle, drawn 1:1 into the eye.
    double capital_px = 28.0;
    int padding_px = 12;  // background around the text
    Rgba8 ink{220, 220, 220, 255};
    Rgba8 background{40, 40, 40, 255};
};

// The style's font, opened once per process; the default font if the style's cannot be opened
// (a protocol's font was checked when it was loaded), an exception if neither opens.
const text::Font& style_font(const TextStyle& style);

// Where render_text puts the lines: the font at capital_px / cap height pixels per em.
text::LineGeometry text_geometry(const TextStyle& style);

// Lines top to bottom, left-aligned (text/glyph_raster.h's layout): each pixel is the background
// blended toward the ink by its coverage c, background + (ink - background) * c / 255, rounded.
modes::RgbaImage render_text(const std::vector<std::string>& lines, const TextStyle& style);

}  // namespace monoplane::headset
