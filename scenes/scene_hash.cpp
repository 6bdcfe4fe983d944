// geometry_hash (generate.h): a splitmix-based combine over 64-bit words of the raw bytes.
// Word-wise rather than FNV's byte-wise, so hashing a High scene (about 100 MB) stays cheap.
// Little-endian byte order is assumed (every platform the project builds on).
#include <algorithm>
#include <cstring>
#include <string>

#include "scenes/generate.h"
#include "scenes/random.h"

namespace monoplane::scenes {
namespace {

class Hasher {
  public:
    void bytes(const void* data, std::size_t size) {
        const auto* p = static_cast<const unsigned char*>(data);
        std::size_t i = 0;
        for (; i + 8 <= size; i += 8) {
            std::uint64_t word = 0;
            std::memcpy(&word, p + i, 8);
            word_(word);
        }
        if (i < size) {
            std::uint64_t tail = 0;
            std::memcpy(&tail, p + i, size - i);
            word_(tail);
        }
        word_(size);  // so that moving bytes between fields changes the hash
    }
    template <typename T>
    void value(const T& v) {
        bytes(&v, sizeof v);
    }
    std::uint64_t result() const { return mix64(state_); }

  private:
    void word_(std::uint64_t word) { state_ = mix64(state_ ^ word) + 0x9e3779b97f4a7c15ULL; }
    std::uint64_t state_ = 0x6d6f6e6f706c616eULL;  // "monoplan"
};

}  // namespace

std::uint64_t geometry_hash(const Scene& scene) {
    static_assert(sizeof(Vertex) == 32, "Vertex has no padding to hash");
    Hasher hasher;
    hasher.bytes(scene.vertices.data(), scene.vertices.size() * sizeof(Vertex));
    hasher.bytes(scene.indices.data(), scene.indices.size() * sizeof(std::uint32_t));
    // Only scenes with masked or blended chunks hash the alpha fields: opaque scenes, procedural
    // or imported, keep the hashes they had before alpha modes were read.
    const bool any_alpha =
        std::any_of(scene.chunks.begin(), scene.chunks.end(),
                    [](const Chunk& chunk) { return chunk.alpha_mode != AlphaMode::kOpaque; });
    // Chunks field by field: never hash padding.
    for (const Chunk& chunk : scene.chunks) {
        hasher.value(chunk.first_index);
        hasher.value(chunk.index_count);
        hasher.value(chunk.vertex_offset);
        hasher.value(chunk.bounds.min);
        hasher.value(chunk.bounds.max);
        hasher.value(chunk.flags);
        // Only imported scenes have textures: procedural hashes stay what they always were.
        if (!scene.textures.empty()) hasher.value(chunk.texture);
        if (any_alpha) {
            hasher.value(static_cast<std::uint8_t>(chunk.alpha_mode));
            hasher.value(chunk.alpha_cutoff);
        }
    }
    if (!scene.texcoords.empty()) {
        hasher.bytes(scene.texcoords.data(), scene.texcoords.size() * sizeof(glm::vec2));
    }
    for (const Viewpoint& viewpoint : scene.viewpoints) {
        hasher.bytes(viewpoint.name.data(), viewpoint.name.size());
        hasher.value(viewpoint.head.position);
        hasher.value(viewpoint.head.orientation);
    }
    return hasher.result();
}

}  // namespace monoplane::scenes
