// Drift against displacements known by construction: a smooth random texture and copies of it
// moved by whole pixels (byte copies) or by fractions of a pixel (bilinear resampling), so the
// expected answer follows from how the test image was made, not from the method under test.
// Sign convention (drift.h): test(x, y) = reference(x - sx, y - sy) moves the content by
// (+sx, +sy), and that is the displacement reported.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "renderer/quality/drift.h"
#include "tests/unit/quality_test_image.h"

namespace monoplane::quality {
namespace {

using testing::flat_image;
using testing::TestImage;

constexpr std::uint32_t kWidth = 256;
constexpr std::uint32_t kHeight = 192;

// With the default options (patch radius 7, search radius 8, so centres start at 15, grid step
// 24): centres x = 15, 39, ..., 231 (cx + 15 < 256: 10 of them) and y = 15, 39, ..., 159
// (cy + 15 < 192: 7), 70 patches in all.
constexpr std::size_t kDefaultGridPatches = 10 * 7;

// White noise blurred with a Gaussian of sigma 2 px, scaled to mean 128 and standard deviation
// about 40: textured everywhere (every patch passes the 4.0 std-dev test), smooth enough that
// bilinear resampling is close to a true sub-pixel shift, and not periodic, so a wrong
// displacement does not correlate well.
TestImage smooth_texture(std::uint32_t width, std::uint32_t height, std::uint32_t seed) {
    // Uniform noise straight from mt19937, whose output the standard fixes (the distributions'
    // is not), so the images, and the values measured on them, are the same on every platform.
    std::mt19937 rng(seed);
    const std::size_t count = std::size_t{width} * height;
    std::vector<double> field(count);
    for (double& value : field) value = static_cast<double>(rng()) / 4294967296.0 - 0.5;

    const int radius = 6;
    const double sigma = 2.0;
    std::vector<double> kernel(2 * radius + 1);
    double kernel_sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        kernel[i + radius] = std::exp(-(i * i) / (2.0 * sigma * sigma));
        kernel_sum += kernel[i + radius];
    }
    for (double& weight : kernel) weight /= kernel_sum;
    const auto clamp_index = [](int i, std::uint32_t size) {
        return static_cast<std::size_t>(std::clamp(i, 0, static_cast<int>(size) - 1));
    };
    std::vector<double> rows(count);
    for (std::uint32_t y = 0; y < height; ++y) {
        for (std::uint32_t x = 0; x < width; ++x) {
            double sum = 0.0;
            for (int i = -radius; i <= radius; ++i) {
                sum += kernel[i + radius] *
                       field[std::size_t{y} * width + clamp_index(static_cast<int>(x) + i, width)];
            }
            rows[std::size_t{y} * width + x] = sum;
        }
    }
    std::vector<double> blurred(count);
    for (std::uint32_t y = 0; y < height; ++y) {
        for (std::uint32_t x = 0; x < width; ++x) {
            double sum = 0.0;
            for (int i = -radius; i <= radius; ++i) {
                sum += kernel[i + radius] *
                       rows[clamp_index(static_cast<int>(y) + i, height) * width + x];
            }
            blurred[std::size_t{y} * width + x] = sum;
        }
    }
    double mean = 0.0;
    for (double value : blurred) mean += value;
    mean /= static_cast<double>(count);
    double variance = 0.0;
    for (double value : blurred) variance += (value - mean) * (value - mean);
    const double scale = 40.0 / std::sqrt(variance / static_cast<double>(count));

