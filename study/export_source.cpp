#include "study/export_source.h"

#include <charconv>
#include <fstream>
#include <optional>
#include <string_view>
#include <system_error>
#include <vector>

#include "common/quoted.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

// The record's first line: what tells it from any other file, and what it is to a person who
// opens it.
constexpr std::string_view kFirstLine =
    "# monoplane export source: the study sessions the export beside this file holds";
constexpr std::string_view kHelpLine =
    "# `monoplane study export` replaces that export only with one of a database that holds "
    "every session named here, or when forced";
// Sessions a refusal names before it says how many more there are.
constexpr std::size_t kNamedSessions = 3;

// A path on one line of the record: control characters (a newline would end the line) as '?'.
std::string one_line(std::string text) {
    for (char& c : text)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    return text;
}

Error line_error(const fs::path& path, int line, const std::string& what) {
    return Error{in_quotes(path) + " line " + std::to_string(line) + ": " + what};
}

// "N STARTED_UTC CODE", the code last: it is the rest of the line.
std::optional<ExportedSession> parse_session(std::string_view text) {
    const std::size_t first_space = text.find(' ');
    if (first_space == std::string_view::npos) return std::nullopt;
    const std::size_t second_space = text.find(' ', first_space + 1);
    if (second_space == std::string_view::npos) return std::nullopt;
    ExportedSession s;
    const std::string_view number = text.substr(0, first_space);
    const auto [end, error] =
        std::from_chars(number.data(), number.data() + number.size(), s.session_number);
    if (error != std::errc() || end != number.data() + number.size()) return std::nullopt;
    s.started_utc = std::string(text.substr(first_space + 1, second_space - first_space - 1));
    s.participant = std::string(text.substr(second_space + 1));
    if (s.participant.empty()) return std::nullopt;
    return s;
}

// One line after the first into `source`; the error says what is wrong with it.
Result<void> parse_line(const std::string& line, ExportSource& source) {
    const std::string_view text(line);
    if (text.empty() || text.starts_with('#')) return Ok{};
    const std::size_t space = text.find(' ');
    const std::string_view key = text.substr(0, space);
    const std::string_view value =
        space == std::string_view::npos ? std::string_view() : text.substr(space + 1);
    if (key == "format") {
        source.format = std::string(value);
    } else if (key == "database") {
        source.database = std::string(value);
    } else if (key == "session") {
        const std::optional<ExportedSession> session = parse_session(value);
        if (!session) return Error{"expected 'session NUMBER STARTED_UTC CODE'"};
        source.sessions.insert(*session);
    } else {
        return Error{"unknown key '" + std::string(key) +
                     "' (written by a newer monoplane?); expected format, database or session"};
    }
    return Ok{};
}

std::string session_text(const ExportedSession& s) {
    return s.participant + " session " + std::to_string(s.session_number) + " (started " +
           s.started_utc + ")";
}

// The sessions of `earlier` that `now` lacks, the first few by name.
std::string missing_sessions(const ExportSource& earlier, const ExportSource& now) {
    std::vector<const ExportedSession*> missing;
    for (const ExportedSession& s : earlier.sessions)
        if (!now.sessions.contains(s)) missing.push_back(&s);
    if (missing.empty()) return "";
    std::string text = std::to_string(missing.size()) + " of its " +
                       std::to_string(earlier.sessions.size()) +
                       (earlier.sessions.size() == 1 ? " session is" : " sessions are") +
                       " not in this database: ";
    for (std::size_t i = 0; i < missing.size() && i < kNamedSessions; ++i)
        text += (i == 0 ? "" : ", ") + session_text(*missing[i]);
    if (missing.size() > kNamedSessions)
        text += " and " + std::to_string(missing.size() - kNamedSessions) + " more";
    return text;
}

}  // namespace

fs::path export_source_path(const fs::path& out) {
    return fs::path(out.string() + ".source");
}

ExportSource export_source(const ExportData& data, ExportFormat format, const fs::path& database) {
    ExportSource source;
    source.format = std::string(export_format_name(format));
    std::error_code ec;
    const fs::path absolute = fs::absolute(database, ec);
    source.database = (ec ? database : absolute.lexically_normal()).string();
    for (const auto& [id, info] : data.sessions)
        source.sessions.insert({info.participant_code, info.session_number, info.started_utc});
    return source;
}

void write_export_source(const ExportSource& source, std::ostream& out) {
    out << kFirstLine << "\n" << kHelpLine << "\n";
    out << "format " << one_line(source.format) << "\n";
    out << "database " << one_line(source.database) << "\n";
    for (const ExportedSession& s : source.sessions) {
        out << "session " << s.session_number << " " << one_line(s.started_utc) << " "
            << one_line(s.participant) << "\n";
    }
}

Result<ExportSource> read_export_source(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return Error{"cannot read " + in_quotes(path)};
    std::string line;
    if (!std::getline(in, line) || !std::string_view(line).starts_with(kFirstLine))
        return line_error(path, 1, "not a record of an export's source");
    ExportSource source;
    for (int number = 2; std::getline(in, line); ++number) {
        Result<void> parsed = parse_line(line, source);
        if (!parsed) return line_error(path, number, parsed.error().message);
    }
    if (in.bad()) return Error{"cannot read " + in_quotes(path)};
    return source;
}

OutputKind export_source_kind() {
    return {"export source record",
            [](std::string_view head) { return head.starts_with(kFirstLine); }};
}

std::optional<OutputProblem> export_output_problem(const fs::path& out, ExportFormat format,
                                                   const fs::path& database, bool force) {
    if (std::optional<OutputProblem> problem =
            output_problem(out, export_output_kind(format), {database}, force))
        return problem;
    if (out.empty()) return std::nullopt;
    return output_problem(export_source_path(out), export_source_kind(), {database}, force);
}

std::optional<OutputProblem> export_source_problem(const fs::path& out, const ExportSource& now,
                                                   bool force) {
    std::error_code ec;
    if (force || !fs::exists(out, ec)) return std::nullopt;
    const std::string kind = now.format + " export";
    const fs::path record = export_source_path(out);
    if (!fs::exists(record, ec)) {
        return OutputProblem{
            OutputRefusal::OtherSource,
            in_quotes(out) + " is a " + kind + " that does not record which study it came from (" +
                in_quotes(record) +
                " is missing: it was written by an older monoplane, or copied without it)"};
    }
    Result<ExportSource> earlier = read_export_source(record);
    if (!earlier) {
        return OutputProblem{OutputRefusal::OtherSource,
                             in_quotes(out) + " is a " + kind +
                                 " whose record of its study cannot be read (" +
                                 earlier.error().message + ")"};
    }
    const std::string missing = missing_sessions(*earlier, now);
    if (missing.empty()) return std::nullopt;
    return OutputProblem{OutputRefusal::OtherSource,
                         in_quotes(out) + " is a " + kind + " of another study: " + missing};
}

}  // namespace monoplane::study
