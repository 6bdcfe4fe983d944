// SSIM and its heat maps against values derived independently in this file: a naive
// O(N * window^2) SSIM written straight from Wang et al. 2004 (2-D weights, two-pass variances),
// closed forms for flat images, and matplotlib's inferno entries copied by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "renderer/quality/colormap.h"
#include "renderer/quality/heat_map.h"
#include "renderer/quality/ssim.h"
#include "tests/unit/quality_test_image.h"

namespace monoplane::quality {
namespace {

using testing::flat_image;
using testing::TestImage;

TestImage random_image(std::uint32_t width, std::uint32_t height, std::uint32_t seed) {
    std::mt19937 rng(seed);
    TestImage image = flat_image(width, height, 0, 0, 0);
    for (std::uint32_t i = 0; i < width * height; ++i) {
        for (int c = 0; c < 3; ++c)
            image.pixels[4 * i + c] = static_cast<std::uint8_t>(rng() >> 24);
    }
    return image;
}

// Soft stripes and blobs with a little noise: neighbouring pixels are similar, as in renderings.
TestImage smooth_image(std::uint32_t width, std::uint32_t height) {
    std::mt19937 rng(7);
    TestImage image = flat_image(width, height, 0, 0, 0);
    for (std::uint32_t y = 0; y < height; ++y) {
        for (std::uint32_t x = 0; x < width; ++x) {
            const double v = 128.0 + 60.0 * std::sin(0.35 * x) * std::cos(0.22 * y) +
                             20.0 * std::sin(0.11 * (x + 2.0 * y)) +
                             static_cast<double>(rng() >> 29);
            for (int c = 0; c < 3; ++c) image.at(x, y)[c] = static_cast<std::uint8_t>(v + 10 * c);
        }
    }
    return image;
}

// b = 128 + k (a - 128) + offset per colour channel, rounded and clamped.
TestImage contrast_scaled(const TestImage& a, double k, double offset) {
    TestImage b = a;
    for (std::size_t i = 0; i < b.pixels.size(); ++i) {
        if (i % 4 == 3) continue;
        const double v = std::round(128.0 + k * (a.pixels[i] - 128.0) + offset);
        b.pixels[i] = static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0));
    }
    return b;
}

ImageView view(const TestImage& image) {
    return rgba_view(image);
}

// ----- the independent reference -------------------------------------------------------------

double reference_luma(const std::uint8_t* rgb) {
    return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2];  // Rec. 709
}

constexpr double kC1 = 6.5025;   // (0.01 * 255)^2
constexpr double kC2 = 58.5225;  // (0.03 * 255)^2

struct Reference {
    std::vector<double> map;  // NaN where the window does not fit
    double mean = 0.0;
    std::size_t count = 0;
};

