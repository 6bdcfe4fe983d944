// An output folder that a command writes whole (`analyze --out DIR`, docs/analysis.md, "Where
// the analysis goes"), so that it never overwrites what it did not write and never leaves a file
// of an earlier run beside the new ones:
//
//   check_output_folder(out, writer, force)       before the inputs are read: refuse at once
//   StagedFolder::create(out, writer, force)      a new folder beside DIR to write into
//   ... write into staged.path() ...
//   staged.commit()                               the marker, then the folder renamed into place
//
// The command leaves a marker file in the folder (writer.marker) that lists every file it
// wrote. An existing DIR is replaced whole only when it holds nothing but what an earlier run
// listed there (or nothing at all); a folder with anything else in it (a thesis folder) is
// refused unless forced, and forced, the new files are moved in among the others: files of the
// same names are replaced, the earlier run's other files removed, everything else kept. DIR that
// is not a folder is refused, forced or not.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "common/result.h"

namespace monoplane::app {

// Who writes the folder: the marker it leaves there and the command's name for messages.
struct FolderWriter {
    std::string marker;   // e.g. ".monoplane-analysis"
    std::string command;  // e.g. "analyze"
};

// What an output folder holds, relative to it, with '/' between parts.
struct FolderContents {
    std::filesystem::path folder;      // absolute, through a symbolic link to a folder
    bool exists = false;               // false: a new folder
    std::vector<std::string> earlier;  // files an earlier run's marker lists, sorted
    // Everything else, sorted: files, and folders the marker has no file in ("chapters/"), whose
    // contents are not listed one by one. The marker itself is neither, unless it cannot be read.
    std::vector<std::string> foreign;
};

// What `out` holds. Errors, naming --out: `out` exists and is not a folder, or cannot be read.
// Reads only; any time.
Result<FolderContents> inspect_output_folder(const std::filesystem::path& out,
                                             const FolderWriter& writer);

// inspect_output_folder, and a refusal of a folder with foreign entries unless `force`: one line
// that names the folder and the first foreign entries and says what --force would do. Reads
// only; any time.
Result<FolderContents> check_output_folder(const std::filesystem::path& out,
                                           const FolderWriter& writer, bool force);

// A new, empty folder beside the output folder, in which a command writes its files; removed
// with everything in it when the object goes without commit() having succeeded.
class StagedFolder {
  public:
    // Checks `out` (check_output_folder) and creates the staged folder in out's parent folder
    // (itself created if needed, as --out always was) under a hidden name of its own
    // (".DIR.tmp-<pid>-<n>"). Errors name the folder and what to do.
    static Result<StagedFolder> create(const std::filesystem::path& out, const FolderWriter& writer,
                                       bool force);

    StagedFolder(StagedFolder&& other) noexcept;
    StagedFolder& operator=(StagedFolder&&) = delete;
    StagedFolder(const StagedFolder&) = delete;
    StagedFolder& operator=(const StagedFolder&) = delete;
    ~StagedFolder();

    // Where to write, until commit(). Any time.
    const std::filesystem::path& path() const { return staged_; }
    // Where a file written at `staged_file` (a path under path()) is once committed: the same
    // place under `out` as given to create(). Any time, also after commit().
    std::filesystem::path final_path(const std::filesystem::path& staged_file) const;

    // Writes the marker (every file under path(), sorted) and puts the folder in place: renamed
    // to `out`, or exchanged with an existing `out` that holds only an earlier run's files (which
    // is then removed), or, when forced onto a folder with foreign entries, its files moved in
    // one by one (the earlier run's files not written again removed). `out` is checked again
    // first: what appeared there since create() is refused as create() would. May be called
    // once; on failure `out` is as it was (forced: files not yet moved stay as they were).
    Result<void> commit();

  private:
    StagedFolder(std::filesystem::path out, std::filesystem::path staged, FolderWriter writer,
                 bool force)
        : out_(std::move(out)),
          staged_(std::move(staged)),
          writer_(std::move(writer)),
          force_(force) {}

    std::filesystem::path out_;     // as given to create()
    std::filesystem::path staged_;  // empty once moved from
    FolderWriter writer_;
    bool force_ = false;
    bool committed_ = false;
};

}  // namespace monoplane::app