    TestImage image = flat_image(width, height, 0);
    for (std::uint32_t y = 0; y < height; ++y) {
        for (std::uint32_t x = 0; x < width; ++x) {
            const double v = 128.0 + scale * (blurred[std::size_t{y} * width + x] - mean);
            // A slight tint, so the colour channels differ and luma is a real weighted sum.
            const double rgb[3] = {v + 12.0, v, v - 12.0};
            for (int c = 0; c < 3; ++c) {
                image.at(x, y)[c] =
                    static_cast<std::uint8_t>(std::clamp(std::round(rgb[c]), 0.0, 255.0));
            }
        }
    }
    return image;
}

// test(x, y) = source(x - shift_x, y - shift_y) per channel, bilinear, coordinates clamped to the
// image (the few clamped pixels at the edges are never inside a matched patch). The content moves
// by (+shift_x, +shift_y).
TestImage shifted(const TestImage& source, double shift_x, double shift_y) {
    TestImage image = flat_image(source.width, source.height, 0);
    const auto max_x = static_cast<double>(source.width - 1);
    const auto max_y = static_cast<double>(source.height - 1);
    for (std::uint32_t y = 0; y < source.height; ++y) {
        for (std::uint32_t x = 0; x < source.width; ++x) {
            const double sx = std::clamp(x - shift_x, 0.0, max_x);
            const double sy = std::clamp(y - shift_y, 0.0, max_y);
            const auto x0 = static_cast<std::uint32_t>(std::floor(sx));
            const auto y0 = static_cast<std::uint32_t>(std::floor(sy));
            const std::uint32_t x1 = std::min(x0 + 1, source.width - 1);
            const std::uint32_t y1 = std::min(y0 + 1, source.height - 1);
            const double fx = sx - x0;
            const double fy = sy - y0;
            for (int c = 0; c < 3; ++c) {
                const double top = (1 - fx) * source.at(x0, y0)[c] + fx * source.at(x1, y0)[c];
                const double bottom = (1 - fx) * source.at(x0, y1)[c] + fx * source.at(x1, y1)[c];
                const double v = (1 - fy) * top + fy * bottom;
                image.at(x, y)[c] = static_cast<std::uint8_t>(std::round(v));
            }
        }
    }
    return image;
}

// test(x, y) = source(x - shift_x, y - shift_y) as a byte copy; pixels whose source lies outside
// the image are mid-grey (never inside a matched patch).
TestImage shifted_whole_pixels(const TestImage& source, int shift_x, int shift_y) {
    TestImage image = flat_image(source.width, source.height, 128);
    for (std::uint32_t y = 0; y < source.height; ++y) {
        for (std::uint32_t x = 0; x < source.width; ++x) {
            const int sx = static_cast<int>(x) - shift_x;
            const int sy = static_cast<int>(y) - shift_y;
            if (sx < 0 || sy < 0 || sx >= static_cast<int>(source.width) ||
                sy >= static_cast<int>(source.height))
                continue;
            std::copy_n(source.at(sx, sy), 4, image.at(x, y));
        }
    }
    return image;
}

ImageView view(const TestImage& image) {
    return rgba_view(image);
}

DriftMeasurement measured(const ImageView& reference, const ImageView& test,
                          std::span<const std::uint8_t> mask = {},
                          const DriftOptions& options = {}) {
    Result<DriftMeasurement> result = measure_drift(reference, test, mask, options);
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().message);
    return std::move(result).value_or_throw();
}

void expect_all_zero(const DriftMeasurement& drift) {
    EXPECT_EQ(drift.patches, 0u);
    EXPECT_EQ(drift.median_px, 0.0);
    EXPECT_EQ(drift.p95_px, 0.0);
    EXPECT_EQ(drift.max_px, 0.0);
    EXPECT_EQ(drift.mean_dx_px, 0.0);
    EXPECT_EQ(drift.mean_dy_px, 0.0);
}

// ----- known displacements --------------------------------------------------------------------

TEST(QualityDrift, IdenticalImagesHaveNoDrift) {
    const TestImage image = smooth_texture(kWidth, kHeight, 1);
    const DriftMeasurement drift = measured(view(image), view(image));
    EXPECT_EQ(drift.patches, kDefaultGridPatches);
    EXPECT_EQ(drift.rejected_patches, 0u);
    EXPECT_NEAR(drift.median_px, 0.0, 1e-6);
    EXPECT_NEAR(drift.p95_px, 0.0, 1e-6);
    EXPECT_NEAR(drift.max_px, 0.0, 1e-6);
    EXPECT_NEAR(drift.mean_dx_px, 0.0, 1e-6);
    EXPECT_NEAR(drift.mean_dy_px, 0.0, 1e-6);
}