// Wang et al. 2004, eqs. 13-16 and 19, one pixel at a time over a (2w + 1)^2 window of 2-D
// weights (Gaussian exp(-(dx^2 + dy^2) / (2 sigma^2)) or uniform) normalised to sum 1.
Reference naive_ssim(const TestImage& a, const TestImage& b, bool gaussian, int w,
                     double sigma = 1.5) {
    const int side = 2 * w + 1;
    std::vector<double> weights(static_cast<std::size_t>(side) * side);
    double total = 0.0;
    for (int dy = -w; dy <= w; ++dy) {
        for (int dx = -w; dx <= w; ++dx) {
            const double weight =
                gaussian ? std::exp(-(dx * dx + dy * dy) / (2.0 * sigma * sigma)) : 1.0;
            weights[(dy + w) * side + (dx + w)] = weight;
            total += weight;
        }
    }
    for (double& weight : weights) weight /= total;

    Reference ref;
    ref.map.assign(std::size_t{a.width} * a.height, std::nan(""));
    double sum = 0.0;
    const int width = static_cast<int>(a.width);
    const int height = static_cast<int>(a.height);
    for (int y = w; y < height - w; ++y) {
        for (int x = w; x < width - w; ++x) {
            double mu_a = 0.0, mu_b = 0.0;
            for (int dy = -w; dy <= w; ++dy) {
                for (int dx = -w; dx <= w; ++dx) {
                    const double weight = weights[(dy + w) * side + (dx + w)];
                    mu_a += weight * reference_luma(a.at(x + dx, y + dy));
                    mu_b += weight * reference_luma(b.at(x + dx, y + dy));
                }
            }
            double var_a = 0.0, var_b = 0.0, cov = 0.0;
            for (int dy = -w; dy <= w; ++dy) {
                for (int dx = -w; dx <= w; ++dx) {
                    const double weight = weights[(dy + w) * side + (dx + w)];
                    const double da = reference_luma(a.at(x + dx, y + dy)) - mu_a;
                    const double db = reference_luma(b.at(x + dx, y + dy)) - mu_b;
                    var_a += weight * da * da;
                    var_b += weight * db * db;
                    cov += weight * da * db;
                }
            }
            const double value = ((2.0 * mu_a * mu_b + kC1) * (2.0 * cov + kC2)) /
                                 ((mu_a * mu_a + mu_b * mu_b + kC1) * (var_a + var_b + kC2));
            ref.map[y * width + x] = value;
            sum += value;
            ++ref.count;
        }
    }
    ref.mean = sum / static_cast<double>(ref.count);
    return ref;
}

SsimResult ssim_ok(const TestImage& a, const TestImage& b, const SsimOptions& options) {
    Result<SsimResult> result = ssim(view(a), view(b), options);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().message);
    return std::move(result).value_or_throw();
}

bool in_border(const SsimResult& result, std::uint32_t x, std::uint32_t y) {
    const std::uint32_t w = result.border;
    return x < w || y < w || x >= result.width - w || y >= result.height - w;
}

const SsimOptions kWindows[] = {SsimOptions::gaussian(), SsimOptions::box(4)};

// ----- SSIM ------------------------------------------------------------------------------------

