// The glTF 2.0 JSON schema's types and cross-references, checked before tinygltf reads the
// document: tinygltf silently ignores optional properties of the wrong type (a texture index of
// -1, a scale that is a string), never range-checks most indices, and recurses without limit
// through `extras` (a deeply nested file would overflow the stack).
#pragma once

#include <cstddef>

#include <nlohmann/json_fwd.hpp>

#include "common/result.h"

namespace monoplane::scenes::gltf {

// Deeper JSON than this is refused (glTF itself nests about 6 levels; the rest is `extras`).
inline constexpr std::size_t kMaxJsonDepth = 64;

// The first problem as a sentence without the file name, e.g. "materials[0].normalTexture.scale
// must be a number, not a string", or "textures[0].source is 3, but the file has 1 image".
// Checks every property the loader or tinygltf reads; unknown properties are left alone.
Result<void> check_json_schema(const nlohmann::json& root);

}  // namespace monoplane::scenes::gltf
