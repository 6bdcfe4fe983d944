// glTF primitive modes to triangle lists (glTF 2.0 section 3.7.2.1): the renderer draws lists.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace monoplane::scenes::gltf {

// glTF's mode numbers.
enum class PrimitiveMode : int {
    Points = 0,
    Lines = 1,
    LineLoop = 2,
    LineStrip = 3,
    Triangles = 4,
    TriangleStrip = 5,
    TriangleFan = 6,
};

bool is_triangle_mode(int mode);

struct TriangleList {
    std::vector<std::uint32_t> indices;  // three per triangle, in the file's winding
    std::size_t dropped_incomplete = 0;  // indices left over (a list not a multiple of 3)
    std::size_t dropped_degenerate = 0;  // triangles with a repeated index (strip restarts)
};

// The triangles of a TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN primitive whose vertex sequence
// is `sequence` (its indices, or 0..n-1 without). Strips alternate winding so that every
// triangle keeps the first one's orientation: triangle i is (v[i], v[i+1], v[i+2]) for even i and
// (v[i+1], v[i], v[i+2]) for odd i; fans are (v[i+1], v[i+2], v[0]), as the specification gives.
// May be called only for is_triangle_mode(mode).
TriangleList triangulate(int mode, const std::vector<std::uint32_t>& sequence);

}  // namespace monoplane::scenes::gltf
