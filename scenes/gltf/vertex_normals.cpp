#include "scenes/gltf/vertex_normals.h"

#include <glm/geometric.hpp>

#include "common/programming_error.h"

namespace monoplane::scenes::gltf {
namespace {

constexpr glm::vec3 kUp{0.0f, 1.0f, 0.0f};

// Below this fraction of the summed face weights, a vertex's sum counts as cancelled.
constexpr float kCancelled = 1e-3f;

}  // namespace

glm::vec3 face_normal(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
    const glm::vec3 cross = glm::cross(b - a, c - a);
    const float length = glm::length(cross);
    return length > 0.0f ? cross / length : kUp;
}

std::vector<glm::vec3> smooth_normals(std::span<const glm::vec3> positions,
                                      std::span<const std::uint32_t> triangles) {
    MONOPLANE_EXPECTS(triangles.size() % 3 == 0);
    std::vector<glm::vec3> sum(positions.size(), glm::vec3(0.0f));
    std::vector<float> weight(positions.size(), 0.0f);                  // summed |cross|
    std::vector<glm::vec3> largest(positions.size(), glm::vec3(0.0f));  // largest face's cross
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
        const std::uint32_t corner[3] = {triangles[t], triangles[t + 1], triangles[t + 2]};
        const glm::vec3 cross = glm::cross(positions[corner[1]] - positions[corner[0]],
                                           positions[corner[2]] - positions[corner[0]]);
        const float area = glm::length(cross);
        for (const std::uint32_t v : corner) {
            sum[v] += cross;
            weight[v] += area;
            if (area > glm::length(largest[v])) largest[v] = cross;
        }
    }
    std::vector<glm::vec3> normals(positions.size(), kUp);
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const float length = glm::length(sum[v]);
        if (length > kCancelled * weight[v] && length > 0.0f) {
            normals[v] = sum[v] / length;
        } else if (const float big = glm::length(largest[v]); big > 0.0f) {
            normals[v] = largest[v] / big;
        }
    }
    return normals;
}

}  // namespace monoplane::scenes::gltf
