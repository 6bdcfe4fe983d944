// The binary glTF container (.glb): a 12-byte header, a JSON chunk and an optional BIN chunk
// (glTF 2.0 section 4.4). Checked here so that a truncated or glTF 1.0 file gets a clear message
// rather than tinygltf's "Invalid glTF binary."
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

#include "common/result.h"

namespace monoplane::scenes::gltf {

struct GlbChunks {
    std::string_view json;               // views into the file's bytes
    std::span<const unsigned char> bin;  // empty without a BIN chunk
};

// Whether the bytes start with the GLB magic "glTF" (whatever the file's extension says).
bool is_glb(std::span<const unsigned char> bytes);

// The chunks of a GLB file; the error says what is wrong with the container.
Result<GlbChunks> split_glb(std::span<const unsigned char> bytes);

}  // namespace monoplane::scenes::gltf
