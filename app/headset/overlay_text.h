// Text for the headset (the trial's label, the questionnaire): lines rasterised on the CPU into
// an RGBA image with stb_easy_font's quads, then shown by blitting that image into the eyes.
// Made only when the text changes, so it costs nothing per frame.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "renderer/modes/view_setup.h"

namespace monoplane::headset {

using Rgba8 = std::array<std::uint8_t, 4>;

struct TextStyle {
    int scale = 4;    // pixels per font unit (the font's capitals are 7 units tall)
    int padding = 3;  // font units of background around the text
    Rgba8 ink{220, 220, 220, 255};
    Rgba8 background{40, 40, 40, 255};
};

// Lines top to bottom, left-aligned; the image is just large enough. Characters outside
// printable ASCII are drawn as '?'.
modes::RgbaImage render_text(const std::vector<std::string>& lines, const TextStyle& style);

}  // namespace monoplane::headset
