#include "app/commands/output_folder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <set>
#include <system_error>
#include <utility>

namespace monoplane::app {
namespace {

namespace fs = std::filesystem;

// Foreign entries a refusal names before it says how many more there are.
constexpr std::size_t kNamedEntries = 5;

std::string in_quotes(const fs::path& path) {
    return "'" + path.string() + "'";
}

// The marker's first line: what tells it from a file of the same name written by anyone else.
std::string marker_first_line(const FolderWriter& writer) {
    return "# monoplane " + writer.command + " output: the files it wrote in this folder";
}

// `out` as an absolute path without a trailing separator, through a symbolic link to a folder
// (the link stays, the folder it points to is the output).
Result<fs::path> output_path(const fs::path& out) {
    if (out.empty()) return Error{"the output folder (--out) is empty"};
    std::error_code ec;
    fs::path folder = fs::absolute(out, ec).lexically_normal();
    if (ec) return Error{"--out " + in_quotes(out) + ": " + ec.message()};
    if (folder.filename().empty()) folder = folder.parent_path();
    const fs::file_status link = fs::symlink_status(folder, ec);
    if (fs::is_symlink(link)) {
        if (!fs::exists(folder, ec))
            return Error{"--out " + in_quotes(out) +
                         " is a symbolic link to nothing; choose another --out. Nothing was "
                         "written."};
        folder = fs::canonical(folder, ec);
        if (ec) return Error{"--out " + in_quotes(out) + ": " + ec.message()};
    }
    return folder;
}

// A path from a marker line, when it is one the command could have written: relative, inside
// the folder, no "." or ".." parts.
bool is_inside(const std::string& line) {
    if (line.empty()) return false;
    const fs::path path(line);
    if (path.is_absolute()) return false;
    for (const fs::path& part : path)
        if (part.empty() || part == "." || part == "..") return false;
    return true;
}

// The files an earlier run's marker lists; none when there is no marker or it is not one.
std::optional<std::set<std::string>> read_marker(const fs::path& marker,
                                                 const FolderWriter& writer) {
    std::ifstream in(marker, std::ios::binary);
    std::string line;
    if (!in || !std::getline(in, line) || line != marker_first_line(writer)) return std::nullopt;
    std::set<std::string> listed;
    while (std::getline(in, line)) {
        if (line.starts_with('#')) continue;
        if (!is_inside(line)) return std::nullopt;
        listed.insert(line);
    }
    return listed;
}

// The folders that hold the listed files ("figures" for "figures/choices.svg").
std::set<std::string> listed_folders(const std::set<std::string>& listed) {
    std::set<std::string> folders;
    for (const std::string& file : listed)
        for (fs::path parent = fs::path(file).parent_path(); !parent.empty();
             parent = parent.parent_path())
            folders.insert(parent.generic_string());
    return folders;
}

struct Listing {
    std::set<std::string> files;
    std::set<std::string> folders;
    std::string marker;  // skipped at the top: it is the writer's own
};

// Sorts the entries of `root`/`relative` into earlier and foreign, descending only into folders
// that hold listed files.
Result<void> classify(const fs::path& root, const fs::path& relative, const Listing& listing,
                      FolderContents& contents) {
    std::error_code ec;
    fs::directory_iterator entries(root / relative, ec);
    for (; !ec && entries != fs::directory_iterator(); entries.increment(ec)) {
        const std::string name = (relative / entries->path().filename()).generic_string();
        if (relative.empty() && name == listing.marker) continue;
        const bool folder = fs::is_directory(entries->symlink_status(ec));
        if (folder && listing.folders.contains(name)) {
            MONOPLANE_TRY(classify(root, relative / entries->path().filename(), listing, contents));
        } else if (!folder && listing.files.contains(name)) {
            contents.earlier.push_back(name);
        } else {
            contents.foreign.push_back(folder ? name + "/" : name);
        }
    }
    if (ec)
        return Error{"cannot read the folder " + in_quotes(root / relative) + ": " + ec.message()};
    return Ok{};
}

// "a, b, c and 4 more".
std::string named_entries(const std::vector<std::string>& entries) {
    std::string text;
    for (std::size_t i = 0; i < entries.size() && i < kNamedEntries; ++i)
        text += (i == 0 ? "" : ", ") + entries[i];
    if (entries.size() > kNamedEntries)
        text += " and " + std::to_string(entries.size() - kNamedEntries) + " more";
    return text;
}

Error foreign_refusal(const fs::path& out, const FolderContents& contents,
                      const FolderWriter& writer) {
    return Error{"--out " + in_quotes(out) + " holds files " + writer.command +
                 " did not write: " + named_entries(contents.foreign) +
                 ". Nothing was written. Choose a new or empty folder for --out, or give --force "
                 "to write among them (files of the same names are replaced, the others kept)."};
}

// Every file under `root`, relative, sorted.
Result<std::vector<std::string>> files_under(const fs::path& root) {
    std::vector<std::string> files;
    std::error_code ec;
    fs::recursive_directory_iterator entries(root, ec);
    for (; !ec && entries != fs::recursive_directory_iterator(); entries.increment(ec))
        if (!fs::is_directory(entries->symlink_status(ec)))
            files.push_back(entries->path().lexically_relative(root).generic_string());
    if (ec) return Error{"cannot list " + in_quotes(root) + ": " + ec.message()};
    std::sort(files.begin(), files.end());
    return files;
}

Result<void> write_marker(const fs::path& staged, const FolderWriter& writer,
                          const std::vector<std::string>& files) {
    const fs::path marker = staged / writer.marker;
    std::ofstream out(marker, std::ios::binary);
    out << marker_first_line(writer) << "\n"
        << "# A later `monoplane " << writer.command
        << " --out` replaces this folder only while it holds nothing but these files.\n";
    for (const std::string& file : files)
        if (file != writer.marker) out << file << "\n";
    out.close();
    if (!out) return Error{"cannot write " + in_quotes(marker) + ": " + std::strerror(errno)};
    return Ok{};
}

// A new folder beside `folder`, named after it and hidden, that no other writer uses.
Result<fs::path> make_staged(const fs::path& folder) {
    static std::atomic<unsigned> counter{0};
    const fs::path parent = folder.parent_path();
    std::error_code ec;
    fs::create_directories(parent, ec);
    for (int attempt = 0; attempt < 100; ++attempt) {
        const fs::path staged =
            parent / ("." + folder.filename().string() + ".tmp-" + std::to_string(::getpid()) +
                      "-" + std::to_string(counter.fetch_add(1)));
        if (::mkdir(staged.c_str(), 0777) == 0) return staged;
        if (errno != EEXIST) {
            return Error{"cannot create a folder in " + in_quotes(parent) + " to write " +
                         in_quotes(folder) + ": " + std::strerror(errno) +
                         "; check that the folder exists and is writable, or choose another "
                         "--out. Nothing was written."};
        }
    }
    return Error{"cannot find a free folder name beside " + in_quotes(folder)};
}

// The staged folder takes the place of `folder`, which holds only an earlier run's files (or
// nothing); the earlier folder is removed after. One atomic exchange where the file system has
// it, else two renames.
Result<void> exchange(const fs::path& staged, const fs::path& folder) {
    struct stat old_mode {};
    if (::stat(folder.c_str(), &old_mode) == 0) ::chmod(staged.c_str(), old_mode.st_mode & 07777);
    const fs::path old = staged.string() + "-old";
    std::error_code ec;
#ifdef RENAME_EXCHANGE
    if (::renameat2(AT_FDCWD, staged.c_str(), AT_FDCWD, folder.c_str(), RENAME_EXCHANGE) == 0) {
        fs::remove_all(staged, ec);  // the earlier run's folder, now under the staged name
        return Ok{};
    }
#endif
    if (std::rename(folder.c_str(), old.c_str()) != 0) {
        return Error{"cannot move the earlier output " + in_quotes(folder) +
                     " aside: " + std::strerror(errno) + ". Nothing was changed."};
    }
    if (std::rename(staged.c_str(), folder.c_str()) != 0) {
        const int err = errno;
        std::rename(old.c_str(), folder.c_str());
        return Error{"cannot move the new output into place at " + in_quotes(folder) + ": " +
                     std::strerror(err) + ". Nothing was changed."};
    }
    fs::remove_all(old, ec);
    return Ok{};
}

// Forced onto a folder with foreign entries: each new file moved in (the marker last), then the
// earlier run's files that were not written again removed, with folders they leave empty.
Result<void> move_in(const fs::path& staged, const fs::path& folder,
                     const std::vector<std::string>& files, const FolderContents& before) {
    std::error_code ec;
    for (const std::string& file : files) {
        const fs::path target = folder / file;
        fs::create_directories(target.parent_path(), ec);
        if (std::rename((staged / file).c_str(), target.c_str()) != 0) {
            return Error{"cannot move " + in_quotes(fs::path(file)) + " into " + in_quotes(folder) +
                         ": " + std::strerror(errno)};
        }
    }
    const std::set<std::string> written(files.begin(), files.end());
    for (const std::string& file : before.earlier) {
        if (written.contains(file)) continue;
        fs::remove(folder / file, ec);
        for (fs::path parent = fs::path(file).parent_path(); !parent.empty();
             parent = parent.parent_path())
            if (!fs::remove(folder / parent, ec)) break;  // only an empty folder goes
    }
    fs::remove_all(staged, ec);
    return Ok{};
}

}  // namespace

Result<FolderContents> inspect_output_folder(const fs::path& out, const FolderWriter& writer) {
    Result<fs::path> folder = output_path(out);
    MONOPLANE_TRY(folder);
    FolderContents contents;
    contents.folder = *folder;
    std::error_code ec;
    const fs::file_status status = fs::status(contents.folder, ec);
    if (!fs::exists(status)) return contents;
    if (!fs::is_directory(status)) {
        return Error{"--out " + in_quotes(out) +
                     " exists and is not a folder; choose another --out (--force does not "
                     "replace a file with a folder). Nothing was written."};
    }
    contents.exists = true;
    const std::optional<std::set<std::string>> listed =
        read_marker(contents.folder / writer.marker, writer);
    Listing listing;
    if (listed) {
        listing.files = *listed;
        listing.folders = listed_folders(*listed);
        listing.marker = writer.marker;
    }
    MONOPLANE_TRY(classify(contents.folder, {}, listing, contents));
    std::sort(contents.earlier.begin(), contents.earlier.end());
    std::sort(contents.foreign.begin(), contents.foreign.end());
    return contents;
}

Result<FolderContents> check_output_folder(const fs::path& out, const FolderWriter& writer,
                                           bool force) {
    Result<FolderContents> contents = inspect_output_folder(out, writer);
    MONOPLANE_TRY(contents);
    if (!contents->foreign.empty() && !force) return foreign_refusal(out, *contents, writer);
    return contents;
}

Result<StagedFolder> StagedFolder::create(const fs::path& out, const FolderWriter& writer,
                                          bool force) {
    Result<FolderContents> contents = check_output_folder(out, writer, force);
    MONOPLANE_TRY(contents);
    Result<fs::path> staged = make_staged(contents->folder);
    MONOPLANE_TRY(staged);
    return StagedFolder(out, *staged, writer, force);
}

StagedFolder::StagedFolder(StagedFolder&& other) noexcept
    : out_(std::move(other.out_)),
      staged_(std::exchange(other.staged_, {})),
      writer_(std::move(other.writer_)),
      force_(other.force_),
      committed_(other.committed_) {}

StagedFolder::~StagedFolder() {
    if (staged_.empty() || committed_) return;
    std::error_code ec;
    fs::remove_all(staged_, ec);
}

fs::path StagedFolder::final_path(const fs::path& staged_file) const {
    return out_ / staged_file.lexically_relative(staged_);
}

Result<void> StagedFolder::commit() {
    if (committed_) return Error{"the output " + in_quotes(out_) + " is in place already"};
    // What appeared in `out` since create() counts as it would have then.
    Result<FolderContents> contents = check_output_folder(out_, writer_, force_);
    MONOPLANE_TRY(contents);
    Result<std::vector<std::string>> files = files_under(staged_);
    MONOPLANE_TRY(files);
    MONOPLANE_TRY(write_marker(staged_, writer_, *files));
    files.value().push_back(writer_.marker);  // moved last: a marker means its files are there
    const fs::path& folder = contents->folder;
    Result<void> placed = Ok{};
    if (!contents->exists) {
        if (std::rename(staged_.c_str(), folder.c_str()) != 0)
            placed = Error{"cannot move the new output into place at " + in_quotes(folder) + ": " +
                           std::strerror(errno) + ". Nothing was changed."};
    } else if (contents->foreign.empty()) {
        placed = exchange(staged_, folder);
    } else {
        placed = move_in(staged_, folder, *files, *contents);
    }
    committed_ = placed.ok();
    return placed;
}

}  // namespace monoplane::app
