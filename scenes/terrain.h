// The LANDSCAPE height field: flat where the participant stands, gently rolling nearby, hills
// further out and mountains beyond 150 m, so the ground rises in the view with distance
// (papers/000 Sect. 5: ground and what stands on it rise in the visual field).
#pragma once

#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace monoplane::scenes {

class Terrain {
  public:
    explicit Terrain(std::uint64_t seed);

    // Height in metres at ground position (x, z); exactly 0 within 1 m of the origin.
    float height(glm::vec2 position) const;
    // Unit normal from central differences over about the given cell size, so coarse far cells
    // are not shaded with detail they do not have.
    glm::vec3 normal(glm::vec2 position, float cell_size) const;
    // Linear albedo from height, slope and a little noise: grass, dry grass, rock, snow.
    glm::vec3 albedo(glm::vec2 position, float height, glm::vec3 normal) const;

    static constexpr float kTreeLine = 55.0f;
    static constexpr float kSnowLine = 95.0f;

  private:
    std::uint64_t seed_;
};

}  // namespace monoplane::scenes
