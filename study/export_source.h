// Where an export came from, recorded beside it (FILE.source), so that an export of one study
// never silently replaces another study's export of the same format (docs/data.md, "Where an
// export may go"). A database's path says nothing (copies move, two sites both have study.sqlite),
// so a study is known by its sessions: each by participant code, session number and start time,
// which a copy, a move or a schema migration keeps. An export is of the same study when every
// session its record names is in the database exported now: a study only gains sessions, so a
// later export of the same study always is, and another site's or lab PC's never is (unless the
// earlier export holds no session at all, when nothing can be lost).
#pragma once

#include <filesystem>
#include <optional>
#include <ostream>
#include <set>
#include <string>

#include "common/result.h"
#include "study/export.h"
#include "study/output_file.h"

namespace monoplane::study {

// A session as the record names it.
struct ExportedSession {
    std::string participant;
    int session_number = 1;
    std::string started_utc;  // ISO 8601 UTC, as the database has it

    auto operator<=>(const ExportedSession&) const = default;
};

struct ExportSource {
    std::string format;    // export_format_name(), for a reader
    std::string database;  // the database's path when exported, for a reader; never compared
    std::set<ExportedSession> sessions;
};

// The record's file beside an export: "trials.csv" -> "trials.csv.source". Pure.
std::filesystem::path export_source_path(const std::filesystem::path& out);

// The record of an export of `data` (every session it holds) from the database `database`.
// Pure; any time.
ExportSource export_source(const ExportData& data, ExportFormat format,
                           const std::filesystem::path& database);

// The record as a text a person can read: a first line that says what the file is, then
// "format F", "database PATH" and one "session N STARTED_UTC CODE" line per session.
void write_export_source(const ExportSource& source, std::ostream& out);

// Reads a record written by write_export_source. Errors name the file and the line: a file that
// cannot be read, is not such a record, or has a line this version does not know.
Result<ExportSource> read_export_source(const std::filesystem::path& path);

// How an existing record is told from any other file (by its first line), for check_output.
OutputKind export_source_kind();

// May an export of `format` from `database` be written to `out`, and its record beside it?
// check_output's rules (output_file.h) for both files; run before the database is read. Reads
// only.
std::optional<OutputProblem> export_output_problem(const std::filesystem::path& out,
                                                   ExportFormat format,
                                                   const std::filesystem::path& database,
                                                   bool force);

// May an export whose record is `now` replace `out`? None when `out` does not exist, when
// `force`, or when every session of out's record is among now's. Otherwise an OtherSource
// problem that names `out` and says why: its record is missing (an export of an older version,
// or copied without it) or cannot be read, or it names sessions `now` lacks (the first three, and
// how many). Call after output_problem allowed `out` (it is then an earlier export of the same
// format, or forced). Reads only.
std::optional<OutputProblem> export_source_problem(const std::filesystem::path& out,
                                                   const ExportSource& now, bool force);

}  // namespace monoplane::study
