#include "scenes/gltf/buffer_sources.h"

#include <array>
#include <cstdint>
#include <system_error>

#include <nlohmann/json.hpp>

#include "scenes/gltf/file_bytes.h"

namespace monoplane::scenes::gltf {
namespace {

using nlohmann::json;

// tinygltf's IsDataURI(): any other data: URI it would take for a file name.
constexpr std::array<std::string_view, 7> kBase64Prefixes = {
    "data:application/octet-stream;base64,",
    "data:image/jpeg;base64,",
    "data:image/png;base64,",
    "data:image/bmp;base64,",
    "data:image/gif;base64,",
    "data:text/plain;base64,",
    "data:application/gltf-buffer;base64,",
};

int hex_value(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return 0;  // as tinygltf's from_hex
}

bool is_base64_digit(char c) {
    return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' ||
           c == '/';
}

// The bytes base64 text decodes to: tinygltf's decoder stops at the first character that is not
// a base64 digit ('=' padding included).
std::uint64_t base64_decoded_size(std::string_view text) {
    std::uint64_t digits = 0;
    while (digits < text.size() && is_base64_digit(text[digits])) ++digits;
    return digits / 4 * 3 + (digits % 4 == 0 ? 0 : digits % 4 - 1);
}

// tinygltf's decoder counts characters in an int.
constexpr std::size_t kMaxDataUriBytes = 0x7fffffffu;

std::string in_quotes(std::string_view text) {
    constexpr std::size_t kLongest = 80;
    if (text.size() > kLongest) return "\"" + std::string(text.substr(0, kLongest)) + "...\"";
    return "\"" + std::string(text) + "\"";
}

Result<void> check_buffer(const json& buffer, std::size_t index,
                          const std::filesystem::path& base_directory, bool is_glb,
                          std::size_t bin_size) {
    const std::string name = "buffer " + std::to_string(index);
    const std::uint64_t byte_length = buffer.at("byteLength").get<std::uint64_t>();
    const auto uri_member = buffer.find("uri");
    if (uri_member == buffer.end()) {
        if (!is_glb) return Error{name + " has no uri (only a .glb's first buffer may omit it)"};
        if (index != 0)
            return Error{name + " has no uri (only the first buffer may use the BIN chunk)"};
        if (bin_size == 0) return Error{name + " has no uri, and the .glb has no BIN chunk"};
        if (byte_length > bin_size) {
            return Error{name + " has byteLength " + std::to_string(byte_length) +
                         ", more than the .glb's BIN chunk (" + std::to_string(bin_size) +
                         " bytes)"};
        }
        return Ok{};
    }
    const std::string uri = uri_member->get<std::string>();
    if (uri.rfind("data:", 0) == 0) {
        if (!is_base64_data_uri(uri)) {
            return Error{name + "'s data: URI is not base64 with a media type glTF allows"};
        }
        if (uri.size() > kMaxDataUriBytes) {
            return Error{name + "'s data: URI is longer than 2 GiB: use a .glb or a .bin file"};
        }
        const std::uint64_t decoded = base64_decoded_size(uri.substr(uri.find(',') + 1));
        if (decoded != byte_length) {
            return Error{name + "'s data: URI holds " + std::to_string(decoded) +
                         " bytes, but its byteLength is " + std::to_string(byte_length)};
        }
        return Ok{};
    }
    const std::optional<std::string> relative = uri_to_relative_path(uri);
    if (!relative) {
        return Error{name + "'s uri " + in_quotes(uri) +
                     " is not a path relative to the glTF file (other URIs are not supported)"};
    }
    const std::filesystem::path path = base_directory / *relative;
    std::error_code error;
    if (!std::filesystem::is_regular_file(path, error)) {
        return Error{name + ": file " + in_quotes(*relative) + " not found in " +
                     (base_directory.empty() ? std::string("the current directory")
                                             : base_directory.string())};
    }
    const std::uintmax_t size = std::filesystem::file_size(path, error);
    if (error) return Error{name + ": file " + in_quotes(*relative) + " cannot be read"};
    if (size != byte_length) {
        return Error{name + ": file " + in_quotes(*relative) + " has " + std::to_string(size) +
                     " bytes, but the buffer's byteLength is " + std::to_string(byte_length)};
    }
    if (size > kMaxFileBytes)
        return Error{name + ": file " + in_quotes(*relative) + " is over 4 GiB"};
    return Ok{};
}

}  // namespace

bool is_base64_data_uri(std::string_view uri) {
    for (const std::string_view prefix : kBase64Prefixes) {
        if (uri.substr(0, prefix.size()) == prefix) return true;
    }
    return false;
}

std::optional<std::string> uri_to_relative_path(std::string_view uri) {
    // A scheme is letters, digits, + - . before the first ':' (RFC 3986); a path's first
    // segment may not contain ':' unless something precedes it.
    const std::size_t colon = uri.find(':');
    const std::size_t slash = uri.find('/');
    if (colon != std::string_view::npos && (slash == std::string_view::npos || colon < slash)) {
        return std::nullopt;
    }
    if (uri.empty() || uri.front() == '/' || uri.front() == '\\') return std::nullopt;
    std::string path;
    for (std::size_t i = 0; i < uri.size(); ++i) {
        if (uri[i] == '+') {
            path += ' ';
        } else if (uri[i] == '%' && uri.size() > i + 2) {
            path += static_cast<char>(hex_value(uri[i + 1]) * 16 + hex_value(uri[i + 2]));
            i += 2;
        } else {
            path += uri[i];
        }
    }
    if (path.find('\0') != std::string::npos) return std::nullopt;
    return path;
}

Result<void> check_buffer_sources(const json& root, const std::filesystem::path& base_directory,
                                  bool is_glb, std::size_t bin_size) {
    const auto buffers = root.find("buffers");
    if (buffers == root.end()) return Ok{};
    for (std::size_t i = 0; i < buffers->size(); ++i) {
        MONOPLANE_TRY(check_buffer((*buffers)[i], i, base_directory, is_glb, bin_size));
    }
    return Ok{};
}

}  // namespace monoplane::scenes::gltf
