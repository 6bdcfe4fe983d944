// Text for the headset (the trial's label, the questionnaire, pages of text): lines rasterised on
// the CPU into an RGBA image with stb_easy_font's quads, then shown by blitting that image into
// the eyes. Made only when the text changes, so it costs nothing per frame.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/modes/view_setup.h"

namespace monoplane::headset {

using Rgba8 = std::array<std::uint8_t, 4>;

// stb_easy_font's metrics, in font units: a capital letter's height and the line spacing.
constexpr int kCapitalUnits = 7;
constexpr int kLineUnits = 12;

struct TextStyle {
    // Pixels per font unit. Fractional scales serve text sized in degrees of visual angle, drawn
    // 1:1 into the eye (a stroke is then 1 or 2 pixels wide, as the display's resolution allows).
    double scale = 4.0;
    int padding = 3;  // font units of background around the text
    Rgba8 ink{220, 220, 220, 255};
    Rgba8 background{40, 40, 40, 255};
};

// Lines top to bottom, left-aligned; the image is just large enough: round(units * scale) pixels
// each way for the text's width and height in font units plus the padding. Characters outside
// printable ASCII are drawn as '?'.
modes::RgbaImage render_text(const std::vector<std::string>& lines, const TextStyle& style);

// A line's width in font units (what render_text makes it), characters outside printable ASCII
// counted as '?'.
int text_width_units(const std::string& line);

}  // namespace monoplane::headset
