#include "scenes/gltf/primitive_topology.h"

#include "common/programming_error.h"

namespace monoplane::scenes::gltf {

bool is_triangle_mode(int mode) {
    return mode == static_cast<int>(PrimitiveMode::Triangles) ||
           mode == static_cast<int>(PrimitiveMode::TriangleStrip) ||
           mode == static_cast<int>(PrimitiveMode::TriangleFan);
}

TriangleList triangulate(int mode, const std::vector<std::uint32_t>& sequence) {
    MONOPLANE_EXPECTS(is_triangle_mode(mode));
    TriangleList list;
    const std::size_t n = sequence.size();
    auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        // A repeated index spans no area: strips use them to restart, nothing is drawn.
        if (a == b || b == c || a == c) {
            ++list.dropped_degenerate;
            return;
        }
        list.indices.insert(list.indices.end(), {a, b, c});
    };
    if (mode == static_cast<int>(PrimitiveMode::Triangles)) {
        list.indices.reserve(n - n % 3);
        for (std::size_t i = 0; i + 2 < n; i += 3)
            add(sequence[i], sequence[i + 1], sequence[i + 2]);
        list.dropped_incomplete = n % 3;
        return list;
    }
    if (n < 3) {
        list.dropped_incomplete = n;
        return list;
    }
    list.indices.reserve(3 * (n - 2));
    for (std::size_t i = 0; i + 2 < n; ++i) {
        if (mode == static_cast<int>(PrimitiveMode::TriangleStrip)) {
            if (i % 2 == 0) {
                add(sequence[i], sequence[i + 1], sequence[i + 2]);
            } else {
                add(sequence[i + 1], sequence[i], sequence[i + 2]);
            }
        } else {
            add(sequence[i + 1], sequence[i + 2], sequence[0]);
        }
    }
    return list;
}

}  // namespace monoplane::scenes::gltf
