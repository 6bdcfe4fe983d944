// BEAMS (papers/000 Sect. 6, Fig. 6b): a scaffold-like field of long straight beams with sharp
// edges, the worst case for hybrid rendering: rails run along the view direction from arm's
// length through every mono-plane distance, so the kink at the mono plane shows on each of them.
#pragma once

#include <cstdint>
#include <vector>

#include "scenes/beam_mesh.h"
#include "scenes/scene.h"

namespace monoplane::scenes {

struct BeamsLayout {
    std::vector<Beam> beams;         // every beam of the scene, before tessellation
    std::vector<std::size_t> rails;  // indices into beams: those running along -z from near
};

// The beams that generate_beams() tessellates; exposed so tests and tools can find the rails.
BeamsLayout beams_layout(Detail detail, std::uint64_t seed);

Scene generate_beams(Detail detail, std::uint64_t seed);

}  // namespace monoplane::scenes
