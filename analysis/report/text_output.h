// Text formats the report writes: a small JSON writer (stable key order, no NaN: JSON has none, so
// a non-finite number is written null) and RFC 4180 CSV fields. Numbers are formatted the same
// on every platform and locale, so two runs over the same data give the same files.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace monoplane::analysis::report {

// The shortest text that reads back as the same double ("0.5", "39.5", "1e-12"); "" for NaN or
// infinity (an empty CSV field reads as NA in R and pandas).
std::string number_text(double value);

// A CSV field: quoted when it holds a comma, quote, CR or LF, with inner quotes doubled.
std::string csv_field(std::string_view text);
// One CSV line (with "\n") from already formatted fields.
std::string csv_line(const std::vector<std::string>& fields);

// Text with &, <, >, " and ' as entities: safe as HTML element content and attribute value.
std::string html_escaped(std::string_view text);

class JsonWriter {
  public:
    JsonWriter& begin_object(std::string_view key = {});
    JsonWriter& end_object();
    JsonWriter& begin_array(std::string_view key = {});
    JsonWriter& end_array();

    JsonWriter& value(std::string_view key, std::string_view text);
    JsonWriter& value(std::string_view key, const char* text) {
        return value(key, std::string_view(text));
    }
    JsonWriter& value(std::string_view key, const std::string& text) {
        return value(key, std::string_view(text));
    }
    JsonWriter& value(std::string_view key, double number);  // null when not finite
    JsonWriter& value(std::string_view key, int number);
    JsonWriter& value(std::string_view key, std::int64_t number);
    JsonWriter& value(std::string_view key, bool flag);
    JsonWriter& null(std::string_view key);

    // The document, one key per line, indented by two spaces per level.
    const std::string& str() const { return out_; }

  private:
    JsonWriter& open(std::string_view key, char bracket);
    JsonWriter& close(char bracket);
    void prefix(std::string_view key);
    void quoted(std::string_view text);

    std::string out_;
    std::vector<bool> first_;
};

}  // namespace monoplane::analysis::report
