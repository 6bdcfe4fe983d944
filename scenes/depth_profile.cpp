#include "scenes/depth_profile.h"

#include <algorithm>
#include <limits>

#include <glm/ext/matrix_double4x4.hpp>

namespace monoplane::scenes {

rig::Pose eye_pose(const rig::Pose& head, const glm::dvec3& offset_in_head) {
    rig::Pose eye = head;
    eye.position = head.position + head.orientation * offset_in_head;
    return eye;
}

PrimitiveDepthProfile primitive_depth_profile(const Scene& scene, const DepthProfileView& view,
                                              std::span<const double> distances) {
    const glm::dmat4 eye_from_world = rig::view_matrix(view.eye, glm::dvec3(0.0));
    const rig::Tangents& t = view.tangents;
    // Centroid depths of the triangles in view, sorted: a fraction is then one binary search.
    std::vector<double> depths;
    depths.reserve(scene.triangle_count());
    for (const Chunk& chunk : scene.chunks) {
        const std::uint32_t end = chunk.first_index + chunk.index_count;
        for (std::uint32_t i = chunk.first_index; i + 2 < end; i += 3) {
            glm::dvec3 sum{0.0};
            for (std::uint32_t k = 0; k < 3; ++k) {
                const std::size_t vertex = static_cast<std::size_t>(
                    static_cast<std::int64_t>(scene.indices[i + k]) + chunk.vertex_offset);
                sum += glm::dvec3(scene.vertices[vertex].position);
            }
            const glm::dvec3 p = glm::dvec3(eye_from_world * glm::dvec4(sum / 3.0, 1.0));
            const double depth = -p.z;
            if (!(depth >= view.near && depth <= view.far)) continue;
            const double x = p.x / depth;
            const double y = p.y / depth;
            if (x < t.left || x > t.right || y < t.down || y > t.up) continue;
            depths.push_back(depth);
        }
    }
    std::sort(depths.begin(), depths.end());

    PrimitiveDepthProfile profile;
    profile.triangles_in_view = depths.size();
    for (const double m : distances) {
        if (depths.empty()) {
            profile.fraction_nearer.push_back(std::numeric_limits<double>::quiet_NaN());
            continue;
        }
        const auto nearer = std::lower_bound(depths.begin(), depths.end(), m) - depths.begin();
        profile.fraction_nearer.push_back(static_cast<double>(nearer) /
                                          static_cast<double>(depths.size()));
    }
    return profile;
}

std::vector<double> pixel_fraction_nearer(std::span<const float> linear_depth,
                                          std::span<const double> distances) {
    std::vector<double> fractions;
    fractions.reserve(distances.size());
    for (const double m : distances) {
        if (linear_depth.empty()) {
            fractions.push_back(std::numeric_limits<double>::quiet_NaN());
            continue;
        }
        const auto nearer = std::count_if(linear_depth.begin(), linear_depth.end(),
                                          [&](float d) { return static_cast<double>(d) < m; });
        fractions.push_back(static_cast<double>(nearer) / static_cast<double>(linear_depth.size()));
    }
    return fractions;
}

}  // namespace monoplane::scenes