TEST(Ssim, WindowKernels) {
    const std::vector<double> gaussian = ssim_window_kernel(SsimOptions::gaussian());
    ASSERT_EQ(gaussian.size(), 11u);
    double sum = 0.0;
    for (double weight : gaussian) sum += weight;
    EXPECT_NEAR(sum, 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(gaussian[0], gaussian[10]);
    EXPECT_NEAR(gaussian[5] / gaussian[4], std::exp(1.0 / (2.0 * 1.5 * 1.5)), 1e-14);

    const std::vector<double> box = ssim_window_kernel(SsimOptions::box());
    ASSERT_EQ(box.size(), 9u);  // w = 4: 9 x 9
    for (double weight : box) EXPECT_DOUBLE_EQ(weight, 1.0 / 9.0);
}

TEST(Ssim, IdenticalImagesGiveExactlyOne) {
    const TestImage image = random_image(40, 30, 1);
    for (const SsimOptions& options : kWindows) {
        const SsimResult result = ssim_ok(image, image, options);
        const std::uint32_t w = static_cast<std::uint32_t>(options.half_size);
        EXPECT_EQ(result.border, w);
        EXPECT_EQ(result.counted_pixels, std::size_t{40 - 2 * w} * (30 - 2 * w));
        EXPECT_EQ(result.mean, 1.0);
        ASSERT_EQ(result.map.size(), 40u * 30u);
        for (std::uint32_t y = 0; y < 30; ++y) {
            for (std::uint32_t x = 0; x < 40; ++x) {
                if (in_border(result, x, y)) {
                    EXPECT_TRUE(std::isnan(result.at(x, y))) << x << "," << y;
                } else {
                    EXPECT_EQ(result.at(x, y), 1.0f) << x << "," << y;
                }
            }
        }
    }
}

TEST(Ssim, IsSymmetric) {
    const TestImage a = random_image(40, 30, 2);
    const TestImage b = contrast_scaled(random_image(40, 30, 3), 0.7, 12.0);
    for (const SsimOptions& options : kWindows) {
        const SsimResult ab = ssim_ok(a, b, options);
        const SsimResult ba = ssim_ok(b, a, options);
        EXPECT_EQ(ab.mean, ba.mean);
        for (std::size_t i = 0; i < ab.map.size(); ++i) {
            if (std::isnan(ab.map[i])) {
                EXPECT_TRUE(std::isnan(ba.map[i]));
            } else {
                EXPECT_EQ(ab.map[i], ba.map[i]) << i;
            }
        }
    }
}

// On flat images every variance and the covariance are 0, so SSIM is the luminance term alone.
TEST(Ssim, FlatImagesGiveTheLuminanceTerm) {
    struct Case {
        std::uint8_t a[3];
        std::uint8_t b[3];
    };
    const Case cases[] = {
        {{100, 100, 100}, {130, 130, 130}},  // brightness step on grey
        {{200, 50, 20}, {180, 90, 40}},      // colours: checks the Rec. 709 weights
        {{0, 0, 0}, {255, 255, 255}},        // the extreme: C1 / (255^2 + C1)
    };
    for (const Case& c : cases) {
        const TestImage a = flat_image(24, 20, c.a[0], c.a[1], c.a[2]);
        const TestImage b = flat_image(24, 20, c.b[0], c.b[1], c.b[2]);
        const double mu_a = reference_luma(c.a);
        const double mu_b = reference_luma(c.b);
        const double expected = (2.0 * mu_a * mu_b + kC1) / (mu_a * mu_a + mu_b * mu_b + kC1);
        for (const SsimOptions& options : kWindows) {
            const SsimResult result = ssim_ok(a, b, options);
            EXPECT_NEAR(result.mean, expected, 1e-12);
            for (std::uint32_t y = result.border; y < 20 - result.border; ++y) {
                for (std::uint32_t x = result.border; x < 24 - result.border; ++x) {
                    EXPECT_NEAR(result.at(x, y), expected, 1e-7);  // float map
                }
            }
        }
    }
    // Grey 100 vs 130 by hand: (2 * 13000 + 6.5025) / (10000 + 16900 + 6.5025).
    const TestImage a = flat_image(24, 20, 100, 100, 100);
    const TestImage b = flat_image(24, 20, 130, 130, 130);
    EXPECT_NEAR(ssim_ok(a, b, {}).mean, 26006.5025 / 26906.5025, 1e-12);
}

void expect_matches_reference(const TestImage& a, const TestImage& b, const SsimOptions& options,
                              const Reference& ref) {
    const SsimResult result = ssim_ok(a, b, options);
    EXPECT_EQ(result.counted_pixels, ref.count);
    EXPECT_NEAR(result.mean, ref.mean, 1e-9);
    for (std::size_t i = 0; i < ref.map.size(); ++i) {
        if (std::isnan(ref.map[i])) {
            EXPECT_TRUE(std::isnan(result.map[i])) << i;
        } else {
            EXPECT_NEAR(result.map[i], ref.map[i], 1e-6) << i;
        }
    }
}

TEST(Ssim, ContrastScaledImageMatchesNaiveReference) {
    const TestImage a = random_image(40, 30, 4);
    const TestImage b = contrast_scaled(a, 0.6, 9.0);

    const Reference gaussian = naive_ssim(a, b, true, 5);
    const Reference box = naive_ssim(a, b, false, 4);
    // Not trivially close to 1: contrast and brightness both changed.
    EXPECT_LT(gaussian.mean, 0.95);
    EXPECT_GT(gaussian.mean, 0.5);
    EXPECT_LT(box.mean, 0.95);

    expect_matches_reference(a, b, SsimOptions::gaussian(), gaussian);
    expect_matches_reference(a, b, SsimOptions::box(4), box);
}

TEST(Ssim, OtherWindowsMatchNaiveReference) {
    const TestImage a = smooth_image(40, 30);
    const TestImage b = contrast_scaled(random_image(40, 30, 5), 0.3, 40.0);
    SsimOptions wide = SsimOptions::gaussian();
    wide.half_size = 3;
    wide.gaussian_sigma = 2.0;
    expect_matches_reference(a, b, wide, naive_ssim(a, b, true, 3, 2.0));
    expect_matches_reference(a, b, SsimOptions::box(1), naive_ssim(a, b, false, 1));
    // w = 0: a single pixel, no variance, luminance term only.
    expect_matches_reference(a, b, SsimOptions::box(0), naive_ssim(a, b, false, 0));
}

TEST(Ssim, OnePixelShiftLowersSsim) {
    for (const TestImage& a : {smooth_image(40, 30), random_image(40, 30, 6)}) {
        TestImage b = a;  // b(x, y) = a(x - 1, y), first column repeated
        for (std::uint32_t y = 0; y < 30; ++y) {
            for (std::uint32_t x = 1; x < 40; ++x) {
                for (int c = 0; c < 4; ++c) b.at(x, y)[c] = a.at(x - 1, y)[c];
            }
        }
        for (const SsimOptions& options : kWindows) {
            const double mean = ssim_ok(a, b, options).mean;
            EXPECT_LT(mean, 1.0);
            EXPECT_GT(mean, -1.0);
        }
    }
    // Noise decorrelates after one pixel; the smooth image stays similar.
    const TestImage noise = random_image(40, 30, 6);
    TestImage shifted = noise;
    for (std::uint32_t y = 0; y < 30; ++y) {
        for (std::uint32_t x = 1; x < 40; ++x) {
            for (int c = 0; c < 4; ++c) shifted.at(x, y)[c] = noise.at(x - 1, y)[c];
        }
    }
    EXPECT_LT(ssim_ok(noise, shifted, {}).mean, 0.3);
}

TEST(Ssim, MaskRestrictsTheMean) {
    const TestImage a = random_image(40, 30, 8);
    TestImage b = a;  // left half (x < 20) inverted
    for (std::uint32_t y = 0; y < 30; ++y) {
        for (std::uint32_t x = 0; x < 20; ++x) {
            for (int c = 0; c < 3; ++c) b.at(x, y)[c] = 255 - a.at(x, y)[c];
        }
    }
    for (SsimOptions options : kWindows) {
        const std::uint32_t w = static_cast<std::uint32_t>(options.half_size);
        const SsimResult whole = ssim_ok(a, b, options);
        EXPECT_LT(whole.mean, 0.9);

        // Right half from column 20 + w on: those windows see only unchanged pixels.
        std::vector<std::uint8_t> right(std::size_t{40} * 30, 0);
        for (std::uint32_t y = 0; y < 30; ++y) {
            for (std::uint32_t x = 20 + w; x < 40; ++x) right[y * 40 + x] = 1;
        }
        options.mask = right;
        const SsimResult masked = ssim_ok(a, b, options);
        EXPECT_EQ(masked.mean, 1.0);
        EXPECT_EQ(masked.counted_pixels, std::size_t{40 - w - (20 + w)} * (30 - 2 * w));
        // The map does not depend on the mask.
        for (std::size_t i = 0; i < whole.map.size(); ++i) {
            if (!std::isnan(whole.map[i])) {
                EXPECT_EQ(masked.map[i], whole.map[i]);
            }
        }

        // The mask selects values, not window contents: the right half from column 20 on
        // includes windows reaching into the inverted half.
        for (std::uint32_t y = 0; y < 30; ++y) right[y * 40 + 20] = 1;
        EXPECT_LT(ssim_ok(a, b, options).mean, 1.0);

        // Only border pixels selected: nothing to average.
        std::vector<std::uint8_t> corner(std::size_t{40} * 30, 0);
        corner[0] = 1;
        options.mask = corner;
        const SsimResult empty = ssim_ok(a, b, options);
        EXPECT_EQ(empty.counted_pixels, 0u);
        EXPECT_TRUE(std::isnan(empty.mean));
    }
}

TEST(Ssim, GreyAndRgbaViewsAgree) {
    const TestImage rgba = smooth_image(30, 24);
    std::vector<std::uint8_t> grey(std::size_t{30} * 24);
    TestImage grey_rgba = rgba;
    for (std::size_t i = 0; i < grey.size(); ++i) {
        grey[i] = rgba.pixels[4 * i + 1];
        for (int c = 0; c < 3; ++c) grey_rgba.pixels[4 * i + c] = grey[i];
    }
    const ImageView grey_view{30, 24, 1, grey};
    const Result<SsimResult> result = ssim(grey_view, view(grey_rgba));
    ASSERT_TRUE(result.ok());
    EXPECT_NEAR(result->mean, 1.0, 1e-12);  // luma of (v, v, v) is v up to rounding
}

TEST(Ssim, RefusesMismatchedOrInvalidInput) {
    const TestImage a = random_image(40, 30, 9);
    const TestImage wider = random_image(41, 30, 9);
    const Result<SsimResult> sizes = ssim(view(a), view(wider));
    ASSERT_FALSE(sizes.ok());
    EXPECT_NE(sizes.error().message.find("40x30"), std::string::npos);
    EXPECT_NE(sizes.error().message.find("41x30"), std::string::npos);

    ImageView short_buffer = view(a);
    short_buffer.pixels = short_buffer.pixels.first(100);
    EXPECT_FALSE(ssim(short_buffer, view(a)).ok());
    ImageView two_channels = view(a);
    two_channels.channels = 2;
    EXPECT_FALSE(ssim(two_channels, two_channels).ok());

    const TestImage tiny = random_image(10, 30, 9);  // narrower than the 11 x 11 Gaussian
    const Result<SsimResult> too_small = ssim(view(tiny), view(tiny));
    ASSERT_FALSE(too_small.ok());
    EXPECT_NE(too_small.error().message.find("11x11"), std::string::npos);
    EXPECT_TRUE(ssim(view(tiny), view(tiny), SsimOptions::box(4)).ok());

    SsimOptions bad_mask;
    const std::vector<std::uint8_t> mask(std::size_t{40} * 29, 1);
    bad_mask.mask = mask;
    EXPECT_FALSE(ssim(view(a), view(a), bad_mask).ok());

    EXPECT_FALSE(ssim(view(a), view(a), SsimOptions::box(-1)).ok());
    SsimOptions no_sigma;
    no_sigma.gaussian_sigma = 0.0;
    EXPECT_FALSE(ssim(view(a), view(a), no_sigma).ok());
}

// ----- heat maps -------------------------------------------------------------------------------

// matplotlib's inferno entries 0, 128 and 255, times 255, rounded.
constexpr std::uint8_t kZeroColour[4] = {0, 0, 4, 255};        // (0.001462, 0.000466, 0.013866)
constexpr std::uint8_t kMidColour[4] = {188, 55, 84, 255};     // (0.735683, 0.215906, 0.330245)
constexpr std::uint8_t kFullColour[4] = {252, 255, 164, 255};  // (0.988362, 0.998364, 0.644924)

void expect_pixel(const std::vector<std::uint8_t>& rgba, std::size_t i,
                  const std::uint8_t (&expected)[4]) {
    for (int c = 0; c < 4; ++c) EXPECT_EQ(rgba[4 * i + c], expected[c]) << "pixel " << i;
}

TEST(HeatMap, InfernoEndpoints) {
    EXPECT_EQ(inferno(0.0f), (Rgb8{0, 0, 4}));
    EXPECT_EQ(inferno(0.5f), (Rgb8{188, 55, 84}));
    EXPECT_EQ(inferno(1.0f), (Rgb8{252, 255, 164}));
    EXPECT_EQ(inferno(-3.0f), inferno(0.0f));
    EXPECT_EQ(inferno(7.0f), inferno(1.0f));
    EXPECT_EQ(inferno(std::nanf("")), inferno(0.0f));
    // Lightness rises: the sum of channels grows along the map.
    int previous = -1;
    for (int i = 0; i <= 64; ++i) {
        const Rgb8 c = inferno(static_cast<float>(i) / 64.0f);
        const int lightness = 2 * c[0] + 5 * c[1] + c[2];
        EXPECT_GT(lightness, previous) << i;
        previous = lightness;
    }
}

TEST(HeatMap, IdenticalImagesAreTheZeroColour) {
    const TestImage image = smooth_image(40, 30);
    for (const SsimOptions& options : kWindows) {
        const SsimResult result = ssim_ok(image, image, options);
        const std::vector<std::uint8_t> heat = ssim_heat_map_rgba(result);
        ASSERT_EQ(heat.size(), 40u * 30u * 4u);
        constexpr std::uint8_t kTransparent[4] = {0, 0, 0, 0};
        for (std::uint32_t y = 0; y < 30; ++y) {
            for (std::uint32_t x = 0; x < 40; ++x) {
                expect_pixel(heat, y * 40 + x,
                             in_border(result, x, y) ? kTransparent : kZeroColour);
            }
        }
    }
}

TEST(HeatMap, ScaleMapsOneMinusSsim) {
    SsimResult result;
    result.width = 3;
    result.height = 2;
    result.map = {1.0f, 0.95f, 0.9f, 0.0f, -1.0f, std::nanf("")};
    const std::vector<std::uint8_t> heat = ssim_heat_map_rgba(result);  // scale 10
    expect_pixel(heat, 0, kZeroColour);
    expect_pixel(heat, 1, kMidColour);   // (1 - 0.95) * 10 = 0.5
    expect_pixel(heat, 2, kFullColour);  // 1, saturated from here on
    expect_pixel(heat, 3, kFullColour);
    expect_pixel(heat, 4, kFullColour);
    constexpr std::uint8_t kTransparent[4] = {0, 0, 0, 0};
    expect_pixel(heat, 5, kTransparent);

    const std::vector<std::uint8_t> gentle = ssim_heat_map_rgba(result, 1.0f);
    expect_pixel(gentle, 3, kFullColour);  // SSIM 0 -> 1
    result.map = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f};
    expect_pixel(ssim_heat_map_rgba(result, 1.0f), 0, kMidColour);
}

