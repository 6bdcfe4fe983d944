// UTF-8 text as code points (RFC 3629), for measuring, breaking and checking what a font draws.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace monoplane::text {

// The code points of `utf8`, or nothing when it is not valid UTF-8 (a stray continuation byte,
// a truncated or overlong sequence, a surrogate, beyond U+10FFFF). Any time.
std::optional<std::u32string> decode_utf8(std::string_view utf8);

// The byte offset of the first invalid sequence in `utf8`, or nothing when all of it is valid.
std::optional<std::size_t> first_invalid_utf8(std::string_view utf8);

// As decode_utf8, each invalid byte read as U+FFFD (the replacement character), so that text
// from anywhere can be drawn.
std::u32string decode_utf8_lenient(std::string_view utf8);

std::string encode_utf8(char32_t code_point);
std::string encode_utf8(std::u32string_view code_points);

// "U+00E4": how the Unicode Standard names a code point (at least four hex digits).
std::string code_point_label(char32_t code_point);

}  // namespace monoplane::text
