#include "renderer/modes/frustum_culling.h"

#include <algorithm>
#include <iterator>
#include <numeric>

#include <glm/common.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>

namespace monoplane::modes {

std::array<glm::dvec4, 6> frustum_planes(const glm::dmat4& view_proj) {
    const glm::dmat4 t = glm::transpose(view_proj);  // t[i] is row i of view_proj
    return {t[3] + t[0], t[3] - t[0], t[3] + t[1], t[3] - t[1], t[2], t[3] - t[2]};
}

bool intersects(const std::array<glm::dvec4, 6>& planes, const scenes::Aabb& box) {
    for (const glm::dvec4& p : planes) {
        // The box corner furthest along the plane's normal.
        const glm::dvec3 corner(p.x >= 0 ? box.max.x : box.min.x, p.y >= 0 ? box.max.y : box.min.y,
                                p.z >= 0 ? box.max.z : box.min.z);
        if (p.x * corner.x + p.y * corner.y + p.z * corner.z + p.w < 0.0) return false;
    }
    return true;
}

std::vector<std::uint32_t> visible_chunks(const scenes::Scene& scene, const glm::dmat4& view_proj) {
    const auto planes = frustum_planes(view_proj);
    std::vector<std::uint32_t> visible;
    visible.reserve(scene.chunks.size());
    for (std::uint32_t i = 0; i < scene.chunks.size(); ++i) {
        if (intersects(planes, scene.chunks[i].bounds)) visible.push_back(i);
    }
    return visible;
}

std::vector<std::uint32_t> front_to_back_order(const scenes::Scene& scene,
                                               const glm::dvec3& viewer) {
    std::vector<double> distance(scene.chunks.size());
    for (std::size_t i = 0; i < scene.chunks.size(); ++i) {
        const scenes::Aabb& box = scene.chunks[i].bounds;
        const glm::dvec3 nearest = glm::clamp(viewer, glm::dvec3(box.min), glm::dvec3(box.max));
        distance[i] = glm::length(nearest - viewer);
    }
    std::vector<std::uint32_t> order(scene.chunks.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return distance[a] < distance[b]; });
    return order;
}

std::vector<std::uint32_t> draw_order(const scenes::Scene& scene, const glm::dvec3& viewer) {
    std::vector<std::uint32_t> order = front_to_back_order(scene, viewer);
    std::vector<double> centre_distance(scene.chunks.size());
    for (std::size_t i = 0; i < scene.chunks.size(); ++i) {
        const scenes::Aabb& box = scene.chunks[i].bounds;
        const glm::dvec3 centre = 0.5 * (glm::dvec3(box.min) + glm::dvec3(box.max));
        centre_distance[i] = glm::length(centre - viewer);
    }
    const auto blended = [&](std::uint32_t c) {
        return scene.chunks[c].alpha_mode == scenes::AlphaMode::kBlend;
    };
    // The blended chunks keep their places among the others (the lists separate the classes);
    // only their order among themselves changes.
    std::vector<std::uint32_t> back_to_front;
    std::copy_if(order.begin(), order.end(), std::back_inserter(back_to_front), blended);
    std::stable_sort(back_to_front.begin(), back_to_front.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                         if (centre_distance[a] != centre_distance[b])
                             return centre_distance[a] > centre_distance[b];
                         return a < b;
                     });
    auto next = back_to_front.begin();
    for (std::uint32_t& chunk : order) {
        if (blended(chunk)) chunk = *next++;
    }
    return order;
}

}  // namespace monoplane::modes