TEST(QualityDrift, WholePixelShiftIsMeasuredExactly) {
    // Every test patch is a byte copy of a reference patch, so the correlation peak is exactly 1
    // at (3, -5) and its neighbours are symmetric: no sub-pixel offset may creep in.
    const TestImage reference = smooth_texture(kWidth, kHeight, 2);
    const TestImage test = shifted_whole_pixels(reference, 3, -5);
    const DriftMeasurement drift = measured(view(reference), view(test));
    EXPECT_EQ(drift.patches, kDefaultGridPatches);
    EXPECT_NEAR(drift.mean_dx_px, 3.0, 1e-9);
    EXPECT_NEAR(drift.mean_dy_px, -5.0, 1e-9);
    EXPECT_NEAR(drift.median_px, std::sqrt(34.0), 1e-9);
    EXPECT_NEAR(drift.max_px, std::sqrt(34.0), 1e-9);
}

TEST(QualityDrift, SubPixelShiftIsMeasuredToAFewHundredthsOfAPixel) {
    // test(x, y) = reference(x - 2.3, y + 1.2): content moves right 2.3 and up 1.2. Over 60
    // texture seeds the median was within 0.041 px of the truth and the means within 0.03 px;
    // single patches were within 0.21 px (resampling blurs the test image, and a parabola fit
    // pulls slightly towards whole pixels), hence the looser bounds on p95 and max.
    const TestImage reference = smooth_texture(kWidth, kHeight, 3);
    const TestImage test = shifted(reference, 2.3, -1.2);
    const double expected = std::hypot(2.3, -1.2);

    const DriftMeasurement drift = measured(view(reference), view(test));
    EXPECT_EQ(drift.patches, kDefaultGridPatches);
    EXPECT_EQ(drift.rejected_patches, 0u);
    EXPECT_NEAR(drift.median_px, expected, 0.08);
    EXPECT_NEAR(drift.mean_dx_px, 2.3, 0.05);
    EXPECT_NEAR(drift.mean_dy_px, -1.2, 0.05);
    EXPECT_NEAR(drift.p95_px, expected, 0.3);
    EXPECT_NEAR(drift.max_px, expected, 0.4);

    // Swapping the roles reverses the direction (up to the blur bilinear resampling adds).
    const DriftMeasurement back = measured(view(test), view(reference));
    EXPECT_EQ(back.patches, kDefaultGridPatches);
    EXPECT_NEAR(back.median_px, expected, 0.08);
    EXPECT_NEAR(back.mean_dx_px, -2.3, 0.05);
    EXPECT_NEAR(back.mean_dy_px, 1.2, 0.05);
}

TEST(QualityDrift, ChannelCountsMayDiffer) {
    // Grey reference, RGBA test with the same grey in R, G and B: luma agrees up to the last bit.
    const TestImage colour = smooth_texture(kWidth, kHeight, 4);
    std::vector<std::uint8_t> grey(std::size_t{kWidth} * kHeight);
    for (std::size_t i = 0; i < grey.size(); ++i) grey[i] = colour.pixels[4 * i + 1];
    TestImage grey_rgba = flat_image(kWidth, kHeight, 0);
    for (std::size_t i = 0; i < grey.size(); ++i) {
        std::fill_n(&grey_rgba.pixels[4 * i], 3, grey[i]);
    }
    const TestImage test = shifted_whole_pixels(grey_rgba, -4, 2);
    const ImageView grey_view{kWidth, kHeight, 1, grey};
    const DriftMeasurement drift = measured(grey_view, view(test));
    EXPECT_EQ(drift.patches, kDefaultGridPatches);
    EXPECT_NEAR(drift.mean_dx_px, -4.0, 1e-6);
    EXPECT_NEAR(drift.mean_dy_px, 2.0, 1e-6);
    EXPECT_NEAR(drift.max_px, std::sqrt(20.0), 1e-6);
}

