// SPHERES (papers/000 Sect. 6, Fig. 6d): many spheres of varied size spread through depth, no
// lines or edges: the benign case for hybrid rendering.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "scenes/scene.h"

namespace monoplane::scenes {

// Sphere centres lie at depths (metres along -z from the default eye, which stands at z = 0)
// stratified uniformly over [kSpheresNearest, kSpheresFarthest].
inline constexpr float kSpheresNearest = 0.5f;
inline constexpr float kSpheresFarthest = 170.0f;

struct PlacedSphere {
    glm::vec3 centre;
    float radius;
};

// The spheres generate_spheres() tessellates, in placement order (nearest stratum first); a
// sphere that found no free spot is left out.
std::vector<PlacedSphere> spheres_layout(Detail detail, std::uint64_t seed);

Scene generate_spheres(Detail detail, std::uint64_t seed);

}  // namespace monoplane::scenes
