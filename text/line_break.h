// Where a paragraph may break into lines, and the greedy fill of lines to a width: a subset of
// the Unicode Line Breaking Algorithm (UAX #14, https://www.unicode.org/reports/tr14/) that is
// enough for European scripts and Chinese, Japanese and Korean, which write no spaces between
// words. Widths are the font's advances (no kerning: text is not shaped).
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "text/font.h"

namespace monoplane::text {

// UAX #14's line breaking classes that this subset tells apart (section 5.1 names them).
enum class BreakClass {
    Alphabetic,   // AL and everything not listed below: breaks only at spaces
    Space,        // SP: a break opportunity after a run of them
    Glue,         // GL: no-break spaces and the word joiner, never broken at
    Ideographic,  // ID: CJK ideographs, kana, Hangul syllables, full-width forms
    Opening,      // OP: opening brackets and quotes; never a break after one
    Closing,      // CL/CP: closing brackets and CJK full stops and commas; never before one
    Exclamation,  // EX: ! ? and their full-width forms; never before one
    Nonstarter,  // NS/IS: small kana, the prolonged sound mark, ・, and , . : ; never start a line
    Quote,       // QU: quotation marks that may open or close; no break beside one
    Hyphen,      // HY/BA: a break opportunity after a hyphen or dash that follows a letter
};

BreakClass break_class(char32_t code_point);

// Whether a line may break between code points text[i - 1] and text[i] (0 < i < size): the
// pair rules LB7 to LB31 of UAX #14 for the classes above. Spaces stay at the end of the
// earlier line (LB7, LB18).
bool break_allowed(std::u32string_view text, std::size_t i);

// `text` (UTF-8; line breaks start new lines, empty lines are kept) broken into lines no wider
// than max_width_em at the break opportunities above, each filled greedily. Spaces at a break
// are dropped. Only a run without break opportunity that is wider than a whole line is split
// between characters (at least one character a line). Invalid UTF-8 reads as U+FFFD.
std::vector<std::string> wrap_text(std::string_view text, const Font& font, double max_width_em);

// A line's width in ems: the sum of its characters' advances (a tab is a space, a carriage
// return takes none; both are drawn so).
double text_width_em(std::string_view utf8, const Font& font);
double text_width_em(std::u32string_view text, const Font& font);

}  // namespace monoplane::text
