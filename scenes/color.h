// Colour helpers for the generators: albedos are picked by eye as sRGB and stored linear
// (scene.h: Vertex::albedo_rgba8 is linear).
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "scenes/scene.h"

namespace monoplane::scenes {

inline float srgb_to_linear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

// 0xRRGGBB as written in a colour picker, to linear RGB.
inline glm::vec3 from_srgb(std::uint32_t hex) {
    return {srgb_to_linear(static_cast<float>((hex >> 16) & 0xffu) / 255.0f),
            srgb_to_linear(static_cast<float>((hex >> 8) & 0xffu) / 255.0f),
            srgb_to_linear(static_cast<float>(hex & 0xffu) / 255.0f)};
}

// Hue in [0, 1), saturation and value in [0, 1]; the result is sRGB, convert with srgb_to_linear.
inline glm::vec3 hsv_to_srgb(float hue, float saturation, float value) {
    const glm::vec3 k = glm::abs(
        glm::fract(glm::vec3(hue) + glm::vec3(1.0f, 2.0f / 3.0f, 1.0f / 3.0f)) * 6.0f - 3.0f);
    return value * glm::mix(glm::vec3(1.0f), glm::clamp(k - 1.0f, 0.0f, 1.0f), saturation);
}

inline glm::vec3 srgb_to_linear(glm::vec3 c) {
    return {srgb_to_linear(c.x), srgb_to_linear(c.y), srgb_to_linear(c.z)};
}

inline std::uint32_t pack_albedo(glm::vec3 linear) {
    return pack_rgba8(linear.x, linear.y, linear.z);
}

}  // namespace monoplane::scenes
