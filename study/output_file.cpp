#include "study/output_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <optional>
#include <streambuf>
#include <system_error>

#include "common/quoted.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

// What SQLite writes first: a database file's header, and a write-ahead log's magic numbers
// (big-endian 0x377f0682 or 0x377f0683). Either is a file a study cannot do without.
constexpr std::string_view kSqliteHeader{"SQLite format 3\0", 16};

bool is_sqlite_head(std::string_view head) {
    if (head.starts_with(kSqliteHeader)) return true;
    return head.size() >= 4 && head.substr(0, 3) == std::string_view("\x37\x7f\x06", 3) &&
           (head[3] == '\x82' || head[3] == '\x83');
}

// Files SQLite and the session holds keep beside a database: replacing one damages the study.
constexpr std::array<std::string_view, 4> kDatabaseCompanions = {"-wal", "-shm", "-journal",
                                                                 "-holds"};

// The same file, by any spelling: existing files by device and inode (hard and symbolic links,
// relative paths), a file not there yet by its absolute path with links resolved.
bool same_file(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    if (fs::exists(a, ec) && fs::exists(b, ec)) return fs::equivalent(a, b, ec) && !ec;
    const fs::path ca = fs::weakly_canonical(fs::absolute(a, ec), ec);
    if (ec) return false;
    const fs::path cb = fs::weakly_canonical(fs::absolute(b, ec), ec);
    return !ec && ca == cb;
}

// The reason `out` may never be written, forced or not, when it is one of the inputs or one of
// an input database's companion files.
std::optional<std::string> input_conflict(const fs::path& out,
                                          const std::vector<fs::path>& inputs) {
    for (const fs::path& input : inputs) {
        if (same_file(out, input)) {
            const std::string what =
                std::string(is_sqlite_file(input) ? "the database" : "a file") +
                " this command reads: writing there would destroy it";
            if (out.lexically_normal() == input.lexically_normal())
                return in_quotes(out) + " is " + what;
            return in_quotes(out) + " is the same file as " + in_quotes(input) + ", " + what;
        }
        for (std::string_view suffix : kDatabaseCompanions) {
            // Beside the path as given and beside the link's target: SQLite and the session
            // holds use the real file. Compared by path too, for a companion not there yet.
            std::error_code error;
            const fs::path companion = input.string() + std::string(suffix);
            const fs::path real_companion =
                fs::weakly_canonical(input, error).string() + std::string(suffix);
            const fs::path real_out = fs::weakly_canonical(out, error);
            if (same_file(out, companion) || same_file(out, real_companion) ||
                real_out == fs::weakly_canonical(companion, error) || real_out == real_companion) {
                return in_quotes(out) + " belongs to the database " + in_quotes(input) +
                       " (SQLite or a running session keeps it beside the database): writing "
                       "there would damage the study";
            }
        }
    }
    return std::nullopt;
}

// Up to kOutputHeadBytes from the start of a file; the error says why it cannot be read.
Result<std::string> read_head(const fs::path& path) {
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    std::string head(kOutputHeadBytes, '\0');
    if (in) in.read(head.data(), static_cast<std::streamsize>(head.size()));
    if (!in && !in.eof()) {
        const int err = errno;
        return Error{"cannot read " + in_quotes(path) + " to tell whether it may be replaced" +
                     (err != 0 ? std::string(": ") + std::strerror(err) : std::string())};
    }
    head.resize(static_cast<std::size_t>(in.gcount()));
    return head;
}

// The start of a file's first line, printable, for a message that shows what the file is.
std::string first_line(std::string_view head) {
    std::string line(head.substr(0, head.find_first_of("\r\n")));
    for (char& c : line)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
    if (line.size() > 60) line = line.substr(0, 57) + "...";
    return line.empty() ? "an empty first line" : "'" + line + "'";
}

// The folder `out` goes into must exist: the output is written there and renamed.
std::optional<OutputProblem> folder_problem(const fs::path& out) {
    const fs::path folder = out.parent_path().empty() ? fs::path(".") : out.parent_path();
    std::error_code ec;
    const fs::file_status status = fs::status(folder, ec);
    if (!fs::exists(status)) {
        return OutputProblem{OutputRefusal::NoFolder, "the folder " + in_quotes(folder) +
                                                          " for the output " + in_quotes(out) +
                                                          " does not exist"};
    }
    if (!fs::is_directory(status)) {
        return OutputProblem{
            OutputRefusal::FolderIsNoFolder,
            in_quotes(folder) + " in the output path " + in_quotes(out) + " is not a folder"};
    }
    return std::nullopt;
}

