#include "scenes/scene.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace monoplane::scenes {
namespace {

std::uint32_t to_unorm8(float value) {
    const float clamped = std::clamp(value, 0.0f, 1.0f);
    return static_cast<std::uint32_t>(std::lround(clamped * 255.0f));
}

}  // namespace

std::uint32_t pack_material(const Material& material) {
    return to_unorm8(material.roughness) | (to_unorm8(material.specular) << 8) |
           (static_cast<std::uint32_t>(material.pattern) << 16);
}

Material unpack_material(std::uint32_t packed) {
    Material material;
    material.roughness = static_cast<float>(packed & 0xffu) / 255.0f;
    material.specular = static_cast<float>((packed >> 8) & 0xffu) / 255.0f;
    material.pattern = static_cast<std::uint8_t>((packed >> 16) & 0xffu);
    return material;
}

std::uint32_t pack_rgba8(float r, float g, float b, float a) {
    return to_unorm8(r) | (to_unorm8(g) << 8) | (to_unorm8(b) << 16) | (to_unorm8(a) << 24);
}

Viewpoint make_viewpoint(std::string name, const glm::dvec3& position, double yaw_degrees,
                         double pitch_degrees) {
    constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;
    Viewpoint viewpoint;
    viewpoint.name = std::move(name);
    viewpoint.head.position = position;
    viewpoint.head.orientation = rig::orientation_from_yaw_pitch(yaw_degrees * kRadiansPerDegree,
                                                                 pitch_degrees * kRadiansPerDegree);
    return viewpoint;
}

const Viewpoint* Scene::find_viewpoint(const std::string& name) const {
    const auto it = std::find_if(viewpoints.begin(), viewpoints.end(),
                                 [&](const Viewpoint& v) { return v.name == name; });
    return it == viewpoints.end() ? nullptr : &*it;
}

}  // namespace monoplane::scenes
