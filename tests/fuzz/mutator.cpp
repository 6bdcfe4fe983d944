#include "tests/fuzz/mutator.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <utility>

namespace monoplane::fuzz {
namespace {

using namespace std::string_view_literals;

// Values at the edges of what parsers convert: zero and signed zero, -1, the double range and its
// subnormals, non-finite values in TOML's and C's spellings, and integers at and beyond the
// 32- and 64-bit limits (TOML integers are 64-bit; beyond that is a syntax error).
constexpr std::array kExtremeNumbers = {
    "0"sv,
    "-0"sv,
    "-1"sv,
    "1"sv,
    "0.0"sv,
    "-0.0"sv,
    "1e308"sv,
    "-1e308"sv,
    "1.7976931348623157e308"sv,
    "1e309"sv,
    "1e-308"sv,
    "5e-324"sv,
    "nan"sv,
    "+nan"sv,
    "-nan"sv,
    "inf"sv,
    "+inf"sv,
    "-inf"sv,
    "NaN"sv,
    "Infinity"sv,
    "2147483647"sv,
    "2147483648"sv,
    "-2147483649"sv,
    "4294967296"sv,
    "9007199254740993"sv,
    "9.0e15"sv,
    "9223372036854775807"sv,
    "-9223372036854775808"sv,
    "9223372036854775808"sv,
    "18446744073709551616"sv,
    "99999999999999999999999999999"sv,
    "0x7fffffffffffffff"sv,
    "0xffffffffffffffff"sv,
    "0o777"sv,
    "0b1"sv,
    "1_000"sv,
    "1e10"sv,
    "1e19"sv,
    "16384"sv,
    "16385"sv,
    "15"sv,
    "0.1"sv,
    "1000"sv,
    "1e-9"sv,
};

// TOML and CSV syntax, string escapes, and byte sequences that are not valid UTF-8 (a lone
// continuation byte, an overlong form, a surrogate, a code point above U+10FFFF), a BOM, NUL.
constexpr std::array kSpecials = {
    "\""sv,
    "'"sv,
    "\"\"\""sv,
    "'''"sv,
    "["sv,
    "]"sv,
    "[["sv,
    "]]"sv,
    "{"sv,
    "}"sv,
    "="sv,
    ","sv,
    "."sv,
    "#"sv,
    "\\"sv,
    "\\u"sv,
    "\\uD800"sv,
    "\\U0010FFFF"sv,
    "\\U00110000"sv,
    "\\x41"sv,
    "\n"sv,
    "\r"sv,
    "\r\n"sv,
    "\t"sv,
    " "sv,
    "\0"sv,
    "\x7f"sv,
    "\x80"sv,
    "\xff"sv,
    "\xc0\xaf"sv,
    "\xc3"sv,
    "\xef\xbb\xbf"sv,
    "\xed\xa0\x80"sv,
    "\xf4\x90\x80\x80"sv,
    "\xe2\x80\xa8"sv,
    "a.b"sv,
    "\"\" = 1"sv,
    "x = {"sv,
    "x = ["sv,
    "[a]\n"sv,
    "[[a]]\n"sv,
    "a = 1\n"sv,
    "1979-05-27T07:32:00Z"sv,
    "07:32:00"sv,
    "1979-05-27"sv,
    "true"sv,
    "false"sv,
    "\"\""sv,
    ",,"sv,
    "NA"sv,
    "TRUE"sv,
    "False"sv,
    "\"a,b\""sv,
    "\"\n\""sv,
};

constexpr std::array<unsigned char, 12> kSpecialBytes = {0x00, 0xff, 0x7f, 0x80, '\n', '\r',
                                                         '"',  ',',  '=',  '[',  ']',  '\\'};

bool is_word_start(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || c == '_' || c == '/';
}
bool is_word_char(char c) {
    return is_word_start(c) || (c >= '0' && c <= '9') || c == '.' || c == '-';
}
bool is_digit(char c) {
    return c >= '0' && c <= '9';
}

struct Span {
    std::size_t begin;
    std::size_t end;
};

// The end of the comment line that starts at i, or i when none does: the structure-aware
// mutations skip whole-line comments (the repository's files have many), whose words and
// numbers no parser reads.
std::size_t skip_comment_line(std::string_view text, std::size_t i) {
    if (i != 0 && text[i - 1] != '\n') return i;
    std::size_t first = i;
    while (first < text.size() && (text[first] == ' ' || text[first] == '\t')) ++first;
    if (first >= text.size() || text[first] != '#') return i;
    const std::size_t newline = text.find('\n', first);
    return newline == std::string_view::npos ? text.size() : newline;
}

// Numbers as a scanner sees them: a digit run (with sign, point, exponent, TOML's _ and date
// dashes) that does not continue a word, so "msaa4" keeps its 4.
std::vector<Span> number_spans(std::string_view text) {
    std::vector<Span> spans;
    std::size_t i = 0;
    while (i < text.size()) {
        if (const std::size_t after = skip_comment_line(text, i); after != i) {
            i = after;
            continue;
        }
        const bool starts = is_digit(text[i]) || ((text[i] == '-' || text[i] == '+') &&
                                                  i + 1 < text.size() && is_digit(text[i + 1]));
        if (!starts || (i > 0 && is_word_char(text[i - 1]))) {
            ++i;
            continue;
        }
        std::size_t end = i + 1;
        while (end < text.size() && (is_word_char(text[end]) || text[end] == '+')) ++end;
        spans.push_back({i, end});
        i = end;
    }
    return spans;
}

std::vector<Span> word_spans(std::string_view text) {
    std::vector<Span> spans;
    std::size_t i = 0;
    while (i < text.size()) {
        if (const std::size_t after = skip_comment_line(text, i); after != i) {
            i = after;
            continue;
        }
        if (!is_word_start(text[i])) {
            ++i;
            continue;
        }
        std::size_t end = i + 1;
        while (end < text.size() && is_word_char(text[end])) ++end;
        spans.push_back({i, end});
        i = end;
    }
    return spans;
}

// Each line with its line break.
std::vector<Span> line_spans(std::string_view text) {
    std::vector<Span> spans;
    std::size_t begin = 0;
    while (begin < text.size()) {
        const std::size_t newline = text.find('\n', begin);
        const std::size_t end = newline == std::string_view::npos ? text.size() : newline + 1;
        spans.push_back({begin, end});
        begin = end;
    }
    return spans;
}

// A position in text, 0..size inclusive.
std::size_t position(const std::string& text, Prng& rng) {
    return rng.below(text.size() + 1);
}

// A short range inside text (length 1..max, clamped); text must not be empty.
Span short_range(const std::string& text, Prng& rng, std::size_t max_length) {
    const std::size_t begin = rng.below(text.size());
    const std::size_t length = 1 + rng.below(max_length);
    return {begin, std::min(text.size(), begin + length)};
}

template <class Container>
const auto& pick(const Container& items, Prng& rng) {
    return items[rng.below(items.size())];
}

std::string at(std::string_view name, std::size_t where) {
    return std::string(name) + "@" + std::to_string(where);
}

}  // namespace

std::vector<std::string> split_words(std::string_view text) {
    std::vector<std::string> words;
    std::size_t i = 0;
    while (i < text.size()) {
        const std::size_t begin = text.find_first_not_of(" \t\n", i);
        if (begin == std::string_view::npos) break;
        const std::size_t end = std::min(text.size(), text.find_first_of(" \t\n", begin));
        words.emplace_back(text.substr(begin, end - begin));
        i = end;
    }
    return words;
}

std::vector<std::string> words_of(std::string_view text) {
    constexpr std::size_t kMaxWordLength = 80;
    std::vector<std::string> words;
    const auto add = [&](std::string_view word) {
        if (word.size() > kMaxWordLength) return;
        if (std::ranges::find(words, word) == words.end()) words.emplace_back(word);
    };
    for (const Span& span : word_spans(text)) add(text.substr(span.begin, span.end - span.begin));
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '"') continue;
        const std::size_t close = text.find_first_of("\"\n", i + 1);
        if (close == std::string_view::npos || text[close] != '"') continue;
        add(text.substr(i, close + 1 - i));
        i = close;
    }
    return words;
}