// `out` exists: what it is decides whether it may be replaced.
std::optional<OutputProblem> existing_problem(const fs::path& out, const OutputKind& kind,
                                              bool force) {
    std::error_code ec;
    if (!fs::is_regular_file(out, ec)) {
        return OutputProblem{OutputRefusal::NotAFile,
                             in_quotes(out) + " exists and is " +
                                 (fs::is_directory(out, ec) ? "a folder" : "not a regular file")};
    }
    Result<std::string> head = read_head(out);
    if (!head) return OutputProblem{OutputRefusal::Unreadable, head.error().message};
    if (is_sqlite_head(*head)) {
        return OutputProblem{OutputRefusal::IsADatabase,
                             in_quotes(out) +
                                 " is an SQLite database (perhaps a study's): refusing to "
                                 "replace it"};
    }
    if (kind.is_earlier_output && kind.is_earlier_output(*head)) return std::nullopt;
    if (force) return std::nullopt;
    return OutputProblem{OutputRefusal::NotAnEarlierOutput,
                         in_quotes(out) + " exists and is not an earlier " + kind.name +
                             ": it begins with " + first_line(*head)};
}

}  // namespace

bool is_sqlite_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(kSqliteHeader.size(), '\0');
    if (!in.read(head.data(), static_cast<std::streamsize>(head.size()))) return false;
    return is_sqlite_head(head);
}

std::optional<OutputProblem> output_problem(const fs::path& out, const OutputKind& kind,
                                            const std::vector<fs::path>& inputs, bool force) {
    if (out.empty()) return OutputProblem{OutputRefusal::NoName, "the output file name is empty"};
    if (std::optional<std::string> conflict = input_conflict(out, inputs))
        return OutputProblem{OutputRefusal::IsAnInput, *conflict};
    std::error_code ec;
    const fs::file_status status = fs::status(out, ec);  // through a symbolic link
    if (fs::exists(status)) return existing_problem(out, kind, force);
    // A new file (or a symbolic link to nothing, which the output replaces).
    return folder_problem(out);
}

Error output_error(const OutputProblem& problem) {
    switch (problem.refusal) {
        case OutputRefusal::NoName:
            return Error{problem.what};
        case OutputRefusal::IsAnInput:
        case OutputRefusal::IsADatabase:
            return Error{problem.what + ", even when forced. Nothing was written."};
        case OutputRefusal::NotAnEarlierOutput:
        case OutputRefusal::OtherSource:
            return Error{problem.what + "; it is replaced only when forced. Nothing was written."};
        default:
            return Error{problem.what + ". Nothing was written."};
    }
}

Result<void> check_output(const fs::path& out, const OutputKind& kind,
                          const std::vector<fs::path>& inputs, bool force) {
    const std::optional<OutputProblem> problem = output_problem(out, kind, inputs, force);
    if (!problem) return Ok{};
    return output_error(*problem);
}

namespace {

// An output stream's buffer over a file descriptor, so the file can be flushed to disk (fsync)
// before it is renamed into place. Remembers the first write error for the message.
class DescriptorBuffer final : public std::streambuf {
  public:
    explicit DescriptorBuffer(int fd) : fd_(fd) { setp(buffer_.data(), buffer_.data() + size()); }
    int error() const { return error_; }

  protected:
    int_type overflow(int_type ch) override {
        if (!drain()) return traits_type::eof();
        if (!traits_type::eq_int_type(ch, traits_type::eof())) {
            *pptr() = traits_type::to_char_type(ch);
            pbump(1);
        }
        return traits_type::not_eof(ch);
    }
    int sync() override { return drain() ? 0 : -1; }

