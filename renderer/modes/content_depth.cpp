#include "renderer/modes/content_depth.h"

#include <algorithm>

#include <glm/geometric.hpp>

#include "renderer/modes/frustum_culling.h"

namespace monoplane::modes {

double farthest_content_depth(const scenes::Scene& scene, const StereoViewInputs& views,
                              double widen_tangent) {
    StereoViewInputs widened = views;
    for (rig::Tangents* t : {&widened.left, &widened.right}) {
        t->left -= widen_tangent;
        t->right += widen_tangent;
        t->down -= widen_tangent;
        t->up += widen_tangent;
    }
    const std::array planes = {frustum_planes(eye_view_proj(widened, Eye::kLeft)),
                               frustum_planes(eye_view_proj(widened, Eye::kRight))};
    const glm::dvec3 head = views.head.position;
    const glm::dvec3 forward = views.head.orientation * glm::dvec3(0.0, 0.0, -1.0);
    double farthest = views.near;
    for (const scenes::Chunk& chunk : scene.chunks) {
        if (!intersects(planes[0], chunk.bounds) && !intersects(planes[1], chunk.bounds)) continue;
        const glm::dvec3 lo(chunk.bounds.min), hi(chunk.bounds.max);
        // Depth is linear: its largest value over the box is at the corner furthest along it.
        const glm::dvec3 corner(forward.x >= 0.0 ? hi.x : lo.x, forward.y >= 0.0 ? hi.y : lo.y,
                                forward.z >= 0.0 ? hi.z : lo.z);
        farthest = std::max(farthest, glm::dot(corner - head, forward));
    }
    return std::min(farthest, views.far);
}

}  // namespace monoplane::modes