Mutator::Mutator(std::vector<std::string> corpus, std::vector<std::string> dictionary,
                 std::size_t max_size)
    : corpus_(std::move(corpus)), max_size_(max_size) {
    assert(!corpus_.empty());
    for (std::string& word : dictionary) {
        if (!word.empty() && std::ranges::find(dictionary_, word) == dictionary_.end())
            dictionary_.push_back(std::move(word));
    }
    for (const std::string& input : corpus_) {
        for (std::string& word : words_of(input)) {
            if (std::ranges::find(dictionary_, word) == dictionary_.end())
                dictionary_.push_back(std::move(word));
        }
    }
    if (dictionary_.empty()) dictionary_.emplace_back("x");
}

Mutant Mutator::mutant(std::uint64_t seed, std::uint64_t iteration) const {
    // Iterations are independent of each other: any one can be replayed alone.
    Prng rng(seed ^ (iteration * 0xD1B54A32D192ED03ull));
    rng.next();
    const std::size_t base = rng.below(corpus_.size());
    Mutant mutant{corpus_[base], "corpus " + std::to_string(base)};
    std::size_t count = 1 + rng.below(3);
    if (rng.one_in(4)) count += rng.below(10);
    for (std::size_t i = 0; i < count; ++i) {
        mutate_once(mutant.bytes, rng, mutant.history);
        if (mutant.bytes.size() > max_size_) mutant.bytes.resize(max_size_);
    }
    return mutant;
}

