// Writing a command's output file without destroying what a lab already has (docs/data.md,
// "Where an export may go"). A command checks its output before it opens anything, then writes
// the file beside its final place and renames it there when complete:
//
//   check_output(out, export_output_kind(format), {database}, force).value_or_throw();
//   ... open the database, collect ...
//   write_file_atomically(out, [&](std::ostream& s) -> Result<void> { ...; return Ok{}; });
//
// check_output refuses, with nothing changed:
// - always (`force` does not help): an output that is one of the command's inputs (the same
//   file by any path: relative, through a symbolic link, a hard link) or an input database's
//   -wal, -shm, -journal or -holds file; any SQLite database or write-ahead log (told by its
//   header bytes, whatever its name); a folder or anything that is not a regular file;
// - unless `force`: any other existing file that is not an earlier output of the same kind (a
//   protocol, notes, another format's export), told by its first bytes;
// and says so when the folder the output goes into does not exist. Whether an earlier output
// came from the same inputs is the command's to tell (an export's is study/export_source.h),
// after it has read them; it refuses with OutputRefusal::OtherSource. Its messages speak of the
// output and of forcing; a command that names them otherwise (the CLI's --out and --force) asks
// output_problem() and words the refusal itself.
#pragma once

#include <filesystem>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"

namespace monoplane::study {

// What a command writes, and how an earlier file of its own is told from anything else.
struct OutputKind {
    std::string name;  // for messages: "csv export"
    // True when `head`, the first bytes of an existing file (up to kOutputHeadBytes), is what an
    // earlier run of this kind of output wrote: only such a file is replaced without `force`.
    std::function<bool(std::string_view head)> is_earlier_output;
};

inline constexpr std::size_t kOutputHeadBytes = 4096;

// Why an output may not be written, so that a caller can say what to change in its own words.
enum class OutputRefusal {
    NoName,              // the output's name is empty
    IsAnInput,           // one of the inputs, or a file beside an input database: never replaced
    IsADatabase,         // an SQLite database or write-ahead log: never replaced
    NotAFile,            // a folder, or something else that is not a regular file
    Unreadable,          // it exists and cannot be read to tell what it is
    NotAnEarlierOutput,  // another file: replaced only when forced
    OtherSource,         // an earlier output of other inputs (another study's): only when forced
    NoFolder,            // the folder it goes into does not exist
    FolderIsNoFolder,    // what should be its folder is something else
};

struct OutputProblem {
    OutputRefusal refusal;
    // What is wrong, naming the file(s), without what to do about it: "'a.csv' exists and is a
    // folder", "'a.csv' exists and is not an earlier csv export: it begins with 'x'".
    std::string what;
};

// May `out` be written? `inputs`: the files the command reads (its databases), each compared
// with `out` as the same file. None when writing may go ahead. Reads only: never creates,
// truncates or touches a file.
std::optional<OutputProblem> output_problem(const std::filesystem::path& out,
                                            const OutputKind& kind,
                                            const std::vector<std::filesystem::path>& inputs,
                                            bool force);

// A refusal in the library's own words: its `what`, whether forcing would help, and that
// nothing was written. Pure; any time.
Error output_error(const OutputProblem& problem);

// How a caller words a refusal for its users (the CLI's names --out and --force).
using OutputWording = std::function<Error(const OutputProblem&)>;

// output_problem() as an Error, worded by output_error().
Result<void> check_output(const std::filesystem::path& out, const OutputKind& kind,
                          const std::vector<std::filesystem::path>& inputs, bool force);

// True when the file begins as an SQLite database or its write-ahead log does; false for
// anything else, a missing file included.
bool is_sqlite_file(const std::filesystem::path& path);

// Writes `out` by calling `write` on a new file beside it (same folder, so the rename cannot
// cross file systems), flushes it to disk, and renames it over `out`: a reader sees the old
// file or the whole new one, never a part, and a failure (a full disk, `write`'s own error)
// leaves `out` as it was and no temporary file behind. A new file gets the usual permissions
// (0666 less the umask); a replaced one keeps its mode. When `out` is a symbolic link, the file
// it points to is replaced and the link stays.
Result<void> write_file_atomically(const std::filesystem::path& out,
                                   const std::function<Result<void>(std::ostream&)>& write);

// One file of write_files_atomically: where, and what goes in it.
struct FileWrite {
    std::filesystem::path out;
    std::function<Result<void>(std::ostream&)> write;
};

// Several files that belong together (an export and the record of its source): each is written
// whole beside its place and flushed as write_file_atomically does, and only when all of them
// are complete are they renamed into place, in the order given. A failure before the renames
// leaves every file as it was and no temporary file behind.
Result<void> write_files_atomically(const std::vector<FileWrite>& files);

}  // namespace monoplane::study