TEST(HeatMap, BlendOverlaysOnTheRendering) {
    const TestImage base = smooth_image(40, 30);
    const TestImage other = contrast_scaled(base, 0.5, 0.0);
    const SsimResult result = ssim_ok(base, other, SsimOptions::box(4));
    const std::vector<std::uint8_t> heat = ssim_heat_map_rgba(result);

    const Result<std::vector<std::uint8_t>> none = blend_heat_map(view(base), heat, 0.0f);
    ASSERT_TRUE(none.ok());
    const Result<std::vector<std::uint8_t>> full = blend_heat_map(view(base), heat, 1.0f);
    ASSERT_TRUE(full.ok());
    const Result<std::vector<std::uint8_t>> half = blend_heat_map(view(base), heat, 0.5f);
    ASSERT_TRUE(half.ok());
    for (std::uint32_t y = 0; y < 30; ++y) {
        for (std::uint32_t x = 0; x < 40; ++x) {
            const std::size_t i = y * 40 + x;
            const bool border = in_border(result, x, y);
            for (int c = 0; c < 3; ++c) {
                const int under = base.at(x, y)[c];
                const int over = heat[4 * i + c];
                EXPECT_EQ((*none)[4 * i + c], under);
                EXPECT_EQ((*full)[4 * i + c], border ? under : over);
                // (under + over) / 2, halves rounded away from zero.
                EXPECT_EQ((*half)[4 * i + c], border ? under : (under + over + 1) / 2);
            }
            EXPECT_EQ((*full)[4 * i + 3], 255);
        }
    }

    EXPECT_FALSE(blend_heat_map(view(base), std::span(heat).first(heat.size() - 4), 0.5f).ok());
    EXPECT_FALSE(blend_heat_map(view(base), heat, 1.5f).ok());
    EXPECT_FALSE(blend_heat_map(view(base), heat, std::nanf("")).ok());
}

}  // namespace
}  // namespace monoplane::quality
