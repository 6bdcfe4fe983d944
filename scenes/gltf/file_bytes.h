// Whole-file reads for the glTF loader: the .gltf/.glb itself and the buffers and images it names.
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

#include "common/result.h"

namespace monoplane::scenes::gltf {

// glTF's binary container addresses 32 bits, and tinygltf takes JSON lengths as 32-bit counts.
inline constexpr std::uint64_t kMaxFileBytes = 0xffffffffu;

// The file's bytes, or why not ("not found", "is a directory", "is larger than 4 GiB..."). The
// message names neither the glTF file nor the role of this one: the caller knows both.
Result<std::vector<unsigned char>> read_file_bytes(const std::filesystem::path& path);

}  // namespace monoplane::scenes::gltf