// ----- the mask -------------------------------------------------------------------------------

TEST(QualityDrift, MaskSelectsWhereDriftIsMeasured) {
    // Hybrid-like: the right half (x >= 128) drifted by (2.3, -1.2), the left half is untouched.
    const TestImage reference = smooth_texture(kWidth, kHeight, 5);
    const TestImage moved = shifted(reference, 2.3, -1.2);
    TestImage test = reference;
    for (std::uint32_t y = 0; y < kHeight; ++y) {
        for (std::uint32_t x = 128; x < kWidth; ++x) std::copy_n(moved.at(x, y), 4, test.at(x, y));
    }
    std::vector<std::uint8_t> right(std::size_t{kWidth} * kHeight, 0);
    std::vector<std::uint8_t> left(right.size(), 0);
    for (std::size_t i = 0; i < right.size(); ++i) (i % kWidth >= 128 ? right : left)[i] = 1;

    // Patches wholly right of x = 128 have cx - 7 >= 128: cx = 135, 159, 183, 207, 231.
    const DriftMeasurement far = measured(view(reference), view(test), right);
    EXPECT_EQ(far.patches, 5u * 7u);
    EXPECT_NEAR(far.median_px, std::hypot(2.3, -1.2), 0.08);
    EXPECT_NEAR(far.mean_dx_px, 2.3, 0.05);
    EXPECT_NEAR(far.mean_dy_px, -1.2, 0.05);

    // Wholly left: cx + 7 <= 127, so cx = 15, ..., 111; every test pixel read (up to
    // 111 + 8 + 7 = 126) is untouched, so the drift is exactly zero.
    const DriftMeasurement near = measured(view(reference), view(test), left);
    EXPECT_EQ(near.patches, 5u * 7u);
    EXPECT_NEAR(near.max_px, 0.0, 1e-6);

    // Unmasked, both halves count (no patch straddles x = 128: cx = 111 ends at 118, cx = 135
    // starts at 128), half of them moved, half not.
    const DriftMeasurement everywhere = measured(view(reference), view(test));
    EXPECT_EQ(everywhere.patches, kDefaultGridPatches);
    EXPECT_NEAR(everywhere.mean_dx_px, 2.3 / 2.0, 0.05);
}

TEST(QualityDrift, MaskExcludingEverythingMeasuresNothing) {
    const TestImage reference = smooth_texture(kWidth, kHeight, 6);
    const TestImage test = shifted(reference, 2.3, -1.2);
    const std::vector<std::uint8_t> nothing(std::size_t{kWidth} * kHeight, 0);
    const DriftMeasurement drift = measured(view(reference), view(test), nothing);
    expect_all_zero(drift);
    EXPECT_EQ(drift.rejected_patches, 0u);
}

// ----- nothing to measure, or nothing that matches ----------------------------------------------

TEST(QualityDrift, FlatImagesMeasureNothing) {
    const TestImage flat = flat_image(kWidth, kHeight, 90);
    const TestImage other_flat = flat_image(kWidth, kHeight, 200);
    expect_all_zero(measured(view(flat), view(other_flat)));
    // A flat reference has no patch to look for, whatever the test image holds.
    expect_all_zero(measured(view(flat), view(smooth_texture(kWidth, kHeight, 7))));

    // A textured reference against a flat test: nothing correlates, every patch is rejected.
    const DriftMeasurement lost = measured(view(smooth_texture(kWidth, kHeight, 7)), view(flat));
    expect_all_zero(lost);
    EXPECT_EQ(lost.rejected_patches, kDefaultGridPatches);
}