  private:
    static constexpr std::ptrdiff_t size() { return 1 << 16; }
    bool drain() {
        for (const char* p = pbase(); p < pptr();) {
            const ssize_t n = ::write(fd_, p, static_cast<std::size_t>(pptr() - p));
            if (n < 0 && errno == EINTR) continue;
            if (n < 0) {
                error_ = errno;
                return false;
            }
            p += n;
        }
        setp(buffer_.data(), buffer_.data() + size());
        return true;
    }
    std::array<char, 1 << 16> buffer_{};
    int fd_;
    int error_ = 0;
};

// A new, empty file beside `target` that no other writer uses: its name starts with '.' and
// carries the process id and a counter, and O_EXCL refuses one that exists.
Result<std::pair<int, fs::path>> create_temporary(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    const fs::path folder = target.parent_path();
    for (int attempt = 0; attempt < 100; ++attempt) {
        const fs::path name =
            folder / ("." + target.filename().string() + ".tmp-" + std::to_string(::getpid()) +
                      "-" + std::to_string(counter.fetch_add(1)));
        const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) return std::pair{fd, name};
        if (errno != EEXIST) {
            return Error{"cannot create a file in " +
                         in_quotes(folder.empty() ? fs::path(".") : folder) + " to write " +
                         in_quotes(target) + ": " + std::strerror(errno) +
                         "; check that the folder exists and is writable."};
        }
    }
    return Error{"cannot find a free temporary file name beside " + in_quotes(target)};
}

// Writes through `write`, then flushes to disk; the error says what failed.
Result<void> fill(int fd, const fs::path& target,
                  const std::function<Result<void>(std::ostream&)>& write) {
    DescriptorBuffer buffer(fd);
    std::ostream stream(&buffer);
    MONOPLANE_TRY(write(stream));
    stream.flush();
    if (!stream.good() || buffer.error() != 0) {
        const int err = buffer.error();
        return Error{"writing " + in_quotes(target) + " failed" +
                     (err != 0 ? std::string(": ") + std::strerror(err) : std::string()) +
                     "; it was left as it was."};
    }
    if (::fsync(fd) != 0) {
        return Error{"writing " + in_quotes(target) + " to disk failed: " + std::strerror(errno) +
                     "; it was left as it was."};
    }
    return Ok{};
}

// After the rename, the folder's entry is made durable too; a failure there loses nothing that
// was on disk before, so it is not an error.
void sync_folder(const fs::path& folder) {
    const int fd =
        ::open(folder.empty() ? "." : folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) return;
    ::fsync(fd);
    ::close(fd);
}

// A file written beside its place, complete and on disk, waiting to be renamed there.
struct Staged {
    fs::path target;     // where it goes (a symbolic link's file, not the link)
    fs::path temporary;  // where it is now
};

// Through a symbolic link to an existing file: that file is replaced, the link kept.
fs::path replaced_target(const fs::path& out) {
    std::error_code ec;
    if (fs::is_symlink(fs::symlink_status(out, ec)) && fs::exists(out, ec))
        return fs::canonical(out, ec);
    return out;
}

// Writes one file beside its place; on failure nothing of it is left.
Result<Staged> stage(const FileWrite& file) {
    const fs::path target = replaced_target(file.out);
    Result<std::pair<int, fs::path>> temporary = create_temporary(target);
    MONOPLANE_TRY(temporary);
    const auto [fd, temporary_path] = *temporary;
    struct stat existing {};
    if (::stat(target.c_str(), &existing) == 0) ::fchmod(fd, existing.st_mode & 07777);
    Result<void> filled = fill(fd, target, file.write);
    if (::close(fd) != 0 && filled) {
        filled = Error{"writing " + in_quotes(target) + " failed: " + std::strerror(errno)};
    }
    if (!filled) {
        ::unlink(temporary_path.c_str());
        return filled.error();
    }
    return Staged{target, temporary_path};
}

}  // namespace

Result<void> write_file_atomically(const fs::path& out,
                                   const std::function<Result<void>(std::ostream&)>& write) {
    return write_files_atomically({FileWrite{out, write}});
}

Result<void> write_files_atomically(const std::vector<FileWrite>& files) {
    std::vector<Staged> staged;
    Result<void> done = Ok{};
    for (const FileWrite& file : files) {
        Result<Staged> one = stage(file);
        if (!one) {
            done = one.error();
            break;
        }
        staged.push_back(*one);
    }
    for (std::size_t i = 0; done && i < staged.size(); ++i) {
        if (std::rename(staged[i].temporary.c_str(), staged[i].target.c_str()) != 0) {
            done = Error{"cannot move the new file into place at " + in_quotes(staged[i].target) +
                         ": " + std::strerror(errno) + "; it was left as it was."};
        } else {
            sync_folder(staged[i].target.parent_path());
            staged[i].temporary.clear();
        }
    }
    // Whatever was not renamed is not wanted: no temporary file stays behind.
    for (const Staged& s : staged)
        if (!s.temporary.empty()) ::unlink(s.temporary.c_str());
    return done;
}

}  // namespace monoplane::study
