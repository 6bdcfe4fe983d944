#include "scenes/gltf/glb_container.h"

#include <cstdint>
#include <cstring>
#include <string>

namespace monoplane::scenes::gltf {
namespace {

constexpr std::uint32_t kJsonChunk = 0x4E4F534Au;  // "JSON", little-endian
constexpr std::uint32_t kBinChunk = 0x004E4942u;   // "BIN\0"
constexpr std::size_t kHeaderBytes = 12;
constexpr std::size_t kChunkHeaderBytes = 8;

std::uint32_t read_u32(std::span<const unsigned char> bytes, std::size_t offset) {
    // Little-endian, as the container is (and every platform the project builds on).
    std::uint32_t value = 0;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

}  // namespace

bool is_glb(std::span<const unsigned char> bytes) {
    return bytes.size() >= 4 && std::memcmp(bytes.data(), "glTF", 4) == 0;
}

Result<GlbChunks> split_glb(std::span<const unsigned char> bytes) {
    if (!is_glb(bytes)) return Error{"is not a binary glTF file (no \"glTF\" magic)"};
    if (bytes.size() < kHeaderBytes + kChunkHeaderBytes) {
        return Error{"is too short (" + std::to_string(bytes.size()) +
                     " bytes) for a binary glTF header and JSON chunk"};
    }
    const std::uint32_t version = read_u32(bytes, 4);
    if (version == 1) {
        return Error{
            "is binary glTF version 1 (glTF 1.0), which is not supported: convert the "
            "file to glTF 2.0"};
    }
    if (version != 2) {
        return Error{"has binary glTF container version " + std::to_string(version) + ", not 2"};
    }
    const std::uint64_t length = read_u32(bytes, 8);
    if (length > bytes.size()) {
        return Error{"is truncated: its header says " + std::to_string(length) +
                     " bytes, the file has " + std::to_string(bytes.size())};
    }
    const std::uint64_t json_length = read_u32(bytes, 12);
    if (read_u32(bytes, 16) != kJsonChunk) return Error{"has no JSON chunk first"};
    const std::uint64_t json_end = kHeaderBytes + kChunkHeaderBytes + json_length;
    if (json_length == 0 || json_end > length) {
        return Error{"has a JSON chunk of " + std::to_string(json_length) +
                     " bytes that does not fit the file's " + std::to_string(length)};
    }
    GlbChunks chunks;
    chunks.json = std::string_view(reinterpret_cast<const char*>(bytes.data()) + 20,
                                   static_cast<std::size_t>(json_length));
    // The JSON chunk is padded to 4 bytes; a BIN chunk, if any, follows.
    if (length - json_end >= kChunkHeaderBytes) {
        const std::uint64_t bin_length = read_u32(bytes, static_cast<std::size_t>(json_end));
        const std::uint32_t type = read_u32(bytes, static_cast<std::size_t>(json_end) + 4);
        const std::uint64_t bin_begin = json_end + kChunkHeaderBytes;
        if (type != kBinChunk) return Error{"has a second chunk that is not BIN"};
        if (bin_begin + bin_length > length) {
            return Error{"has a BIN chunk of " + std::to_string(bin_length) + " bytes, but only " +
                         std::to_string(length - bin_begin) + " bytes follow its header"};
        }
        chunks.bin = bytes.subspan(static_cast<std::size_t>(bin_begin),
                                   static_cast<std::size_t>(bin_length));
    }
    return chunks;
}

}  // namespace monoplane::scenes::gltf
