#include "text/line_break.h"

#include <algorithm>
#include <array>

#include "text/utf8.h"

namespace monoplane::text {
namespace {

struct ClassRange {
    char32_t first;
    char32_t last;
    BreakClass cls;
};

// The classes of LineBreak.txt (UAX #14's data file) for the characters this subset treats
// apart from their neighbours; sorted, checked before the ideographic blocks below.
constexpr std::array<ClassRange, 78> kPunctuation = {{
    {0x09, 0x09, BreakClass::Space},          {0x20, 0x20, BreakClass::Space},
    {0x21, 0x21, BreakClass::Exclamation},    {0x22, 0x22, BreakClass::Quote},
    {0x27, 0x27, BreakClass::Quote},          {0x28, 0x28, BreakClass::Opening},
    {0x29, 0x29, BreakClass::Closing},        {0x2C, 0x2C, BreakClass::Nonstarter},
    {0x2D, 0x2D, BreakClass::Hyphen},         {0x2E, 0x2E, BreakClass::Nonstarter},
    {0x3A, 0x3B, BreakClass::Nonstarter},     {0x3F, 0x3F, BreakClass::Exclamation},
    {0x5B, 0x5B, BreakClass::Opening},        {0x5D, 0x5D, BreakClass::Closing},
    {0x7B, 0x7B, BreakClass::Opening},        {0x7D, 0x7D, BreakClass::Closing},
    {0xA0, 0xA0, BreakClass::Glue},           {0xAB, 0xAB, BreakClass::Quote},
    {0xBB, 0xBB, BreakClass::Quote},          {0x2007, 0x2007, BreakClass::Glue},
    {0x2010, 0x2010, BreakClass::Hyphen},     {0x2011, 0x2011, BreakClass::Glue},
    {0x2013, 0x2014, BreakClass::Hyphen},     {0x2018, 0x2019, BreakClass::Quote},
    {0x201A, 0x201A, BreakClass::Opening},    {0x201B, 0x201D, BreakClass::Quote},
    {0x201E, 0x201E, BreakClass::Opening},    {0x201F, 0x201F, BreakClass::Quote},
    {0x2026, 0x2026, BreakClass::Nonstarter}, {0x202F, 0x202F, BreakClass::Glue},
    {0x2039, 0x203A, BreakClass::Quote},      {0x203C, 0x203C, BreakClass::Nonstarter},
    {0x2047, 0x2049, BreakClass::Nonstarter}, {0x2060, 0x2060, BreakClass::Glue},
    {0x3000, 0x3000, BreakClass::Space},      {0x3001, 0x3002, BreakClass::Closing},
    {0x3005, 0x3005, BreakClass::Nonstarter}, {0x3008, 0x3008, BreakClass::Opening},
    {0x3009, 0x3009, BreakClass::Closing},    {0x300A, 0x300A, BreakClass::Opening},
    {0x300B, 0x300B, BreakClass::Closing},    {0x300C, 0x300C, BreakClass::Opening},
    {0x300D, 0x300D, BreakClass::Closing},    {0x300E, 0x300E, BreakClass::Opening},
    {0x300F, 0x300F, BreakClass::Closing},    {0x3010, 0x3010, BreakClass::Opening},
    {0x3011, 0x3011, BreakClass::Closing},    {0x3014, 0x3014, BreakClass::Opening},
    {0x3015, 0x3015, BreakClass::Closing},    {0x3016, 0x3016, BreakClass::Opening},
    {0x3017, 0x3017, BreakClass::Closing},    {0x3018, 0x3018, BreakClass::Opening},
    {0x3019, 0x3019, BreakClass::Closing},    {0x301A, 0x301A, BreakClass::Opening},
    {0x301B, 0x301B, BreakClass::Closing},    {0x301C, 0x301C, BreakClass::Nonstarter},
    {0x301D, 0x301D, BreakClass::Opening},    {0x301E, 0x301F, BreakClass::Closing},
    {0x3041, 0x3041, BreakClass::Nonstarter}, {0x3043, 0x3043, BreakClass::Nonstarter},
    {0x3045, 0x3045, BreakClass::Nonstarter}, {0x3047, 0x3047, BreakClass::Nonstarter},
    {0x3049, 0x3049, BreakClass::Nonstarter}, {0x3063, 0x3063, BreakClass::Nonstarter},
    {0x3083, 0x3083, BreakClass::Nonstarter}, {0x3085, 0x3085, BreakClass::Nonstarter},
    {0x3087, 0x3087, BreakClass::Nonstarter}, {0x30A1, 0x30A1, BreakClass::Nonstarter},
    {0x30C3, 0x30C3, BreakClass::Nonstarter}, {0x30FB, 0x30FC, BreakClass::Nonstarter},
    {0xFEFF, 0xFEFF, BreakClass::Glue},       {0xFF01, 0xFF01, BreakClass::Exclamation},
    {0xFF08, 0xFF08, BreakClass::Opening},    {0xFF09, 0xFF09, BreakClass::Closing},
    {0xFF0C, 0xFF0C, BreakClass::Closing},    {0xFF0E, 0xFF0E, BreakClass::Closing},
    {0xFF1A, 0xFF1B, BreakClass::Nonstarter}, {0xFF1F, 0xFF1F, BreakClass::Exclamation},
}};

// The East Asian blocks whose characters are ID (or H2/H3 for Hangul syllables, which break
// alike): a line may break before and after each.
constexpr std::array<std::pair<char32_t, char32_t>, 9> kIdeographic = {{
    {0x2E80, 0x303F},    // CJK radicals, ideographic description, CJK symbols
    {0x3040, 0x31FF},    // hiragana, katakana, bopomofo, Hangul compatibility jamo, kanbun
    {0x3200, 0x4DBF},    // enclosed CJK, compatibility, extension A
    {0x4E00, 0x9FFF},    // CJK unified ideographs
    {0xA000, 0xA4CF},    // Yi
    {0xAC00, 0xD7AF},    // Hangul syllables
    {0xF900, 0xFAFF},    // CJK compatibility ideographs
    {0xFF00, 0xFFEF},    // full-width and half-width forms
    {0x20000, 0x3FFFD},  // supplementary ideographic planes
}};

bool is_east_asian(char32_t c) {
    return std::ranges::any_of(kIdeographic,
                               [c](const auto& r) { return c >= r.first && c <= r.second; });
}

bool closes(BreakClass c) {
    return c == BreakClass::Closing || c == BreakClass::Exclamation || c == BreakClass::Nonstarter;
}

// Whether a line may break after the spaces that end at text[i - 1] (LB14: not after an
// opening bracket and spaces; none at a paragraph's leading spaces).
bool break_after_spaces(std::u32string_view text, std::size_t i) {
    std::size_t j = i;
    while (j > 0 && break_class(text[j - 1]) == BreakClass::Space) --j;
    return j > 0 && break_class(text[j - 1]) != BreakClass::Opening;
}

// Where the greedy fill ends a line that starts at `start`: the furthest break opportunity
// whose line (trailing spaces dropped) fits, else the most characters that fit (at least one).
std::size_t line_end(std::u32string_view text, const std::vector<double>& prefix, std::size_t start,
                     double max_width) {
    const auto fits = [&](std::size_t end) {
        while (end > start && break_class(text[end - 1]) == BreakClass::Space) --end;
        return prefix[end] - prefix[start] <= max_width;
    };
    std::size_t best = 0;
    for (std::size_t i = start + 1; i <= text.size(); ++i) {
        if (i < text.size() && !break_allowed(text, i)) continue;
        if (!fits(i)) break;
        best = i;
    }
    if (best != 0) return best;
    std::size_t end = start + 1;
    while (end < text.size() && prefix[end + 1] - prefix[start] <= max_width) ++end;
    return end;
}

void wrap_paragraph(std::u32string_view text, const Font& font, double max_width,
                    std::vector<std::string>& lines) {
    std::vector<double> prefix(text.size() + 1, 0.0);
    for (std::size_t i = 0; i < text.size(); ++i)
        prefix[i + 1] = prefix[i] + font.advance(text[i] == '\t' ? U' ' : text[i]);
    const auto skip_spaces = [&](std::size_t i) {
        while (i < text.size() && break_class(text[i]) == BreakClass::Space) ++i;
        return i;
    };
    std::size_t start = skip_spaces(0);
    if (start == text.size()) {
        lines.emplace_back();  // an empty paragraph is an empty line
        return;
    }
    while (start < text.size()) {
        std::size_t end = line_end(text, prefix, start, max_width);
        std::size_t trimmed = end;
        while (trimmed > start && break_class(text[trimmed - 1]) == BreakClass::Space) --trimmed;
        lines.push_back(encode_utf8(text.substr(start, trimmed - start)));
        start = skip_spaces(end);
    }
}

}  // namespace

BreakClass break_class(char32_t c) {
    const auto found = std::ranges::find_if(
        kPunctuation, [c](const ClassRange& r) { return c >= r.first && c <= r.last; });
    if (found != kPunctuation.end()) return found->cls;
    return is_east_asian(c) ? BreakClass::Ideographic : BreakClass::Alphabetic;
}

bool break_allowed(std::u32string_view text, std::size_t i) {
    const BreakClass before = break_class(text[i - 1]);
    const BreakClass after = break_class(text[i]);
    if (after == BreakClass::Space) return false;  // LB7
    if (closes(after)) return false;               // LB13, LB16, LB21 (NS)
    if (after == BreakClass::Glue && before != BreakClass::Space) return false;   // LB12a
    if (before == BreakClass::Glue) return false;                                 // LB12
    if (before == BreakClass::Space) return break_after_spaces(text, i);          // LB14, LB18
    if (before == BreakClass::Opening) return false;                              // LB14
    if (before == BreakClass::Quote || after == BreakClass::Quote) return false;  // LB19
    if (before == BreakClass::Hyphen) {
        // LB21: after a hyphen between letters ("well-known"), not in "-5" or "a--".
        return after == BreakClass::Alphabetic && i >= 2 &&
               break_class(text[i - 2]) == BreakClass::Alphabetic;
    }
    if (before == BreakClass::Ideographic || after == BreakClass::Ideographic) return true;  // LB31
    // A full-width closing mark before Latin or an opening bracket: LB31 (LB30's "no break"
    // is for the narrow ones, as in "f(x)" or "(a)b").
    if (closes(before) && is_east_asian(text[i - 1])) return true;
    return false;  // LB28 and the rest: letters, digits and narrow punctuation stay together
}

std::vector<std::string> wrap_text(std::string_view text, const Font& font, double max_width_em) {
    std::u32string code_points = decode_utf8_lenient(text);
    std::erase(code_points, U'\r');
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (;;) {
        const std::size_t end = code_points.find(U'\n', start);
        const std::u32string_view all(code_points);
        wrap_paragraph(all.substr(start, end == std::u32string::npos ? end : end - start), font,
                       max_width_em, lines);
        if (end == std::u32string::npos) break;
        start = end + 1;
    }
    return lines;
}

double text_width_em(std::u32string_view text, const Font& font) {
    double width = 0.0;
    for (const char32_t c : text) {
        if (c != U'\r' && c != U'\n') width += font.advance(c == U'\t' ? U' ' : c);
    }
    return width;
}

double text_width_em(std::string_view utf8, const Font& font) {
    return text_width_em(decode_utf8_lenient(utf8), font);
}

}  // namespace monoplane::text
