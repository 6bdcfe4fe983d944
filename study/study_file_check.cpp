#include "study/study_file_check.h"

#include <array>
#include <fstream>
#include <string>
#include <string_view>
#include <system_error>

#include "common/quoted.h"

namespace monoplane::study {
namespace {

// The first 100 bytes of a SQLite file (https://www.sqlite.org/fileformat2.html, section 1.3).
constexpr std::size_t kHeaderBytes = 100;
constexpr std::string_view kMagic{"SQLite format 3\0", 16};

std::uint32_t big_endian(const std::array<unsigned char, kHeaderBytes>& h, std::size_t at,
                         std::size_t bytes) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < bytes; ++i) value = (value << 8) | h[at + i];
    return value;
}

Error missing(const std::filesystem::path& file) {
    return Error{"no study database " + in_quotes(file) +
                 " (no such file); check the name, or start a study with `monoplane study run`."};
}

// The database size the header promises, in bytes, or 0 when the header does not vouch for it
// (the in-header size is valid only while the change counter at 24 equals the version-valid-for
// number at 92; older writers left it stale).
std::uintmax_t promised_size(const std::array<unsigned char, kHeaderBytes>& h) {
    std::uintmax_t page_size = big_endian(h, 16, 2);
    if (page_size == 1) page_size = 65536;
    const std::uint32_t pages = big_endian(h, 28, 4);
    if (big_endian(h, 24, 4) != big_endian(h, 92, 4)) return 0;
    return page_size * pages;
}

Result<void> check_header(const std::filesystem::path& file, std::uintmax_t size) {
    std::array<unsigned char, kHeaderBytes> header{};
    std::ifstream in(file, std::ios::binary);
    if (!in)
        return Error{"cannot read study database " + in_quotes(file) +
                     "; check that you may read it."};
    in.read(reinterpret_cast<char*>(header.data()), header.size());
    const std::string_view start(reinterpret_cast<const char*>(header.data()),
                                 static_cast<std::size_t>(in.gcount()));
    if (!start.starts_with(kMagic))
        return Error{in_quotes(file) +
                     " is not a SQLite database, so not a study database; give the study's "
                     ".sqlite file, or a new file name to start one."};
    if (size < kHeaderBytes)
        return Error{in_quotes(file) + " is truncated (" + std::to_string(size) +
                     " bytes, shorter than a SQLite header): a copy that failed? Copy it again "
                     "from the original."};
    const std::uintmax_t promised = promised_size(header);
    if (promised > size)
        return Error{in_quotes(file) + " is truncated: " + std::to_string(size) + " bytes of the " +
                     std::to_string(promised) +
                     " its header promises. A copy that failed? Copy it again from the original."};
    return Ok{};
}

}  // namespace

Result<StudyFileState> check_study_file(const std::filesystem::path& file, StudyFileUse use) {
    if (file.empty()) return Error{"no study database file given"};
    std::error_code ec;
    const std::filesystem::file_status status = std::filesystem::status(file, ec);
    if (status.type() == std::filesystem::file_type::not_found) {
        if (use == StudyFileUse::Create) return StudyFileState{};
        return missing(file);
    }
    if (ec)
        return Error{"cannot look at study database " + in_quotes(file) + ": " + ec.message() +
                     "."};
    if (status.type() != std::filesystem::file_type::regular)
        return Error{in_quotes(file) + " is not a regular file, so not a study database."};
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    if (ec)
        return Error{"cannot look at study database " + in_quotes(file) + ": " + ec.message() +
                     "."};
    if (size == 0)
        return Error{in_quotes(file) +
                     " is 0 bytes: not a study database; a copy that failed? Use the original, "
                     "or give a new file name to start a study."};
    MONOPLANE_TRY(check_header(file, size));
    return StudyFileState{.exists = true, .size_bytes = size};
}

}  // namespace monoplane::study
