// A unit icosphere (a subdivided icosahedron), the base shape of rocks and leafy tree crowns:
// triangles of nearly equal size, unlike a latitude-longitude sphere.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

namespace monoplane::scenes {

struct IcosphereMesh {
    std::vector<glm::vec3> directions;  // unit vectors
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

// 20 * 4^subdivisions triangles, wound counter-clockwise seen from outside.
IcosphereMesh make_icosphere(int subdivisions);

}  // namespace monoplane::scenes
