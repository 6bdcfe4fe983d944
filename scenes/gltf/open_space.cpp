#include "scenes/gltf/open_space.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include <glm/geometric.hpp>

namespace monoplane::scenes::gltf {
namespace {

struct Hit {
    double distance = std::numeric_limits<double>::infinity();
    bool from_behind = false;
};

bool ray_meets_box(const glm::dvec3& origin, const glm::dvec3& direction, const Aabb& box,
                   double nearer_than) {
    double enter = 0.0;
    double leave = nearer_than;
    for (int axis = 0; axis < 3; ++axis) {
        const double lo = box.min[axis], hi = box.max[axis];
        if (std::abs(direction[axis]) < 1e-15) {
            if (origin[axis] < lo || origin[axis] > hi) return false;
            continue;
        }
        double t0 = (lo - origin[axis]) / direction[axis];
        double t1 = (hi - origin[axis]) / direction[axis];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
        if (enter > leave) return false;
    }
    return true;
}

// Möller-Trumbore; the distance along the ray, or nothing.
std::optional<double> ray_meets_triangle(const glm::dvec3& origin, const glm::dvec3& direction,
                                         const glm::dvec3& a, const glm::dvec3& b,
                                         const glm::dvec3& c) {
    const glm::dvec3 ab = b - a, ac = c - a;
    const glm::dvec3 p = glm::cross(direction, ac);
    const double det = glm::dot(ab, p);
    if (std::abs(det) < 1e-18) return std::nullopt;
    const glm::dvec3 s = origin - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, ab);
    const double v = glm::dot(direction, q) / det;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double t = glm::dot(ac, q) / det;
    return t > 1e-9 ? std::optional<double>(t) : std::nullopt;
}

Hit nearest_hit(const Scene& scene, const glm::dvec3& origin, const glm::dvec3& direction) {
    Hit hit;
    for (const Chunk& chunk : scene.chunks) {
        if (!ray_meets_box(origin, direction, chunk.bounds, hit.distance)) continue;
        for (std::uint32_t i = 0; i + 2 < chunk.index_count; i += 3) {
            std::array<glm::dvec3, 3> corner;
            for (std::uint32_t k = 0; k < 3; ++k) {
                const std::uint32_t vertex = scene.indices[chunk.first_index + i + k] +
                                             static_cast<std::uint32_t>(chunk.vertex_offset);
                corner[k] = glm::dvec3(scene.vertices[vertex].position);
            }
            const std::optional<double> t =
                ray_meets_triangle(origin, direction, corner[0], corner[1], corner[2]);
            if (!t || *t >= hit.distance) continue;
            hit.distance = *t;
            // Triangles wind counter-clockwise about their outward side (scene.h).
            const glm::dvec3 normal = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
            hit.from_behind = glm::dot(normal, direction) > 0.0;
        }
    }
    return hit;
}

}  // namespace

bool is_open_space(const Scene& scene, const glm::dvec3& point, const glm::dvec3& view_direction,
                   double clearance) {
    if (nearest_hit(scene, point, view_direction).distance < clearance) return false;
    int met = 0;
    int enclosed = 0;
    for (int x = -1; x <= 1; ++x) {
        for (int y = -1; y <= 1; ++y) {
            for (int z = -1; z <= 1; ++z) {
                if (x == 0 && y == 0 && z == 0) continue;
                const Hit hit = nearest_hit(scene, point, glm::normalize(glm::dvec3(x, y, z)));
                if (!std::isfinite(hit.distance)) continue;
                ++met;
                if (hit.from_behind) ++enclosed;
            }
        }
    }
    return 2 * enclosed <= met;
}

}  // namespace monoplane::scenes::gltf
