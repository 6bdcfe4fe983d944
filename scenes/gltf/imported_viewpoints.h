// Viewpoints for an imported scene (a default viewpoint from the file's first camera or, without
// one, framing its bounds), plus benchmark views.
#pragma once

#include <optional>
#include <vector>

#include <glm/ext/matrix_double4x4.hpp>

#include "rig/pose.h"
#include "scenes/scene.h"

namespace monoplane::scenes::gltf {

// Eye height above the scene's lowest point where a participant stands in it (the procedural
// scenes' 1.7 m).
inline constexpr double kEyeHeight = 1.7;
// A scene whose footprint is at least this wide on its shorter horizontal side is one to stand
// in (a room, a street, a landscape); a smaller one is an object to look at from outside.
inline constexpr double kWalkableFootprint = 4.0;

bool is_walkable(const Aabb& bounds);

// A glTF camera's world transform as a head pose: glTF cameras look down -z with +y up, like the
// head frame; scale is dropped. Nothing for a singular or mirroring
// transform, which no head pose can express.
std::optional<rig::Pose> camera_pose(const glm::dmat4& world);

// "default": the camera pose if there is one; else, in a walkable scene, standing at eye height
// near its +z side looking down -z across it, if that spot is open space (open_space.h: not
// inside a solid, nothing right in front of the eyes); else outside the bounds, looking at their
// centre from the +z side and 20 degrees above. Then "bench-forward" (the default looking 10
// degrees further down), "bench-overview" (from above a corner) and "bench-side" (from +x), all
// three framing the whole bounds except bench-forward. The scene's chunks, indices, vertices and
// bounds must be complete.
std::vector<Viewpoint> imported_viewpoints(const Scene& scene,
                                           const std::optional<rig::Pose>& camera);

}  // namespace monoplane::scenes::gltf
