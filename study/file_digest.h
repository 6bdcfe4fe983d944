// SHA-256 digests of the files a study's imported scenes were read from (docs/scenes.md, "glTF
// scenes in a study"): evidence, stored with each session, of exactly which bytes the
// participants saw. OpenSSL's EVP interface computes them (libssl-dev), not a hand-written hash.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "common/result.h"

namespace monoplane::study {

struct FileDigest {
    std::uint64_t size_bytes = 0;
    std::string sha256;  // 64 lowercase hex digits, as `sha256sum` prints them

    bool operator==(const FileDigest&) const = default;
};

// The size and SHA-256 (FIPS 180-4) of a file's contents, read in pieces (scene files may be
// gigabytes). Any thread, any time. Refuses, naming the file: a path that does not exist, is not a
// regular file, or cannot be opened or read.
Result<FileDigest> digest_file(const std::filesystem::path& path);

// True for 64 lowercase hex digits: the form digest_file() gives and the database keeps.
bool is_sha256_hex(std::string_view text);

}  // namespace monoplane::study
