// LANDSCAPE (papers/000 Sect. 6, Fig. 6c): a natural terrain with rocks and trees, the ground
// rising in the view with distance; low depth complexity, a typical application scenario.
#pragma once

#include <cstdint>

#include "scenes/scene.h"

namespace monoplane::scenes {

Scene generate_landscape(Detail detail, std::uint64_t seed);

}  // namespace monoplane::scenes
