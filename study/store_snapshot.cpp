#include "study/store_snapshot.h"

#include <sys/stat.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <utility>

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

// What tells one committed state of the file from the next: the main file changes only at a
// checkpoint (size, modification time), and a log restarted after a checkpoint gets new salts
// (bytes 16-23 of its header, https://www.sqlite.org/fileformat2.html section 4.1).
struct FileStamp {
    bool exists = false;
    off_t size = 0;
    timespec modified{};
    std::array<char, 8> wal_salt{};
    bool operator==(const FileStamp& o) const {
        return exists == o.exists && size == o.size && modified.tv_sec == o.modified.tv_sec &&
               modified.tv_nsec == o.modified.tv_nsec && wal_salt == o.wal_salt;
    }
};

FileStamp stamp(const fs::path& file, bool is_wal) {
    FileStamp s;
    struct stat st {};
    if (::stat(file.c_str(), &st) != 0) return s;
    s.exists = true;
    s.size = st.st_size;
    s.modified = st.st_mtim;
    if (is_wal) {
        std::ifstream in(file, std::ios::binary);
        in.seekg(16);
        in.read(s.wal_salt.data(), s.wal_salt.size());
    }
    return s;
}

struct Stamps {
    FileStamp db;
    FileStamp wal;
    bool operator==(const Stamps&) const = default;
};

Stamps stamps(const fs::path& original) {
    return {stamp(original, false), stamp(fs::path(original.string() + "-wal"), true)};
}

Result<void> copy_into(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    if (ec)
        return Error{"cannot read study database '" + from.string() + "' into a private copy (" +
                     ec.message() + "); check that you may read it and that " +
                     to.parent_path().parent_path().string() + " has room."};
    // The copy is ours to open read-write (recovery, migration), whatever the original's mode.
    fs::permissions(to, fs::perms::owner_read | fs::perms::owner_write, ec);
    return Ok{};
}

Result<fs::path> make_private_folder() {
    std::error_code ec;
    const fs::path temp = fs::temp_directory_path(ec);
    if (ec)
        return Error{"no temporary folder to read a study database in (" + ec.message() +
                     "); set TMPDIR to a writable folder."};
    std::string pattern = (temp / "monoplane-read-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) {
        const int err = errno;
        return Error{"cannot make a temporary folder in " + temp.string() + " (" +
                     std::strerror(err) + "); set TMPDIR to a writable folder."};
    }
    return fs::path(pattern);
}

}  // namespace

Result<StoreSnapshot> StoreSnapshot::take(const fs::path& original) {
    Result<fs::path> folder = make_private_folder();
    MONOPLANE_TRY(folder);
    StoreSnapshot snapshot(*folder, *folder / "study.sqlite");
    const fs::path wal(original.string() + "-wal");
    const fs::path wal_copy(snapshot.copy_.string() + "-wal");
    constexpr int kAttempts = 20;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        const Stamps before = stamps(original);
        MONOPLANE_TRY(copy_into(original, snapshot.copy_));
        std::error_code ec;
        fs::remove(wal_copy, ec);
        if (before.wal.exists) {
            // The log may vanish between the stamp and the copy (the writer closed): stamp again.
            if (!fs::exists(wal, ec)) continue;
            MONOPLANE_TRY(copy_into(wal, wal_copy));
        }
        if (stamps(original) == before) return snapshot;
        std::this_thread::sleep_for(std::chrono::milliseconds(20 * (attempt + 1)));
    }
    return Error{"study database '" + original.string() +
                 "' changed during every one of 20 attempts to read it (a session writing "
                 "heavily?); retry in a moment."};
}

StoreSnapshot::StoreSnapshot(StoreSnapshot&& other) noexcept
    : folder_(std::exchange(other.folder_, {})), copy_(std::exchange(other.copy_, {})) {}

StoreSnapshot& StoreSnapshot::operator=(StoreSnapshot&& other) noexcept {
    if (this != &other) {
        StoreSnapshot old(std::move(*this));  // removes ours at the end of this scope
        folder_ = std::exchange(other.folder_, {});
        copy_ = std::exchange(other.copy_, {});
    }
    return *this;
}

StoreSnapshot::~StoreSnapshot() {
    if (folder_.empty()) return;
    std::error_code ec;
    fs::remove_all(folder_, ec);  // best effort: a leftover copy in TMPDIR harms no study
}

}  // namespace monoplane::study
