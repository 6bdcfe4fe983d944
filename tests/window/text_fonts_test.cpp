// The experimenter window's and the launcher's font atlas (app/window/text_fonts.h): Dear
// ImGui's built-in font keeps the ASCII text, and merged fonts add what protocols in other
// languages write, at the size Dear ImGui gives them (checked against FreeType's metrics).
// No window, no GPU: the atlas is built on the CPU.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "app/window/text_fonts.h"
#include "tests/text/freetype_reference.h"

namespace monoplane::window {
namespace {

constexpr float kPixels = 13.0f;

ImFont* default_font(ImFontAtlas& atlas) {
    ImFontConfig config;
    config.SizePixels = kPixels;
    return atlas.AddFontDefault(&config);
}

TEST(TextFonts, EuropeanAndCjkCharactersJoinTheBuiltInFont) {
    ImFontAtlas plain;
    ImFont* builtin = default_font(plain);
    ASSERT_TRUE(plain.Build());
    ImFontAtlas atlas;
    ImFont* font = default_font(atlas);
    merge_text_fonts(atlas, kPixels);
    ASSERT_TRUE(atlas.Build());
    // ASCII and Latin-1 keep the built-in font's glyphs: the window's own text is unchanged.
    for (const ImWchar c : {ImWchar('A'), ImWchar('w'), ImWchar(0xE4), ImWchar(0xDF)}) {
        ASSERT_NE(font->FindGlyphNoFallback(c), nullptr) << c;
        EXPECT_EQ(font->FindGlyphNoFallback(c)->AdvanceX,
                  builtin->FindGlyphNoFallback(c)->AdvanceX);
    }
    // Beyond it: Polish, Greek, Cyrillic, an en dash, from DejaVu Sans.
    for (const ImWchar c : {0x0141, 0x03A9, 0x03B1, 0x0416, 0x0436, 0x2013, 0x201E}) {
        EXPECT_EQ(builtin->FindGlyphNoFallback(c), nullptr) << c;
        EXPECT_NE(font->FindGlyphNoFallback(c), nullptr) << c;
    }
    // Dear ImGui sizes a font so that ascender - descender is `pixels` high: DejaVu's Omega
    // advances 1565 / 2048 em (its hmtx), the font spans 2384 / 2048: 13 * 1565 / 2384 = 8.5,
    // snapped to whole pixels.
    testing::FreeTypeReference dejavu(testing::kDejaVuSans);
    const double omega =
        kPixels * dejavu.advance_em(0x03A9) / (dejavu.ascender_em() - dejavu.descender_em());
    EXPECT_NEAR(font->FindGlyphNoFallback(0x03A9)->AdvanceX, omega, 0.5);
    if (!std::filesystem::exists(testing::kWqyMicroHei)) {
        GTEST_SKIP() << testing::kWqyMicroHei << " missing (fonts-wqy-microhei)";
    }
    testing::FreeTypeReference wqy(testing::kWqyMicroHei);
    // 中文。「」, hiragana, katakana, a full-width comma.
    for (const ImWchar c : {0x4E2D, 0x6587, 0x3002, 0x300C, 0x300D, 0x3042, 0x30A2, 0xFF0C}) {
        ASSERT_NE(font->FindGlyphNoFallback(c), nullptr) << c;
    }
    const double ideograph =
        kPixels * wqy.advance_em(0x4E2D) / (wqy.ascender_em() - wqy.descender_em());
    EXPECT_NEAR(font->FindGlyphNoFallback(0x4E2D)->AdvanceX, ideograph, 0.5);
}

}  // namespace
}  // namespace monoplane::window
