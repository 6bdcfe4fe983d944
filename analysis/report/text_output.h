// Text formats the report writes: RFC 4180 CSV fields and the JSON layout of its files (the writer
// is common/json_writer.h; HTML text is escaped with charts::xml_escaped). Numbers are formatted
// the same on every platform and locale, so two runs over the same data give the same files.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "common/json_writer.h"

namespace monoplane::analysis::report {

// The shortest text that reads back as the same double ("0.5", "39.5", "1e-12"); "" for NaN or
// infinity (an empty CSV field reads as NA in R and pandas).
std::string number_text(double value);

// A CSV field: quoted when it holds a comma, quote, CR or LF, with inner quotes doubled.
std::string csv_field(std::string_view text);
// One CSV line (with "\n") from already formatted fields.
std::string csv_line(const std::vector<std::string>& fields);

// summary.json and power.json: one key per line, numbers with every digit (as number_text).
inline constexpr JsonFormat kReportJson{.indented = true, .significant_digits = 0};

}  // namespace monoplane::analysis::report
