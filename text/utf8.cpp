#include "text/utf8.h"

#include <array>
#include <cstdio>

namespace monoplane::text {
namespace {

constexpr char32_t kReplacement = 0xFFFD;

// The code point at utf8[i] and its length in bytes; length 0 for an invalid sequence.
std::pair<char32_t, std::size_t> decode_one(std::string_view utf8, std::size_t i) {
    const auto lead = static_cast<unsigned char>(utf8[i]);
    if (lead < 0x80) return {lead, 1};
    const std::size_t length = (lead >> 5) == 0x6    ? 2
                               : (lead >> 4) == 0xE  ? 3
                               : (lead >> 3) == 0x1E ? 4
                                                     : 0;
    if (length == 0 || i + length > utf8.size()) return {0, 0};
    char32_t code = lead & (0x7F >> length);
    for (std::size_t k = 1; k < length; ++k) {
        const auto next = static_cast<unsigned char>(utf8[i + k]);
        if ((next & 0xC0) != 0x80) return {0, 0};
        code = (code << 6) | (next & 0x3F);
    }
    // The shortest form only, no surrogates, nothing past U+10FFFF (RFC 3629, section 3).
    constexpr std::array<char32_t, 5> kSmallest = {0, 0, 0x80, 0x800, 0x10000};
    if (code < kSmallest[length] || (code >= 0xD800 && code <= 0xDFFF) || code > 0x10FFFF)
        return {0, 0};
    return {code, length};
}

}  // namespace

std::optional<std::u32string> decode_utf8(std::string_view utf8) {
    std::u32string out;
    for (std::size_t i = 0; i < utf8.size();) {
        const auto [code, length] = decode_one(utf8, i);
        if (length == 0) return std::nullopt;
        out += code;
        i += length;
    }
    return out;
}

std::optional<std::size_t> first_invalid_utf8(std::string_view utf8) {
    for (std::size_t i = 0; i < utf8.size();) {
        const std::size_t length = decode_one(utf8, i).second;
        if (length == 0) return i;
        i += length;
    }
    return std::nullopt;
}

std::u32string decode_utf8_lenient(std::string_view utf8) {
    std::u32string out;
    for (std::size_t i = 0; i < utf8.size();) {
        const auto [code, length] = decode_one(utf8, i);
        out += length == 0 ? kReplacement : code;
        i += length == 0 ? 1 : length;
    }
    return out;
}

std::string encode_utf8(char32_t c) {
    std::string out;
    if (c < 0x80) {
        out += static_cast<char>(c);
    } else if (c < 0x800) {
        out += static_cast<char>(0xC0 | (c >> 6));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += static_cast<char>(0xE0 | (c >> 12));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
        out += static_cast<char>(0xF0 | (c >> 18));
        out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
        out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
        out += static_cast<char>(0x80 | (c & 0x3F));
    }
    return out;
}

std::string encode_utf8(std::u32string_view code_points) {
    std::string out;
    for (const char32_t c : code_points) out += encode_utf8(c);
    return out;
}

std::string code_point_label(char32_t code_point) {
    std::array<char, 16> buffer{};
    std::snprintf(buffer.data(), buffer.size(), "U+%04X", static_cast<unsigned>(code_point));
    return buffer.data();
}

}  // namespace monoplane::text
