// Per-detail-level parameters of the generators (scene.h: Detail). Each generator keeps its own
// table; these helpers keep the tables short.
#pragma once

#include <array>
#include <cstdint>

#include "scenes/scene.h"

namespace monoplane::scenes {

inline constexpr std::size_t kDetailCount = 5;

template <typename T>
using PerDetail = std::array<T, kDetailCount>;

template <typename T>
const T& for_detail(const PerDetail<T>& values, Detail detail) {
    return values[static_cast<std::size_t>(detail)];
}

// Test scenes are small, so their chunks are too: a few dozen chunks keep culling testable.
// Larger scenes get chunks of about a thousand triangles: hybrid rendering pays only when few
// chunks straddle the mono plane (papers/000 Sect. 4.4 and 7: "a reasonably grained
// subdivision"), and the GPU culling makes many chunks cheap (one thread each, indirect draws).
inline std::uint32_t chunk_triangle_target(Detail detail) {
    return detail == Detail::Test ? 2048u : 1024u;
}

}  // namespace monoplane::scenes
