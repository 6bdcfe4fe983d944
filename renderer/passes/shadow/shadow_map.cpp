#include "renderer/passes/shadow/shadow_map.h"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

namespace monoplane::passes {

glm::dmat4 fit_light_view_proj(const glm::dvec3& towards_sun, const scenes::Aabb& region) {
    // Light frame: forward points away from the sun; pick any right/up perpendicular to it.
    const glm::dvec3 forward = -glm::normalize(towards_sun);
    const glm::dvec3 helper =
        std::abs(forward.y) > 0.99 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(forward, helper));
    const glm::dvec3 up = glm::cross(right, forward);
    glm::dvec3 lo(std::numeric_limits<double>::max());
    glm::dvec3 hi(std::numeric_limits<double>::lowest());
    for (int corner = 0; corner < 8; ++corner) {
        const glm::dvec3 p((corner & 1) ? region.max.x : region.min.x,
                           (corner & 2) ? region.max.y : region.min.y,
                           (corner & 4) ? region.max.z : region.min.z);
        const glm::dvec3 q(glm::dot(p, right), glm::dot(p, up), glm::dot(p, forward));
        lo = glm::min(lo, q);
        hi = glm::max(hi, q);
    }
    const glm::dvec3 extent = glm::max(hi - lo, glm::dvec3(1e-3));
    // Rows map (right, up, forward) coordinates to [-1, 1] x [-1, 1] x [0, 1].
    glm::dmat4 m(0.0);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = 2.0 * right[c] / extent.x;
        m[c][1] = 2.0 * up[c] / extent.y;
        m[c][2] = forward[c] / extent.z;
    }
    m[3][0] = -2.0 * lo.x / extent.x - 1.0;
    m[3][1] = -2.0 * lo.y / extent.y - 1.0;
    m[3][2] = -lo.z / extent.z;
    m[3][3] = 1.0;
    return m;
}

ShadowMap::ShadowMap(const vk_core::Context& ctx, const ShadowParams& params)
    : params_(params),
      map_(ctx, vk_core::ImageDesc{{params.resolution, params.resolution},
                                   kFormat,
                                   vk::ImageUsageFlagBits::eDepthStencilAttachment |
                                       vk::ImageUsageFlagBits::eSampled}) {
    // Hardware comparison: each texture() tap is itself a 2x2 bilinear PCF.
    sampler_ = vk::raii::Sampler(
        ctx.device(),
        vk::SamplerCreateInfo(
            {}, vk::Filter::eLinear, vk::Filter::eLinear, vk::SamplerMipmapMode::eNearest,
            vk::SamplerAddressMode::eClampToEdge, vk::SamplerAddressMode::eClampToEdge,
            vk::SamplerAddressMode::eClampToEdge, 0.0f, VK_FALSE, 1.0f, VK_TRUE,
            vk::CompareOp::eLessOrEqual, 0.0f, 0.0f, vk::BorderColor::eFloatOpaqueWhite));
}

}  // namespace monoplane::passes
