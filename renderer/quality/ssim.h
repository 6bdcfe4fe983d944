// Structural similarity (Wang, Bovik, Sheikh, Simoncelli 2004, "Image quality assessment: from
// error visibility to structural similarity", IEEE TIP 13(4)) between two renderings, as
// papers/000 Sect. 5.2 and Fig. 6 compare hybrid against stereo images: a mean SSIM and the
// per-pixel local SSIM map behind the "(1 - SSIM) x 10" heat maps.
//
// Definitions used here:
// - Channel: luma of the sRGB-encoded values, Rec. 709 weights, in [0, 255] (see luma.h).
// - Local SSIM at pixel p: ((2 mu_a mu_b + C1)(2 sigma_ab + C2)) /
//   ((mu_a^2 + mu_b^2 + C1)(sigma_a^2 + sigma_b^2 + C2)), with C1 = (0.01 * 255)^2,
//   C2 = (0.03 * 255)^2, and mu, sigma^2, sigma_ab the window-weighted means, variances and
//   covariance over the window centred on p (weights normalised to sum 1; the variance is the
//   weighted E[x^2] - mu^2, as in Wang et al.'s reference code).
// - Window half-size w: the window covers the (2w + 1) x (2w + 1) pixels p + (dx, dy) with
//   |dx|, |dy| <= w. Wang et al.'s default is a Gaussian with w = 5 (11 x 11), sigma = 1.5,
//   truncated at w and renormalised. papers/000 Fig. 6 reports "local SSIM (w = 4)" without
//   defining w; we read it as this half-size, i.e. a 9 x 9 box (the odd, centred neighbour of
//   the 8 x 8 box of Wang et al.'s Sect. III-C), which SsimOptions::box() gives.
// - Borders: local SSIM is computed only where the whole window lies inside the image, i.e. for
//   w <= x < width - w and w <= y < height - w (no padding, so no invented pixels); the map holds
//   NaN elsewhere, and the mean is taken over the computed pixels only (as Wang et al.'s
//   reference code with its 'valid' filtering).
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "common/result.h"
#include "renderer/quality/image_view.h"

namespace monoplane::quality {

inline constexpr double kSsimC1 = (0.01 * 255.0) * (0.01 * 255.0);
inline constexpr double kSsimC2 = (0.03 * 255.0) * (0.03 * 255.0);

enum class SsimWindow { gaussian, box };

struct SsimOptions {
    SsimWindow window = SsimWindow::gaussian;
    // w, see the file comment: the window is (2w + 1) x (2w + 1) pixels. Must be >= 0.
    int half_size = 5;
    // Standard deviation of the Gaussian window in pixels (> 0); ignored for the box.
    double gaussian_sigma = 1.5;
    // Optional region for the mean: width * height bytes, row-major, non-zero = counted. It only
    // selects which local SSIM values are averaged (e.g. the pixels beyond the mono plane); each
    // local SSIM still sees its whole window, masked or not, and the map is always complete.
    // Empty = every pixel. The bytes must outlive the call.
    std::span<const std::uint8_t> mask;

    // Wang et al. 2004's default: 11 x 11 Gaussian, sigma 1.5.
    static SsimOptions gaussian() { return SsimOptions{}; }
    // Uniform (2w + 1) x (2w + 1) box; w = 4 is papers/000 Fig. 6's local SSIM.
    static SsimOptions box(int half_size = 4) {
        SsimOptions options;
        options.window = SsimWindow::box;
        options.half_size = half_size;
        return options;
    }
};

struct SsimResult {
    std::uint32_t width = 0;
    std::uint32_t height = 0;
    // The options' w: map values exist for border <= x < width - border, same for y.
    std::uint32_t border = 0;
    // Mean local SSIM over the computed pixels inside the mask; NaN when that set is empty
    // (a mask that selects only border pixels or nothing).
    double mean = std::numeric_limits<double>::quiet_NaN();
    // Number of local SSIM values averaged into mean.
    std::size_t counted_pixels = 0;
    // width * height local SSIM values in [-1, 1], row-major; NaN where the window does not fit.
    std::vector<float> map;

    // Local SSIM at (x, y); NaN in the border. Requires x < width, y < height.
    float at(std::uint32_t x, std::uint32_t y) const { return map[std::size_t{y} * width + x]; }
};

// SSIM of a against b (symmetric: ssim(a, b) and ssim(b, a) are bit-identical; identical images
// give exactly 1 everywhere). May be called with any well-formed views; channel counts may
// differ (both go through luma). Returns an error, never asserts, when the views are malformed,
// differ in width or height, are smaller than the window, the mask has the wrong size, or the
// options are out of range: such inputs can come from files and command lines.
Result<SsimResult> ssim(const ImageView& a, const ImageView& b, const SsimOptions& options = {});

// The normalised 1-D kernel of the window (2w + 1 taps; the 2-D window is its outer product with
// itself). Exposed for tests and for callers that document their settings. Requires valid
// options (half_size >= 0, gaussian_sigma > 0 for the Gaussian).
std::vector<double> ssim_window_kernel(const SsimOptions& options);

}  // namespace monoplane::quality
