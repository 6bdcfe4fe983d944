#include "scenes/gltf/texture_bake.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace monoplane::scenes::gltf {
namespace {

const std::array<float, 256>& srgb_table() {
    static const std::array<float, 256> table = [] {
        std::array<float, 256> values{};
        for (std::size_t i = 0; i < values.size(); ++i) {
            const double c = static_cast<double>(i) / 255.0;
            values[i] =
                static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
        }
        return values;
    }();
    return table;
}

// Texel index for integer coordinate i on an axis of n texels.
std::int64_t wrap(std::int64_t i, std::int64_t n, TextureWrap mode) {
    switch (mode) {
        case TextureWrap::ClampToEdge:
            return std::clamp<std::int64_t>(i, 0, n - 1);
        case TextureWrap::MirroredRepeat: {
            const std::int64_t period = 2 * n;
            std::int64_t m = i % period;
            if (m < 0) m += period;
            return m < n ? m : period - 1 - m;
        }
        case TextureWrap::Repeat:
            break;
    }
    std::int64_t m = i % n;
    return m < 0 ? m + n : m;
}

}  // namespace

float srgb_to_linear(std::uint8_t encoded) {
    return srgb_table()[encoded];
}

TextureBake::TextureBake(const SceneTexture& texture)
    : wrap_u_(texture.wrap_u), wrap_v_(texture.wrap_v) {
    if (texture.width == 0 || texture.height == 0 ||
        texture.rgba8_srgb.size() < std::size_t{4} * texture.width * texture.height) {
        texels_.assign(1, glm::vec4(1.0f));  // nothing to sample: leave colours untouched
        return;
    }
    width_ = std::min(texture.width, kSide);
    height_ = std::min(texture.height, kSide);
    texels_.assign(std::size_t{width_} * height_, glm::vec4(0.0f));
    std::vector<float> counts(texels_.size(), 0.0f);
    // Each source texel adds to the small texel whose box contains it.
    for (std::uint32_t y = 0; y < texture.height; ++y) {
        const std::size_t ty = std::size_t{y} * height_ / texture.height;
        for (std::uint32_t x = 0; x < texture.width; ++x) {
            const std::size_t tx = std::size_t{x} * width_ / texture.width;
            const std::uint8_t* texel =
                &texture.rgba8_srgb[(std::size_t{y} * texture.width + x) * 4];
            glm::vec4& sum = texels_[ty * width_ + tx];
            sum += glm::vec4(srgb_to_linear(texel[0]), srgb_to_linear(texel[1]),
                             srgb_to_linear(texel[2]), static_cast<float>(texel[3]) / 255.0f);
            counts[ty * width_ + tx] += 1.0f;
        }
    }
    for (std::size_t i = 0; i < texels_.size(); ++i) texels_[i] /= counts[i];
}

glm::vec4 TextureBake::sample(glm::vec2 uv) const {
    // Texel centres sit at (i + 0.5) / n, as in Vulkan's and OpenGL's sampling.
    const double x = static_cast<double>(uv.x) * width_ - 0.5;
    const double y = static_cast<double>(uv.y) * height_ - 0.5;
    // Coordinates far outside [0, 1] are clamped before the integer conversion, which would
    // overflow; wrap() folds the rest. Non-finite uv never gets here (accessors refuse it).
    const double fx = std::floor(x);
    const double fy = std::floor(y);
    const float ax = static_cast<float>(x - fx);
    const float ay = static_cast<float>(y - fy);
    const auto clamp_big = [](double v) { return std::clamp(v, -1e12, 1e12); };
    const auto ix = static_cast<std::int64_t>(clamp_big(fx));
    const auto iy = static_cast<std::int64_t>(clamp_big(fy));
    const auto w = static_cast<std::int64_t>(width_);
    const auto h = static_cast<std::int64_t>(height_);
    const auto at = [&](std::int64_t i, std::int64_t j) {
        return texels_[static_cast<std::size_t>(wrap(j, h, wrap_v_) * w + wrap(i, w, wrap_u_))];
    };
    const glm::vec4 top = at(ix, iy) * (1.0f - ax) + at(ix + 1, iy) * ax;
    const glm::vec4 bottom = at(ix, iy + 1) * (1.0f - ax) + at(ix + 1, iy + 1) * ax;
    return top * (1.0f - ay) + bottom * ay;
}

}  // namespace monoplane::scenes::gltf
