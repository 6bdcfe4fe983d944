// Line breaking (UAX #14 subset, text/line_break.h): words kept whole in Latin, Greek and
// Cyrillic; breaks between CJK characters but never before closing punctuation nor after
// opening; widths from the font's advances, checked against FreeType's (freetype_reference.h).
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

#include "tests/text/freetype_reference.h"
#include "text/font.h"
#include "text/line_break.h"
#include "text/utf8.h"

namespace monoplane::text {
namespace {

using testing::kDejaVuSans;
using testing::kWqyMicroHei;

const Font& dejavu() {
    static const Font font = Font::open(kDejaVuSans).value_or_throw();
    return font;
}

// The CJK font, or nullptr where fonts-wqy-microhei is not installed.
const Font* wqy() {
    static const Result<Font> font = Font::open(kWqyMicroHei);
    return font.ok() ? &font.value() : nullptr;
}

std::vector<std::string> words_of(const std::string& text) {
    std::istringstream in(text);
    std::vector<std::string> words;
    for (std::string w; in >> w;) words.push_back(w);
    return words;
}

std::string joined(const std::vector<std::string>& lines, const char* separator) {
    std::string text;
    for (const std::string& line : lines) text += line + separator;
    return text;
}

const std::string kParagraph =
    "You will see two versions of each scene, one after the other. Press SWITCH to change between "
    "them as often as you like, then press CONFIRM to choose the one that looked more natural.";
const std::string kGerman =
    "Dr\u00fccken Sie SCHALTER, um zwischen den beiden Darstellungen zu wechseln, so oft Sie "
    "m\u00f6chten. W\u00e4hlen Sie dann mit BEST\u00c4TIGEN die nat\u00fcrlichere. Gr\u00f6\u00dfe "
    "und Stra\u00dfe.";
// "Please press the confirm key to start. You will see two pictures of each scene (one after the
// other), then choose the more natural one." No spaces: lines break between characters.
const std::string kChinese =
    "\u8bf7\u6309\u786e\u8ba4\u952e\u5f00\u59cb\u3002\u6bcf\u4e2a\u573a\u666f\u60a8\u5c06\u770b"
    "\u5230\u4e24\u5e45\u753b\u9762\uff08\u4e00\u5e45\u63a5\u4e00\u5e45\uff09\uff0c\u7136\u540e"
    "\u9009\u62e9\u770b\u8d77\u6765\u66f4\u81ea\u7136\u7684\u4e00\u5e45\u300c\u753b\u9762\u300d"
    "\uff01\u8c22\u8c22\u3002";

TEST(Utf8, DecodesAndRefusesWhatIsNotUtf8) {
    EXPECT_EQ(decode_utf8("a\u00e4\u20ac\U0001F600"), std::u32string(U"a\u00e4\u20ac\U0001F600"));
    EXPECT_FALSE(decode_utf8("a\xff"));
    EXPECT_FALSE(decode_utf8("\xc0\xaf"));      // overlong '/'
    EXPECT_FALSE(decode_utf8("\xed\xa0\x80"));  // a surrogate
    EXPECT_FALSE(decode_utf8("\xe2\x82"));      // truncated
    EXPECT_EQ(first_invalid_utf8("ab\xe2\x82"), 2u);
    EXPECT_EQ(decode_utf8_lenient("a\xff"
                                  "b"),
              std::u32string(U"a\uFFFDb"));
    EXPECT_EQ(encode_utf8(U"\u00df\u4e2d\U0001F600"), "\u00df\u4e2d\U0001F600");
    EXPECT_EQ(code_point_label(0xE4), "U+00E4");
    EXPECT_EQ(code_point_label(0x1F600), "U+1F600");
}

TEST(FontMetrics, CapHeightAndAdvancesAreFreeTypes) {
    testing::FreeTypeReference reference(kDejaVuSans);
    ASSERT_TRUE(reference.ok());
    // DejaVu Sans 2.37, read from its tables by hand: head.unitsPerEm 2048, 'H''s glyf yMax
    // 1493, hhea ascender 1901 and descender -483, line gap 0.
    EXPECT_NEAR(reference.cap_height_em(), 1493.0 / 2048.0, 1e-12);
    EXPECT_DOUBLE_EQ(dejavu().metrics().line_spacing, (1901.0 + 483.0) / 2048.0);
    EXPECT_DOUBLE_EQ(dejavu().metrics().cap_height, reference.cap_height_em());
    EXPECT_DOUBLE_EQ(dejavu().metrics().line_spacing, reference.line_spacing_em());
    EXPECT_DOUBLE_EQ(dejavu().metrics().ascender, reference.ascender_em());
    // hmtx: 'W' advances 2025 units, 'i' 569.
    EXPECT_DOUBLE_EQ(dejavu().advance(U'W'), 2025.0 / 2048.0);
    EXPECT_DOUBLE_EQ(dejavu().advance(U'i'), 569.0 / 2048.0);
    EXPECT_DOUBLE_EQ(text_width_em("Wi", dejavu()), (2025.0 + 569.0) / 2048.0);
    EXPECT_TRUE(dejavu().has_glyph(U'\u00df'));
    EXPECT_TRUE(dejavu().has_glyph(U'\u03a9'));   // Greek
    EXPECT_TRUE(dejavu().has_glyph(U'\u0416'));   // Cyrillic
    EXPECT_FALSE(dejavu().has_glyph(U'\u4e2d'));  // no CJK in DejaVu
}

TEST(LineBreak, LatinWordsStayWholeAndLinesFillGreedily) {
    for (const std::string* text : {&kParagraph, &kGerman}) {
        // Every word fits these widths ("Darstellungen", the longest, is about 7.5 ems).
        for (const double max_em : {9.0, 12.0, 25.0}) {
            const std::vector<std::string> lines = wrap_text(*text, dejavu(), max_em);
            ASSERT_GT(lines.size(), 1u);
            for (const std::string& line : lines) {
                EXPECT_LE(text_width_em(line, dejavu()), max_em) << line;
                EXPECT_FALSE(line.empty());
                EXPECT_NE(line.front(), ' ');
                EXPECT_NE(line.back(), ' ');
            }
            EXPECT_EQ(words_of(joined(lines, "\n")), words_of(*text)) << max_em;
            for (std::size_t i = 0; i + 1 < lines.size(); ++i) {
                const std::string next = words_of(lines[i + 1]).front();
                EXPECT_GT(text_width_em(lines[i] + " " + next, dejavu()), max_em);
            }
        }
    }
}

TEST(LineBreak, ExplicitBreaksEmptyLinesAndOverlongWords) {
    EXPECT_EQ(wrap_text("First line.\n\nThird line.", dejavu(), 100.0),
              (std::vector<std::string>{"First line.", "", "Third line."}));
    EXPECT_EQ(wrap_text("", dejavu(), 100.0), std::vector<std::string>{""});
    EXPECT_EQ(wrap_text("end\r\n", dejavu(), 100.0), (std::vector<std::string>{"end", ""}));
    const std::string word(60, 'W');
    const double max_em = text_width_em("WWWWWWWWWW", dejavu());  // ten of them fit
    const std::vector<std::string> lines = wrap_text("a " + word + " b", dejavu(), max_em);
    EXPECT_EQ(lines.front(), "a");
    EXPECT_EQ(joined(lines, ""), "a" + word + "b");
    EXPECT_EQ(lines[1], "WWWWWWWWWW");
    EXPECT_EQ(wrap_text("abc", dejavu(), 0.01).size(), 3u);  // a character a line at least
}

TEST(LineBreak, PairRulesOfUax14) {
    const auto allowed = [](std::u32string_view text, std::size_t i) {
        return break_allowed(text, i);
    };
    EXPECT_TRUE(allowed(U"\u4e2d\u6587", 1));   // ID / ID
    EXPECT_FALSE(allowed(U"\u4e2d\u3002", 1));  // never before 。(CL)
    EXPECT_FALSE(allowed(U"\u4e2d\uff0c", 1));  // never before ，
    EXPECT_FALSE(allowed(U"\u4e2d\u3001", 1));  // never before 、
    EXPECT_FALSE(allowed(U"\u4e2d\u300d", 1));  // never before 」
    EXPECT_FALSE(allowed(U"\u4e2d\u300f", 1));  // never before 』
    EXPECT_FALSE(allowed(U"\u4e2d\uff09", 1));  // never before ）
    EXPECT_FALSE(allowed(U"\u4e2d\uff01", 1));  // never before ！(EX)
    EXPECT_FALSE(allowed(U"\u4e2d\uff1f", 1));  // never before ？
    EXPECT_FALSE(allowed(U"\u30c6\u30fc", 1));  // never before ー (NS)
    EXPECT_FALSE(allowed(U"\u300c\u4e2d", 1));  // never after 「 (OP)
    EXPECT_FALSE(allowed(U"\uff08\u4e2d", 1));  // never after （
    EXPECT_TRUE(allowed(U"\u3002\u4e2d", 1));   // after 。
    EXPECT_TRUE(allowed(U"\u3002\u300c", 1));   // between 。and 「
    EXPECT_TRUE(allowed(U"\u4e2d\u300c", 1));   // before 「
    EXPECT_TRUE(allowed(U"\uac00\uac01", 1));   // Hangul syllables
    EXPECT_TRUE(allowed(U"\u3042\u30a2", 1));   // hiragana, katakana
    EXPECT_TRUE(allowed(U"VR\u4e2d", 2));       // AL / ID
    EXPECT_FALSE(allowed(U"ab", 1));            // AL AL
    EXPECT_TRUE(allowed(U"a b", 2));            // after the space
    EXPECT_FALSE(allowed(U"a b", 1));           // not before it
    EXPECT_FALSE(allowed(U"a !", 2));           // not before '!' even after a space
    EXPECT_FALSE(allowed(U"( a", 2));           // not after '(' and spaces
    EXPECT_FALSE(allowed(U"a\u00a0b", 2));      // no-break space
    EXPECT_TRUE(allowed(U"well-known", 5));     // after a hyphen between letters
    EXPECT_FALSE(allowed(U"a -5", 3));          // not in "-5"
}

// The sample's closing punctuation: 。，、」）！
const std::u32string kClosing = U"\u3002\uff0c\u3001\u300d\uff09\uff01";
constexpr std::size_t npos = std::u32string::npos;

TEST(LineBreak, ChineseBreaksBetweenCharactersButNotAtPunctuation) {
    const Font* font = wqy();
    if (font == nullptr)
        GTEST_SKIP() << kWqyMicroHei << " missing (apt-get install fonts-wqy-microhei)";
    for (const double max_em : {4.0, 5.0, 7.0, 9.5, 13.0}) {
        const std::vector<std::string> lines = wrap_text(kChinese, *font, max_em);
        ASSERT_GT(lines.size(), 2u) << max_em;
        EXPECT_EQ(joined(lines, ""), kChinese);  // nothing dropped, nothing added
        for (std::size_t i = 0; i < lines.size(); ++i) {
            const std::u32string line = testing::utf32(lines[i]);
            EXPECT_LE(text_width_em(line, *font), max_em) << lines[i];
            if (i > 0) {
                EXPECT_EQ(kClosing.find(line.front()), npos)
                    << "line " << i << " starts with closing punctuation: " << lines[i];
            }
            if (i + 1 < lines.size()) {
                EXPECT_EQ(std::u32string(U"\u300c\uff08").find(line.back()), std::u32string::npos)
                    << "line " << i << " ends with an opening bracket: " << lines[i];
                // Greedy: the next line's first character, with the closing marks that may not
                // be separated from it, would not have fitted; nor would the line's last
                // character have, had it been left alone before a closing mark.
                const std::u32string next_line = testing::utf32(lines[i + 1]);
                std::size_t unit = 1;
                while (unit < next_line.size() && kClosing.find(next_line[unit]) != npos) ++unit;
                EXPECT_GT(text_width_em(line + next_line.substr(0, unit), *font), max_em)
                    << lines[i] << " | " << lines[i + 1];
            }
        }
    }
    // Ideographs are one em wide in this font: 5 ems hold 5 of them, the sixth line-breaks.
    EXPECT_DOUBLE_EQ(font->advance(U'\u4e2d'), 1.0);
    EXPECT_EQ(wrap_text("\u4e00\u4e8c\u4e09\u56db\u4e94\u516d\u4e03", *font, 5.0),
              (std::vector<std::string>{"\u4e00\u4e8c\u4e09\u56db\u4e94", "\u516d\u4e03"}));
    // "一二三四。五": 。may not start a line, so 四 moves down with it.
    EXPECT_EQ(wrap_text("\u4e00\u4e8c\u4e09\u56db\u4e94\u3002\u516d", *font, 5.0),
              (std::vector<std::string>{"\u4e00\u4e8c\u4e09\u56db", "\u4e94\u3002\u516d"}));
    // "一二三四「五": 「 may not end a line.
    EXPECT_EQ(wrap_text("\u4e00\u4e8c\u4e09\u56db\u300c\u4e94\u300d", *font, 5.0),
              (std::vector<std::string>{"\u4e00\u4e8c\u4e09\u56db", "\u300c\u4e94\u300d"}));
    // Latin inside Chinese keeps its words: "VR" is not split.
    EXPECT_EQ(wrap_text("\u4e00\u4e8c\u4e09\u56dbVR\u4e94", *font, 5.0),
              (std::vector<std::string>{"\u4e00\u4e8c\u4e09\u56db", "VR\u4e94"}));
}

}  // namespace
}  // namespace monoplane::text
