// Reads glTF accessors (glTF 2.0 section 3.6) trusting nothing the file says: the accessor, its
// buffer view and buffer must exist, the element type and component type must be ones glTF
// allows for the attribute, every byte read must lie inside the view and the view inside the
// buffer's real bytes, sparse substitutions must stay in range, floats must be finite.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "common/result.h"
#include "scenes/gltf/tiny_gltf_config.h"

namespace monoplane::scenes::gltf {

struct FloatRequest {
    std::string what;            // "POSITION of mesh 'Cube' primitive 0", for messages
    std::span<const int> types;  // allowed TINYGLTF_TYPE_* (VEC2, VEC3, ...)
    // UNSIGNED_BYTE and UNSIGNED_SHORT with normalized: true, besides FLOAT (TEXCOORD_n,
    // COLOR_0); otherwise FLOAT only (POSITION, NORMAL).
    bool normalized_unsigned = false;
    std::size_t max_count = 0;  // refuse more elements than this (an allocation bound)
};

struct FloatElements {
    std::size_t components = 0;  // per element: 2 for VEC2...
    std::size_t count = 0;       // elements
    std::vector<float> values;   // count * components, normalized integers decoded to [0, 1]
};

// The accessor's elements as floats. Errors read "accessor 3 (POSITION of mesh 'Cube' primitive
// 0): count 24 with stride 12 from byte 0 reads past the end of buffer view 1 (288 bytes)".
Result<FloatElements> read_float_accessor(const tinygltf::Model& model, int index,
                                          const FloatRequest& request);

// A primitive's indices: SCALAR, UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT, not normalized.
// Each is checked against vertex_count (the primitive's POSITION count).
Result<std::vector<std::uint32_t>> read_index_accessor(const tinygltf::Model& model, int index,
                                                       const std::string& what,
                                                       std::size_t vertex_count,
                                                       std::size_t max_count);

}  // namespace monoplane::scenes::gltf
