#include "text/complex_scripts.h"

#include <array>
#include <string>

namespace monoplane::text {
namespace {

struct ScriptRange {
    char32_t first;
    char32_t last;
    std::string_view what;
    bool script = true;  // a script (needs shaping), or combining marks
};

constexpr std::string_view kMark =
    "a combining mark: write the precomposed letter instead (Unicode normalization form C)";

// Unicode blocks (Blocks.txt of the Unicode Character Database) of the scripts that need it.
constexpr std::array<ScriptRange, 30> kRanges = {{
    {0x0300, 0x036F, kMark, false},
    {0x0590, 0x05FF, "Hebrew script"},
    {0x0600, 0x06FF, "Arabic script"},
    {0x0700, 0x074F, "Syriac script"},
    {0x0750, 0x077F, "Arabic script"},
    {0x0780, 0x07BF, "Thaana script"},
    {0x07C0, 0x07FF, "N'Ko script"},
    {0x0800, 0x08FF, "Arabic script"},
    {0x0900, 0x097F, "Devanagari script"},
    {0x0980, 0x09FF, "Bengali script"},
    {0x0A00, 0x0A7F, "Gurmukhi script"},
    {0x0A80, 0x0AFF, "Gujarati script"},
    {0x0B00, 0x0B7F, "Oriya script"},
    {0x0B80, 0x0BFF, "Tamil script"},
    {0x0C00, 0x0C7F, "Telugu script"},
    {0x0C80, 0x0CFF, "Kannada script"},
    {0x0D00, 0x0D7F, "Malayalam script"},
    {0x0D80, 0x0DFF, "Sinhala script"},
    {0x0E00, 0x0E7F, "Thai script"},
    {0x0E80, 0x0EFF, "Lao script"},
    {0x0F00, 0x0FFF, "Tibetan script"},
    {0x1000, 0x109F, "Myanmar script"},
    {0x1100, 0x11FF, "Hangul Jamo (write precomposed Hangul syllables instead)", false},
    {0x1780, 0x17FF, "Khmer script"},
    {0x1800, 0x18AF, "Mongolian script"},
    {0x1AB0, 0x1AFF, kMark, false},
    {0x1DC0, 0x1DFF, kMark, false},
    {0x20D0, 0x20FF, "a combining mark for symbols", false},
    {0xFB1D, 0xFB4F, "Hebrew script"},
    {0xFB50, 0xFEFF, "Arabic script"},
}};

bool right_to_left(char32_t c) {
    return (c >= 0x0590 && c <= 0x08FF) || (c >= 0xFB1D && c <= 0xFEFF);
}

}  // namespace

std::optional<std::string> needs_shaping(char32_t code_point) {
    // U+FE00..FE6F inside the last range are variation selectors and CJK compatibility forms,
    // which need no shaping; the Arabic presentation forms are FB50..FDFF and FE70..FEFF.
    if (code_point >= 0xFE00 && code_point <= 0xFE6F) return std::nullopt;
    for (const ScriptRange& range : kRanges) {
        if (code_point < range.first || code_point > range.last) continue;
        if (!range.script) return std::string(range.what);
        return std::string(range.what) + (right_to_left(code_point)
                                              ? ", which needs shaping and right-to-left layout"
                                              : ", which needs shaping (letters change form "
                                                "and order)");
    }
    return std::nullopt;
}

}  // namespace monoplane::text
