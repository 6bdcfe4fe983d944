// Characters that a renderer without text shaping cannot draw correctly: scripts whose letters
// change form with their neighbours or are reordered (Arabic, Hebrew's right-to-left order,
// the Indic scripts, Thai, ...) and combining marks that must be positioned on a base letter.
// The headset draws one glyph per code point, left to right, so protocols are refused these.
#pragma once

#include <optional>
#include <string>

namespace monoplane::text {

// Why the character cannot be drawn without shaping ("Arabic script, which needs shaping and
// right-to-left layout"), or nothing for a character drawn as one glyph in order. Any time.
std::optional<std::string> needs_shaping(char32_t code_point);

}  // namespace monoplane::text
