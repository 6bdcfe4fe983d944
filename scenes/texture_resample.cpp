#include "scenes/texture_resample.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "common/programming_error.h"

namespace monoplane::scenes {
namespace {

const std::array<float, 256>& srgb_decode_table() {
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

std::uint8_t encode_srgb_value(float linear) {
    const double c = std::clamp(static_cast<double>(linear), 0.0, 1.0);
    const double encoded = c <= 0.0031308 ? c * 12.92 : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return static_cast<std::uint8_t>(std::lround(encoded * 255.0));
}

std::uint8_t encode_unorm(float value) {
    return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

// Texel index for integer coordinate i on an axis of n texels, as the sampler wraps it.
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
    const std::int64_t m = i % n;
    return m < 0 ? m + n : m;
}

// One output texel of an axis: source texels and their weights (summing to 1).
struct Tap {
    std::uint32_t source = 0;
    float weight = 0.0f;
};
using AxisTaps = std::vector<std::vector<Tap>>;

// Shrinking: destination texel d covers source texels [d r, (d + 1) r), r = source / destination.
AxisTaps box_taps(std::uint32_t source, std::uint32_t destination) {
    AxisTaps taps(destination);
    const double ratio = static_cast<double>(source) / destination;
    for (std::uint32_t d = 0; d < destination; ++d) {
        const double begin = d * ratio;
        const double end = (d + 1) * ratio;
        for (auto s = static_cast<std::uint32_t>(std::floor(begin)); s < source && s < end; ++s) {
            const double covered = std::min<double>(s + 1, end) - std::max<double>(s, begin);
            if (covered > 1e-9) taps[d].push_back({s, static_cast<float>(covered / ratio)});
        }
    }
    return taps;
}

// Growing: destination texel d's centre (d + 0.5) / destination, between the two nearest
// source texel centres.
AxisTaps linear_taps(std::uint32_t source, std::uint32_t destination, TextureWrap mode) {
    AxisTaps taps(destination);
    for (std::uint32_t d = 0; d < destination; ++d) {
        const double x = (d + 0.5) * source / destination - 0.5;
        const double left = std::floor(x);
        const auto t = static_cast<float>(x - left);
        const auto i = static_cast<std::int64_t>(left);
        taps[d].push_back({static_cast<std::uint32_t>(wrap(i, source, mode)), 1.0f - t});
        taps[d].push_back({static_cast<std::uint32_t>(wrap(i + 1, source, mode)), t});
    }
    return taps;
}

AxisTaps axis_taps(std::uint32_t source, std::uint32_t destination, TextureWrap mode) {
    if (destination < source) return box_taps(source, destination);
    if (destination > source) return linear_taps(source, destination, mode);
    AxisTaps identity(destination);
    for (std::uint32_t d = 0; d < destination; ++d) identity[d].push_back({d, 1.0f});
    return identity;
}

}  // namespace

LinearImage decode_srgb(const SceneTexture& texture) {
    MONOPLANE_EXPECTS(texture.rgba8_srgb.size() == std::size_t{texture.width} * texture.height * 4);
    const auto& table = srgb_decode_table();
    LinearImage image{texture.width, texture.height, std::vector<float>(texture.rgba8_srgb.size())};
    for (std::size_t i = 0; i < image.rgba.size(); ++i) {
        const std::uint8_t value = texture.rgba8_srgb[i];
        image.rgba[i] = i % 4 == 3 ? static_cast<float>(value) / 255.0f : table[value];
    }
    return image;
}

std::vector<std::uint8_t> encode_srgb(const LinearImage& image) {
    std::vector<std::uint8_t> bytes(image.rgba.size());
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        bytes[i] = i % 4 == 3 ? encode_unorm(image.rgba[i]) : encode_srgb_value(image.rgba[i]);
    }
    return bytes;
}

LinearImage resample(const LinearImage& image, std::uint32_t width, std::uint32_t height,
                     TextureWrap wrap_u, TextureWrap wrap_v) {
    MONOPLANE_EXPECTS(width > 0 && height > 0);
    MONOPLANE_EXPECTS(image.rgba.size() == std::size_t{image.width} * image.height * 4);
    const AxisTaps taps_x = axis_taps(image.width, width, wrap_u);
    const AxisTaps taps_y = axis_taps(image.height, height, wrap_v);
    LinearImage out{width, height, std::vector<float>(std::size_t{width} * height * 4, 0.0f)};
    for (std::uint32_t y = 0; y < height; ++y) {
        for (std::uint32_t x = 0; x < width; ++x) {
            float* sum = &out.rgba[(std::size_t{y} * width + x) * 4];
            for (const Tap& ty : taps_y[y]) {
                for (const Tap& tx : taps_x[x]) {
                    const float* texel =
                        &image.rgba[(std::size_t{ty.source} * image.width + tx.source) * 4];
                    const float weight = ty.weight * tx.weight;
                    for (int c = 0; c < 4; ++c) sum[c] += weight * texel[c];
                }
            }
        }
    }
    return out;
}

}  // namespace monoplane::scenes
