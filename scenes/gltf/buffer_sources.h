// Where a glTF file's buffers come from (a .glb's BIN chunk, a data: URI, a file beside it),
// checked before tinygltf reads them, so that a missing .bin or a size mismatch gets a message
// naming the buffer and the file instead of tinygltf's "File not found : x.bin".
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json_fwd.hpp>

#include "common/result.h"

namespace monoplane::scenes::gltf {

// A URI as tinygltf turns it into a file name (percent-decoded, '+' as a space, like its
// dlib::urldecode), or nothing when the URI is not a relative path (a scheme such as http:, or
// an absolute path): glTF resolves URIs against the file's own directory.
std::optional<std::string> uri_to_relative_path(std::string_view uri);

// Whether tinygltf decodes this URI as embedded base64 data (its list of media types).
bool is_base64_data_uri(std::string_view uri);

// Checks every buffer of a schema-checked document (check_json_schema()): a .glb's first buffer
// may take the BIN chunk of bin_size bytes; data: URIs must decode to byteLength bytes; files
// must exist in base_directory with byteLength bytes. The error names the buffer.
Result<void> check_buffer_sources(const nlohmann::json& root,
                                  const std::filesystem::path& base_directory, bool is_glb,
                                  std::size_t bin_size);

}  // namespace monoplane::scenes::gltf
