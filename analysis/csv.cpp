#include "analysis/csv.h"

namespace monoplane::analysis {

Result<std::vector<CsvRecord>> parse_csv(std::string_view text, const std::string& file_name) {
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    std::vector<CsvRecord> records;
    CsvRecord record;
    std::string field;
    int line = 1;
    record.line = line;
    bool field_was_quoted = false;

    const auto end_record = [&] {
        record.fields.push_back(std::move(field));
        field.clear();
        field_was_quoted = false;
        const bool blank = record.fields.size() == 1 && record.fields[0].empty();
        if (!blank) records.push_back(std::move(record));
        record = CsvRecord{};  // its line is set by the caller, which knows where it starts
    };

    std::size_t i = 0;
    while (i < text.size()) {
        const char c = text[i];
        if (c == '"' && field.empty() && !field_was_quoted) {
            // A quoted field: runs to the next lone quote, across separators and line breaks.
            const int start_line = line;
            ++i;
            for (;;) {
                if (i >= text.size())
                    return Error{file_name + ":" + std::to_string(start_line) +
                                 ": a quoted field is never closed (a missing '\"')"};
                if (text[i] == '"') {
                    if (i + 1 < text.size() && text[i + 1] == '"') {
                        field += '"';
                        i += 2;
                        continue;
                    }
                    ++i;
                    break;
                }
                if (text[i] == '\n') ++line;
                field += text[i++];
            }
            field_was_quoted = true;
            if (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r')
                return Error{file_name + ":" + std::to_string(line) +
                             ": text after the closing quote of a quoted field"};
            continue;
        }
        if (c == ',') {
            record.fields.push_back(std::move(field));
            field.clear();
            field_was_quoted = false;
            ++i;
        } else if (c == '\n' || c == '\r') {
            i += (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ? 2 : 1;
            end_record();
            ++line;
            record.line = line;
        } else {
            field += c;
            ++i;
        }
    }
    if (!field.empty() || field_was_quoted || !record.fields.empty()) end_record();
    return records;
}

}  // namespace monoplane::analysis