TEST(QualityDrift, ShiftBeyondTheSearchRadiusIsRejectedNotReportedSmall) {
    // 12.6 px right is beyond the default search radius of 8: the best match inside the window is
    // texture that does not correlate, so it must not pass as a small drift.
    const TestImage reference = smooth_texture(kWidth, kHeight, 8);
    const TestImage test = shifted(reference, 12.6, -2.0);
    const DriftMeasurement drift = measured(view(reference), view(test));
    expect_all_zero(drift);
    EXPECT_EQ(drift.rejected_patches, kDefaultGridPatches);

    // A wide enough search finds it. Margin 7 + 16 = 23: centres x = 23, ..., 215 (9), y = 23,
    // ..., 167 (7).
    DriftOptions wide;
    wide.search_radius = 16;
    const DriftMeasurement found = measured(view(reference), view(test), {}, wide);
    EXPECT_EQ(found.patches, 9u * 7u);
    EXPECT_NEAR(found.mean_dx_px, 12.6, 0.05);
    EXPECT_NEAR(found.mean_dy_px, -2.0, 0.05);
}

TEST(QualityDrift, ImageTooSmallForOnePatchMeasuresNothing) {
    // A 15 x 15 patch with an 8 px search needs 31 x 31 pixels.
    const TestImage small = smooth_texture(30, 40, 9);
    expect_all_zero(measured(view(small), view(small)));
    const TestImage fits = smooth_texture(31, 31, 9);
    EXPECT_EQ(measured(view(fits), view(fits)).patches, 1u);
}

// ----- errors ---------------------------------------------------------------------------------

TEST(QualityDrift, RejectsBadInputsWithAnError) {
    const TestImage a = smooth_texture(40, 30, 10);
    const TestImage wider = smooth_texture(41, 30, 10);
    const Result<DriftMeasurement> sizes = measure_drift(view(a), view(wider), {});
    ASSERT_FALSE(sizes.ok());
    EXPECT_NE(sizes.error().message.find("40x30"), std::string::npos);
    EXPECT_NE(sizes.error().message.find("41x30"), std::string::npos);

    ImageView short_buffer = view(a);
    short_buffer.pixels = short_buffer.pixels.first(100);
    EXPECT_FALSE(measure_drift(short_buffer, view(a), {}).ok());
    EXPECT_FALSE(measure_drift(view(a), short_buffer, {}).ok());
    ImageView two_channels = view(a);
    two_channels.channels = 2;
    EXPECT_FALSE(measure_drift(two_channels, two_channels, {}).ok());
    EXPECT_FALSE(measure_drift(ImageView{}, ImageView{}, {}).ok());

    const std::vector<std::uint8_t> short_mask(std::size_t{40} * 29, 1);
    const Result<DriftMeasurement> mask = measure_drift(view(a), view(a), short_mask);
    ASSERT_FALSE(mask.ok());
    EXPECT_NE(mask.error().message.find("1160"), std::string::npos);
    EXPECT_NE(mask.error().message.find("1200"), std::string::npos);

    const auto rejects = [&](auto&& change) {
        DriftOptions options;
        change(options);
        return !measure_drift(view(a), view(a), {}, options).ok();
    };
    EXPECT_TRUE(rejects([](DriftOptions& o) { o.patch_radius = 0; }));
    EXPECT_TRUE(rejects([](DriftOptions& o) { o.grid_step = 0; }));
    EXPECT_TRUE(rejects([](DriftOptions& o) { o.search_radius = -1; }));
    EXPECT_TRUE(rejects([](DriftOptions& o) { o.min_luma_stddev = -1.0; }));
    EXPECT_TRUE(rejects([](DriftOptions& o) { o.min_luma_stddev = std::nan(""); }));
    EXPECT_TRUE(rejects([](DriftOptions& o) { o.min_correlation = 1.5; }));
    EXPECT_TRUE(rejects([](DriftOptions& o) { o.min_correlation = std::nan(""); }));
    EXPECT_FALSE(rejects([](DriftOptions& o) { o.search_radius = 0; }));
    // Huge radii are valid, just too big for any image: nothing measured, no overflow.
    EXPECT_FALSE(rejects([](DriftOptions& o) {
        o.patch_radius = 2147483647;
        o.search_radius = 2147483647;
    }));
}

}  // namespace
}  // namespace monoplane::quality
