// Normals for primitives that have none (glTF leaves them to the client).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace monoplane::scenes::gltf {

// The unit normal of a counter-clockwise triangle, or +y for one without area.
glm::vec3 face_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);

// Area-weighted vertex normals of a triangle list (three indices into positions per triangle):
// each face adds its cross product, twice its area times its normal, to its three vertices, so
// big faces count more than slivers. A vertex whose sum (nearly) cancels, as on a sheet shared
// by both sides, takes the normal of its largest face instead; one no triangle uses, or only
// zero-area ones, gets +y (it draws nothing, any unit vector does).
std::vector<glm::vec3> smooth_normals(std::span<const glm::vec3> positions,
                                      std::span<const std::uint32_t> triangles);

}  // namespace monoplane::scenes::gltf
