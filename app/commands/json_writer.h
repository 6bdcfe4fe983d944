// A minimal JSON writer for the CLI's --json output: objects, arrays, strings and numbers, with
// correct escaping. Output keys are part of the public interface (DESIGN.md section 8).
#pragma once

#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace monoplane::app {

class JsonWriter {
  public:
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
    JsonWriter& value(std::string_view key, double number) {
        prefix(key);
        if (std::isfinite(number)) {
            std::ostringstream s;
            s.precision(10);
            s << number;
            out_ += s.str();
        } else {
            out_ += "null";  // JSON has no NaN or infinity
        }
        return *this;
    }
    JsonWriter& value(std::string_view key, std::uint64_t number) {
        prefix(key);
        out_ += std::to_string(number);
        return *this;
    }
    JsonWriter& value(std::string_view key, int number) {
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
        first_.pop_back();
        out_ += bracket;
        return *this;
    }
    void prefix(std::string_view key) {
        if (!first_.empty()) {
            if (!first_.back()) out_ += ',';
            first_.back() = false;
        }
        if (!key.empty()) {
            quoted(key);
            out_ += ':';
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
                case '\t':
                    out_ += "\\t";
                    break;
                default:
                    if (static_cast<unsigned char>(c) < 0x20) {
                        char buf[8];
                        std::snprintf(buf, sizeof buf, "\\u%04x", c);
                        out_ += buf;
                    } else {
                        out_ += c;
                    }
            }
        }
        out_ += '"';
    }

    std::string out_;
    std::vector<bool> first_;
};

}  // namespace monoplane::app
