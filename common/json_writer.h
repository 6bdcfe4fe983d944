// A minimal JSON writer: objects, arrays, strings and numbers, with correct escaping and no NaN
// (JSON has none, so a non-finite number is written null). Shared by the CLI's --json output (one
// line) and the analysis report's summary.json (indented, every digit kept).
// Numbers are formatted with std::to_chars, so the text is the same on every platform and locale.
// Output keys written with it are part of the public interface.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

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

struct JsonFormat {
    // One key per line, indented by two spaces per level, with a newline after the document;
    // otherwise the whole document on one line with no spaces.
    bool indented = false;
    // Of a double's digits; 0: as many as it takes to read back the same double.
    int significant_digits = 10;
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
        quoted(text);
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

    const std::string& str() const { return out_; }

  private:
    JsonWriter& open(std::string_view key, char bracket) {
        prefix(key);
        out_ += bracket;
        first_.push_back(true);
        return *this;
    }
    JsonWriter& close(char bracket) {
        const bool empty = first_.back();
        first_.pop_back();
        if (format_.indented && !empty) new_line();
        out_ += bracket;
        if (format_.indented && first_.empty()) out_ += '\n';
        return *this;
    }
    void new_line() {
        out_ += '\n';
        out_.append(2 * first_.size(), ' ');
    }
    void prefix(std::string_view key) {
        if (!first_.empty()) {
            if (!first_.back()) out_ += ',';
            first_.back() = false;
            if (format_.indented) new_line();
        }
        if (!key.empty()) {
            quoted(key);
            out_ += format_.indented ? ": " : ":";
        }
    }
    void quoted(std::string_view text) {
        out_ += '"';
        for (char c : text) {
            switch (c) {
                case '"':
                    out_ += "\\\"";
                    break;
                case '\\':
                    out_ += "\\\\";
                    break;
                case '\n':
                    out_ += "\\n";
                    break;
                case '\r':
                    out_ += "\\r";
                    break;
                case '\t':
                    out_ += "\\t";
                    break;
                default:
                    if (static_cast<unsigned char>(c) < 0x20) {
                        char buf[8];
                        std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(c));
                        out_ += buf;
                    } else {
                        out_ += c;
                    }
            }
        }
        out_ += '"';
    }

    JsonFormat format_;
    std::string out_;
    std::vector<bool> first_;
};

}  // namespace monoplane
