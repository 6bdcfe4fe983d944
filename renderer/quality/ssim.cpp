#include "renderer/quality/ssim.h"

#include <cmath>
#include <string>

#include "common/programming_error.h"
#include "renderer/quality/local_moments.h"
#include "renderer/quality/luma.h"

namespace monoplane::quality {
namespace {

bool valid_options(const SsimOptions& options) {
    if (options.half_size < 0) return false;
    return options.window == SsimWindow::box ||
           (std::isfinite(options.gaussian_sigma) && options.gaussian_sigma > 0.0);
}

// The first input problem, or an empty string.
std::string check_inputs(const ImageView& a, const ImageView& b, const SsimOptions& options) {
    if (!is_well_formed(a) || !is_well_formed(b)) {
        return "SSIM needs non-empty 8-bit images with 1, 3 or 4 channels and width * height * "
               "channels bytes; got " +
               describe(a) + " and " + describe(b);
    }
    if (a.width != b.width || a.height != b.height) {
        return "SSIM compares images of the same size; got " + size_text(a) + " and " +
               size_text(b) + " (render both at the same resolution)";
    }
    if (!valid_options(options)) {
        return "SSIM window needs half-size w >= 0 and, for the Gaussian, sigma > 0; got w = " +
               std::to_string(options.half_size) +
               ", sigma = " + std::to_string(options.gaussian_sigma);
    }
    const std::size_t window = 2 * static_cast<std::size_t>(options.half_size) + 1;
    if (a.width < window || a.height < window) {
        return "image " + size_text(a) + " is smaller than the " + std::to_string(window) + "x" +
               std::to_string(window) + " SSIM window (half-size " +
               std::to_string(options.half_size) + ")";
    }
    const std::size_t pixels = std::size_t{a.width} * a.height;
    if (!options.mask.empty() && options.mask.size() != pixels) {
        return "SSIM mask has " + std::to_string(options.mask.size()) + " entries; the " +
               size_text(a) + " images need " + std::to_string(pixels);
    }
    return {};
}

// Local SSIM from the window statistics. The denominators are written as numerator plus a
// non-negative difference, (mu_a - mu_b)^2 and sigma_a^2 + sigma_b^2 - 2 sigma_ab, which is the
// same quantity but makes identical inputs give exactly 1 even where the compiler fuses
// multiply-adds, and keeps the expression symmetric in a and b term by term.
double local_ssim(double mean_a, double mean_b, double mean_aa, double mean_bb, double mean_ab) {
    const double var_a = mean_aa - mean_a * mean_a;
    const double var_b = mean_bb - mean_b * mean_b;
    const double cov = mean_ab - mean_a * mean_b;
    const double luminance_num = 2.0 * mean_a * mean_b + kSsimC1;
    const double luminance_den = luminance_num + (mean_a - mean_b) * (mean_a - mean_b);
    const double structure_num = 2.0 * cov + kSsimC2;
    const double structure_den = structure_num + ((var_a + var_b) - 2.0 * cov);
    return (luminance_num * structure_num) / (luminance_den * structure_den);
}

}  // namespace

std::vector<double> ssim_window_kernel(const SsimOptions& options) {
    MONOPLANE_EXPECTS(valid_options(options));
    const std::size_t r = static_cast<std::size_t>(options.half_size);
    std::vector<double> kernel(2 * r + 1);
    const double two_sigma_squared = 2.0 * options.gaussian_sigma * options.gaussian_sigma;
    double sum = 0.0;
    for (std::size_t i = 0; i < kernel.size(); ++i) {
        const double offset = static_cast<double>(i) - static_cast<double>(r);
        kernel[i] = options.window == SsimWindow::box
                        ? 1.0
                        : std::exp(-(offset * offset) / two_sigma_squared);
        sum += kernel[i];
    }
    for (double& weight : kernel) weight /= sum;
    return kernel;
}

Result<SsimResult> ssim(const ImageView& a, const ImageView& b, const SsimOptions& options) {
    if (std::string problem = check_inputs(a, b, options); !problem.empty()) {
        return Error{std::move(problem)};
    }
    const std::vector<double> luma_a = luma(a);
    const std::vector<double> luma_b = luma(b);
    const std::vector<double> kernel = ssim_window_kernel(options);

    SsimResult result;
    result.width = a.width;
    result.height = a.height;
    result.border = static_cast<std::uint32_t>(options.half_size);
    result.map.assign(luma_a.size(), std::numeric_limits<float>::quiet_NaN());

    double sum = 0.0;
    std::size_t counted = 0;
    const std::uint32_t border = result.border;
    local_moments(
        luma_a, luma_b, a.width, a.height, kernel, [&](std::uint32_t y, const MomentRow& row) {
            const std::size_t row_start = std::size_t{y} * a.width + border;
            for (std::size_t i = 0; i < row.mean_a.size(); ++i) {
                const double value = local_ssim(row.mean_a[i], row.mean_b[i], row.mean_aa[i],
                                                row.mean_bb[i], row.mean_ab[i]);
                result.map[row_start + i] = static_cast<float>(value);
                if (options.mask.empty() || options.mask[row_start + i] != 0) {
                    sum += value;
                    ++counted;
                }
            }
        });
    result.counted_pixels = counted;
    if (counted > 0) result.mean = sum / static_cast<double>(counted);
    return result;
}

}  // namespace monoplane::quality
