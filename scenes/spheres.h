// SPHERES (papers/000 Sect. 6, Fig. 6d): many spheres of varied size spread through depth, no
// lines or edges: the benign case for hybrid rendering.
#pragma once

#include <cstdint>

#include "scenes/scene.h"

namespace monoplane::scenes {

Scene generate_spheres(Detail detail, std::uint64_t seed);

}  // namespace monoplane::scenes
