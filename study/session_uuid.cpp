#include "study/session_uuid.h"

#include <openssl/evp.h>
#include <openssl/rand.h>

#include <algorithm>
#include <array>
#include <random>

#include "common/programming_error.h"

namespace monoplane::study {
namespace {

using Bytes = std::array<unsigned char, 16>;

// Sets the version nibble and the RFC 9562 variant bits (10xx), then writes 8-4-4-4-12 hex.
std::string format_uuid(Bytes bytes, unsigned version) {
    bytes[6] = static_cast<unsigned char>((bytes[6] & 0x0f) | (version << 4));
    bytes[8] = static_cast<unsigned char>((bytes[8] & 0x3f) | 0x80);
    static constexpr char kHex[] = "0123456789abcdef";
    std::string text;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        if (i == 4 || i == 6 || i == 8 || i == 10) text += '-';
        text += kHex[bytes[i] >> 4];
        text += kHex[bytes[i] & 0x0f];
    }
    return text;
}

}  // namespace

std::string random_session_uuid() {
    Bytes bytes{};
    if (RAND_bytes(bytes.data(), static_cast<int>(bytes.size())) != 1) {
        // OpenSSL's generator failed to seed (it should not on Linux): the kernel's instead.
        std::random_device device;
        for (unsigned char& b : bytes) b = static_cast<unsigned char>(device());
    }
    return format_uuid(bytes, 4);
}

std::string derived_session_uuid(std::string_view identity) {
    std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
    unsigned int length = 0;
    if (EVP_Digest(identity.data(), identity.size(), digest.data(), &length, EVP_sha256(),
                   nullptr) != 1 ||
        length < 16) {
        programming_error("SHA-256 is unavailable in this OpenSSL");  // a broken build
    }
    Bytes bytes{};
    std::copy_n(digest.begin(), bytes.size(), bytes.begin());
    return format_uuid(bytes, 8);
}

bool is_session_uuid(std::string_view text) {
    if (text.size() != 36) return false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        const bool dash = i == 8 || i == 13 || i == 18 || i == 23;
        if (dash ? c != '-' : !((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    }
    return true;
}

}  // namespace monoplane::study
