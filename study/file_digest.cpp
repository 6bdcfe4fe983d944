#include "study/file_digest.h"

#include <openssl/evp.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <span>
#include <system_error>
#include <vector>

namespace monoplane::study {
namespace {

struct FreeDigestContext {
    void operator()(EVP_MD_CTX* context) const { EVP_MD_CTX_free(context); }
};
using DigestContext = std::unique_ptr<EVP_MD_CTX, FreeDigestContext>;

// EVP fails only when out of memory or with a broken OpenSSL installation: not the caller's
// mistake, so a runtime error with a message rather than an assertion.
Error openssl_failure(std::string_view what) {
    return Error{"OpenSSL could not compute a SHA-256 digest (" + std::string(what) +
                 "); check the libssl3 installation"};
}

Result<DigestContext> start_sha256() {
    DigestContext context(EVP_MD_CTX_new());
    if (!context) return openssl_failure("EVP_MD_CTX_new");
    if (EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1) {
        return openssl_failure("EVP_DigestInit_ex");
    }
    return context;
}

std::string hex(std::span<const unsigned char> bytes) {
    static constexpr char kDigits[] = "0123456789abcdef";
    std::string text;
    text.reserve(bytes.size() * 2);
    for (const unsigned char byte : bytes) {
        text += kDigits[byte >> 4];
        text += kDigits[byte & 0x0f];
    }
    return text;
}

Result<std::string> finish_sha256(EVP_MD_CTX* context) {
    std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
    unsigned int length = 0;
    if (EVP_DigestFinal_ex(context, digest.data(), &length) != 1 || length != 32) {
        return openssl_failure("EVP_DigestFinal_ex");
    }
    return hex(std::span(digest.data(), length));
}

}  // namespace

Result<FileDigest> digest_file(const std::filesystem::path& path) {
    std::error_code error;
    const std::filesystem::file_status status = std::filesystem::status(path, error);
    if (!std::filesystem::exists(status)) {
        return Error{"file '" + path.string() + "' does not exist"};
    }
    if (!std::filesystem::is_regular_file(status)) {
        return Error{"'" + path.string() + "' is not a regular file"};
    }
    errno = 0;
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        return Error{"cannot open '" + path.string() + "': " + std::strerror(errno)};
    }
    Result<DigestContext> context = start_sha256();
    MONOPLANE_TRY(context);
    constexpr std::size_t kPiece = 64 << 10;  // large files never sit in memory whole
    std::vector<char> piece(kPiece);
    FileDigest digest;
    while (file) {
        file.read(piece.data(), static_cast<std::streamsize>(piece.size()));
        const auto got = static_cast<std::size_t>(file.gcount());
        if (got > 0 && EVP_DigestUpdate(context->get(), piece.data(), got) != 1) {
            return openssl_failure("EVP_DigestUpdate");
        }
        digest.size_bytes += got;
    }
    if (file.bad()) return Error{"cannot read '" + path.string() + "'"};
    Result<std::string> text = finish_sha256(context->get());
    MONOPLANE_TRY(text);
    digest.sha256 = std::move(text).value();
    return digest;
}

bool is_sha256_hex(std::string_view text) {
    return text.size() == 64 && std::ranges::all_of(text, [](char c) {
               return (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f');
           });
}

}  // namespace monoplane::study
