// The project's one JSON writer: objects, arrays, strings and numbers, with correct escaping and
// no NaN (JSON has none, so a non-finite number is written null). Shared by the CLI's --json
// output (one line), the analysis report's summary.json (indented, every digit kept) and the
// study export (one trial per line).
// Numbers are formatted with std::to_chars, so the text is the same on every platform and locale.
// Output keys written with it are part of the public interface.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "common/programming_error.h"

namespace monoplane {

// The text of a finite `value`: with `significant_digits` > 0 as printf's "%.<digits>g", with 0
// the shortest text that reads back as the same double ("0.5", "39.5", "1e-12"). -0 is written
// "0".
inline std::string json_number_text(double value, int significant_digits = 0) {
    if (value == 0.0) return "0";  // also -0
    char buffer[64];
    const auto result = significant_digits > 0
                            ? std::to_chars(buffer, buffer + sizeof buffer, value,
                                            std::chars_format::general, significant_digits)
                            : std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

// True for text that is a number as JSON writes one (-?int[.frac][e[+-]exp]), which CSV readers
// take as a number too: no "+1", ".5", "5.", "007", "inf".
inline bool is_json_number(std::string_view text) {
    std::size_t at = text.starts_with('-') ? 1 : 0;
    const auto digits = [&] {
        const std::size_t from = at;
        while (at < text.size() && text[at] >= '0' && text[at] <= '9') ++at;
        return at - from;
    };
    const std::size_t whole = digits();
    if (whole == 0 || (whole > 1 && text[at - whole] == '0')) return false;
    if (at < text.size() && text[at] == '.' && (++at, digits() == 0)) return false;
    if (at < text.size() && (text[at] == 'e' || text[at] == 'E')) {
        ++at;
        if (at < text.size() && (text[at] == '+' || text[at] == '-')) ++at;
        if (digits() == 0) return false;
    }
    return at == text.size();
}

// Appends `text` as a JSON string literal, quotes included: '"' and '\\' escaped, \n, \r and
// \t as such, the other control characters as \u00xx; everything else, UTF-8 included, as it
// is. The one escaping rule of every JSON the project writes. Not nlohmann's dump(): it throws
// on invalid UTF-8, which a file path or a typed note may hold, and would write \b and \f
// differently from the outputs already written.
inline void append_json_quoted(std::string& out, std::string_view text) {
    out += '"';
    for (char c : text) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\r':
                out += "\\r";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
                    out += buf;
                } else {
                    out += c;
                }
        }
    }
    out += '"';
}

inline std::string json_quoted(std::string_view text) {
    std::string out;
    append_json_quoted(out, text);
    return out;
}

struct JsonFormat {
    // One key per line, indented by two spaces per level, with a newline after the document;
    // otherwise the whole document on one line with no spaces.
    bool indented = false;
    // Of a double's digits; 0: as many as it takes to read back the same double.
    int significant_digits = 10;
    // With indented: the members of only the outermost `line_levels` levels start lines of
    // their own (0: every level's); deeper members follow on the same line after ", ", keys
    // after ": ". An array of records with 1 reads one record per line.
    int line_levels = 0;
};

class JsonWriter {
  public:
    explicit JsonWriter(JsonFormat format = {}) : format_(format) {}

    JsonWriter& begin_object(std::string_view key = {}) { return open(key, '{'); }
    JsonWriter& end_object() { return close('}'); }
    JsonWriter& begin_array(std::string_view key = {}) { return open(key, '['); }
    JsonWriter& end_array() { return close(']'); }

    JsonWriter& value(std::string_view key, std::string_view text) {
        prefix(key);
        append_json_quoted(out_, text);
        return *this;
    }
    JsonWriter& value(std::string_view key, const char* text) {
        return value(key, std::string_view(text));
    }
    JsonWriter& value(std::string_view key, const std::string& text) {
        return value(key, std::string_view(text));
    }
    JsonWriter& value(std::string_view key, double number) {
        prefix(key);
        out_ +=
            std::isfinite(number) ? json_number_text(number, format_.significant_digits) : "null";
        return *this;
    }
    JsonWriter& value(std::string_view key, int number) {
        prefix(key);
        out_ += std::to_string(number);
        return *this;
    }
    JsonWriter& value(std::string_view key, std::int64_t number) {
        prefix(key);
        out_ += std::to_string(number);
        return *this;
    }
    JsonWriter& value(std::string_view key, std::uint64_t number) {
        prefix(key);
        out_ += std::to_string(number);
        return *this;
    }
    JsonWriter& value(std::string_view key, bool flag) {
        prefix(key);
        out_ += flag ? "true" : "false";
        return *this;
    }

    JsonWriter& null(std::string_view key) {
        prefix(key);
        out_ += "null";
        return *this;
    }

    // A number its caller has already formatted as JSON writes one (is_json_number), for digits a
    // double would not keep: exact decimal seconds of integer nanoseconds, stored text.
    JsonWriter& formatted_number(std::string_view key, std::string_view json_number) {
        MONOPLANE_EXPECTS(is_json_number(json_number));
        prefix(key);
        out_ += json_number;
        return *this;
    }

    const std::string& str() const { return out_; }

    // The text written since the last take (all of it, the first time), removed from the writer,
    // which goes on where it was: a long document is streamed as it is written.
    std::string take() {
        std::string text = std::move(out_);
        out_.clear();
        return text;
    }

  private:
    JsonWriter& open(std::string_view key, char bracket) {
        prefix(key);
        out_ += bracket;
        first_.push_back(true);
        return *this;
    }
    JsonWriter& close(char bracket) {
        const bool empty = first_.back();
        const bool members_on_lines = on_lines();
        first_.pop_back();
        if (members_on_lines && !empty) new_line();
        out_ += bracket;
        if (format_.indented && first_.empty()) out_ += '\n';
        return *this;
    }
    void new_line() {
        out_ += '\n';
        out_.append(2 * first_.size(), ' ');
    }
    // Whether the members of the innermost open level start lines of their own.
    bool on_lines() const {
        return format_.indented && (format_.line_levels <= 0 ||
                                    first_.size() <= static_cast<std::size_t>(format_.line_levels));
    }
    void prefix(std::string_view key) {
        if (!first_.empty()) {
            const bool first = first_.back();
            if (!first) out_ += ',';
            first_.back() = false;
            if (on_lines())
                new_line();
            else if (format_.indented && !first)
                out_ += ' ';
        }
        if (!key.empty()) {
            append_json_quoted(out_, key);
            out_ += format_.indented ? ": " : ":";
        }
    }
    JsonFormat format_;
    std::string out_;
    std::vector<bool> first_;
};

}  // namespace monoplane
