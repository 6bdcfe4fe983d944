#include "scenes/gltf/imported_viewpoints.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "scenes/gltf/open_space.h"

namespace monoplane::scenes::gltf {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
// Half the vertical field of view a framing pose allows for (headsets see about 90-110 degrees).
constexpr double kHalfFieldDegrees = 35.0;
// The renderer's near plane is 0.1 m: stand at least this far outside a small object's sphere.
constexpr double kMinClearance = 0.25;

// Outside the bounds' sphere, at azimuth (0: from +z, 90: from +x) and elevation, looking at the
// centre.
Viewpoint framing(std::string name, const Aabb& bounds, double azimuth_degrees,
                  double elevation_degrees) {
    const glm::dvec3 centre = 0.5 * (glm::dvec3(bounds.min) + glm::dvec3(bounds.max));
    const double radius = 0.5 * glm::length(glm::dvec3(bounds.max) - glm::dvec3(bounds.min));
    const double distance =
        std::max(radius / std::sin(kHalfFieldDegrees * kRadiansPerDegree), radius + kMinClearance);
    const double a = azimuth_degrees * kRadiansPerDegree;
    const double e = elevation_degrees * kRadiansPerDegree;
    const glm::dvec3 outward(std::sin(a) * std::cos(e), std::sin(e), std::cos(a) * std::cos(e));
    // make_viewpoint's yaw turns -z towards -x: facing -outward means yaw = azimuth.
    return make_viewpoint(std::move(name), centre + distance * outward, azimuth_degrees,
                          -elevation_degrees);
}

}  // namespace

bool is_walkable(const Aabb& bounds) {
    const glm::vec3 extent = bounds.max - bounds.min;
    return std::min(extent.x, extent.z) >= kWalkableFootprint;
}

std::optional<rig::Pose> camera_pose(const glm::dmat4& world) {
    glm::dmat3 rotation(world);
    for (int c = 0; c < 3; ++c) {
        const double length = glm::length(rotation[c]);
        if (!(length > 1e-12)) return std::nullopt;
        rotation[c] /= length;
    }
    if (glm::determinant(rotation) <= 0.0) return std::nullopt;
    rig::Pose pose;
    pose.position = glm::dvec3(world[3]);
    pose.orientation = glm::normalize(glm::quat_cast(rotation));
    return pose;
}

std::vector<Viewpoint> imported_viewpoints(const Scene& scene,
                                           const std::optional<rig::Pose>& camera) {
    const Aabb& bounds = scene.bounds;
    Viewpoint standing;
    if (camera) {
        standing.name = "default";
        standing.head = *camera;
    } else {
        standing = framing("default", bounds, 0.0, 20.0);
        if (is_walkable(bounds)) {
            const double depth = static_cast<double>(bounds.max.z) - bounds.min.z;
            const glm::dvec3 position(
                0.5 * (static_cast<double>(bounds.min.x) + bounds.max.x),
                static_cast<double>(bounds.min.y) + kEyeHeight,
                static_cast<double>(bounds.max.z) - std::min(1.0, 0.25 * depth));
            if (is_open_space(scene, position, glm::dvec3(0.0, 0.0, -1.0))) {
                standing = make_viewpoint("default", position);
            }
        }
    }
    Viewpoint forward = standing;
    forward.name = "bench-forward";
    const glm::dquat down = glm::angleAxis(-10.0 * kRadiansPerDegree, glm::dvec3(1.0, 0.0, 0.0));
    forward.head.orientation = glm::normalize(standing.head.orientation * down);
    return {standing, forward, framing("bench-overview", bounds, 45.0, 35.0),
            framing("bench-side", bounds, 90.0, 10.0)};
}

}  // namespace monoplane::scenes::gltf