void Mutator::mutate_once(std::string& bytes, Prng& rng, std::string& history) const {
    enum Kind {
        kFlipBit,
        kSetByte,
        kInsertByte,
        kDeleteRange,
        kDuplicateRange,
        kSplice,
        kInsertChunk,
        kExtremeNumber,
        kTruncate,
        kDuplicateLine,
        kDeleteLine,
        kSwapLines,
        kTransplantLine,
        kInsertSpecial,
        kReplaceWord,
        kInsertWord,
        kRepeat,
        kKinds
    };
    // The structure-aware mutations reach deeper into a parser than byte noise, which mostly
    // stops at the first syntax check: they come up more often.
    constexpr std::array<Kind, 24> kWeighted = {
        kFlipBit,        kSetByte,       kInsertByte,    kDeleteRange,   kDuplicateRange,
        kSplice,         kInsertChunk,   kExtremeNumber, kExtremeNumber, kExtremeNumber,
        kTruncate,       kDuplicateLine, kDuplicateLine, kDeleteLine,    kSwapLines,
        kTransplantLine, kInsertSpecial, kInsertSpecial, kReplaceWord,   kReplaceWord,
        kReplaceWord,    kInsertWord,    kInsertWord,    kRepeat};
    static_assert(kKinds == 17);
    const Kind kind = pick(kWeighted, rng);
    const std::string& other = pick(corpus_, rng);

    if (bytes.empty() && kind != kInsertChunk && kind != kSplice && kind != kInsertSpecial &&
        kind != kInsertWord && kind != kInsertByte) {
        bytes = other;  // nothing to mutate in place: start again from another input
        history += "; restart";
        return;
    }
    switch (kind) {
        case kFlipBit: {
            const std::size_t where = rng.below(bytes.size());
            bytes[where] = static_cast<char>(bytes[where] ^ (1u << rng.below(8)));
            history += "; " + at("flip-bit", where);
            break;
        }
        case kSetByte: {
            const std::size_t where = rng.below(bytes.size());
            bytes[where] =
                static_cast<char>(rng.one_in(2) ? pick(kSpecialBytes, rng) : rng.below(256));
            history += "; " + at("set-byte", where);
            break;
        }
        case kInsertByte: {
            const std::size_t where = position(bytes, rng);
            bytes.insert(
                bytes.begin() + static_cast<std::ptrdiff_t>(where),
                static_cast<char>(rng.one_in(2) ? pick(kSpecialBytes, rng) : rng.below(256)));
            history += "; " + at("insert-byte", where);
            break;
        }
        case kDeleteRange: {
            const Span span = short_range(bytes, rng, rng.one_in(4) ? 256 : 8);
            bytes.erase(span.begin, span.end - span.begin);
            history += "; " + at("delete", span.begin);
            break;
        }
        case kDuplicateRange: {
            const Span span = short_range(bytes, rng, rng.one_in(4) ? 512 : 16);
            const std::string copy = bytes.substr(span.begin, span.end - span.begin);
            const std::size_t where = rng.one_in(2) ? span.end : position(bytes, rng);
            bytes.insert(where, copy);
            history += "; " + at("duplicate", span.begin);
            break;
        }
        case kSplice: {
            const std::size_t cut = position(bytes, rng);
            const std::size_t from = rng.below(other.size() + 1);
            bytes = bytes.substr(0, cut) + other.substr(from);
            history += "; " + at("splice", cut);
            break;
        }
        case kInsertChunk: {
            if (other.empty()) break;
            const Span span = short_range(other, rng, 128);
            const std::size_t where = position(bytes, rng);
            bytes.insert(where, other.substr(span.begin, span.end - span.begin));
            history += "; " + at("insert-chunk", where);
            break;
        }
        case kExtremeNumber: {
            const std::vector<Span> numbers = number_spans(bytes);
            const std::string_view value = pick(kExtremeNumbers, rng);
            if (numbers.empty()) {
                const std::size_t where = position(bytes, rng);
                bytes.insert(where, value);
                history += "; " + at("insert-number", where);
                break;
            }
            const Span span = pick(numbers, rng);
            bytes.replace(span.begin, span.end - span.begin, value);
            history += "; " + at("extreme-number", span.begin);
            break;
        }
        case kTruncate: {
            const std::size_t where = rng.below(bytes.size());
            bytes.resize(where);
            history += "; " + at("truncate", where);
            break;
        }
        case kDuplicateLine:
        case kDeleteLine:
        case kSwapLines: {
            const std::vector<Span> lines = line_spans(bytes);
            const Span a = pick(lines, rng);
            const std::string line = bytes.substr(a.begin, a.end - a.begin);
            if (kind == kDuplicateLine) {
                const Span b = rng.one_in(2) ? a : pick(lines, rng);
                bytes.insert(b.end, line.ends_with('\n') ? line : line + "\n");
                history += "; " + at("duplicate-line", a.begin);
            } else if (kind == kDeleteLine) {
                bytes.erase(a.begin, a.end - a.begin);
                history += "; " + at("delete-line", a.begin);
            } else {
                const Span b = pick(lines, rng);
                if (b.begin == a.begin) break;
                const Span first = a.begin < b.begin ? a : b;
                const Span second = a.begin < b.begin ? b : a;
                const std::string first_text = bytes.substr(first.begin, first.end - first.begin);
                const std::string second_text =
                    bytes.substr(second.begin, second.end - second.begin);
                bytes.replace(second.begin, second.end - second.begin, first_text);
                bytes.replace(first.begin, first.end - first.begin, second_text);
                history += "; " + at("swap-lines", first.begin);
            }
            break;
        }
        case kTransplantLine: {
            if (other.empty()) break;
            const Span line = pick(line_spans(other), rng);
            const std::vector<Span> lines = line_spans(bytes);
            const std::size_t where = pick(lines, rng).end;
            std::string text = other.substr(line.begin, line.end - line.begin);
            if (!text.ends_with('\n')) text += '\n';
            if (where > 0 && bytes[where - 1] != '\n') text.insert(0, "\n");
            bytes.insert(where, text);
            history += "; " + at("transplant-line", where);
            break;
        }
        case kInsertSpecial: {
            const std::size_t where = position(bytes, rng);
            bytes.insert(where, pick(kSpecials, rng));
            history += "; " + at("insert-special", where);
            break;
        }
        case kReplaceWord: {
            const std::vector<Span> words = word_spans(bytes);
            const std::string& word = pick(dictionary_, rng);
            if (words.empty()) {
                bytes.insert(position(bytes, rng), word);
                history += "; insert-word";
                break;
            }
            const Span span = pick(words, rng);
            bytes.replace(span.begin, span.end - span.begin, word);
            history += "; " + at("replace-word", span.begin);
            break;
        }
        case kInsertWord: {
            // At a line start most of the time, where a key or a table header would go.
            std::size_t where = position(bytes, rng);
            if (!rng.one_in(4)) {
                const std::vector<Span> lines = line_spans(bytes);
                where = lines.empty() ? 0 : pick(lines, rng).begin;
            }
            std::string text = pick(dictionary_, rng);
            if (rng.one_in(2)) {
                text += " = " + (rng.one_in(2) ? std::string(pick(kExtremeNumbers, rng))
                                               : pick(dictionary_, rng));
                text += '\n';
            }
            bytes.insert(where, text);
            history += "; " + at("insert-word", where);
            break;
        }
        case kRepeat: {
            // Deep nesting ("[[[[", "{{{{"), long keys and strings, many separators.
            const std::string_view unit =
                rng.one_in(2) ? pick(kSpecials, rng) : std::string_view(pick(dictionary_, rng));
            const std::size_t times = 2 + rng.below(rng.one_in(4) ? 2000 : 64);
            std::string text;
            for (std::size_t i = 0; i < times && text.size() < max_size_; ++i) text += unit;
            const std::size_t where = position(bytes, rng);
            bytes.insert(where, text);
            history += "; " + at("repeat", where) + "x" + std::to_string(times);
            break;
        }
        case kKinds:
            break;
    }
}

}  // namespace monoplane::fuzz
