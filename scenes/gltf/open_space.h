// Whether a point of a scene is open space a participant could stand in, or lies inside a solid
// (a large object's interior: a machine modelled in millimetres is hundreds of glTF "metres"
// wide, so a "walkable" standing point 1.7 m above its lowest point lies inside it).
// CPU only.
#pragma once

#include <glm/vec3.hpp>

#include "scenes/scene.h"

namespace monoplane::scenes::gltf {

// Casts rays from `point` in 26 directions (the cube's faces, edges and corners) against every
// triangle (chunk boxes first). A ray that meets a triangle from behind (the triangle's normal
// points along the ray: the ray runs inside a closed surface) counts as enclosed. The point is
// open space unless most of the rays that meet anything are enclosed, or the ray straight ahead
// (view_direction, unit length) meets something nearer than `clearance` metres. Any time.
bool is_open_space(const Scene& scene, const glm::dvec3& point, const glm::dvec3& view_direction,
                   double clearance = 0.3);

}  // namespace monoplane::scenes::gltf
