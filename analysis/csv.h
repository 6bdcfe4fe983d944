// RFC 4180 records, as `monoplane study export` writes them and as pandas, R and spreadsheets
// write them back: `,` separators, fields with commas, quotes or line breaks in double quotes
// with inner quotes doubled, `\n` or `\r\n` line ends.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"

namespace monoplane::analysis {

struct CsvRecord {
    int line = 0;  // 1-based line on which the record starts (a quoted line break spans lines)
    std::vector<std::string> fields;
};

// Splits `text` into records. Blank lines are skipped (as pandas and R do), and so is a leading
// UTF-8 byte order mark (spreadsheets add one). Errors, which name `file_name` and the line: a
// quote that is never closed, text after a closing quote.
Result<std::vector<CsvRecord>> parse_csv(std::string_view text, const std::string& file_name);

}  // namespace monoplane::analysis
