// What this loader reads: glTF 2.0 only, and only the required extensions it can honour. A file
// that requires more would render wrongly (Draco-compressed geometry, quantized positions,
// texture transforms), so it is refused with the reason rather than shown half-read.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include "common/result.h"

namespace monoplane::scenes::gltf {

// The message names the version or extension and what to do, e.g. "glTF 1.0 is not supported
// (asset.version is \"1.0\"): convert the file to glTF 2.0". Call before check_json_schema(): a
// glTF 1.0 file breaks the 2.0 schema everywhere, and the version is the one thing worth saying.
Result<void> check_supported(const nlohmann::json& root);

}  // namespace monoplane::scenes::gltf
