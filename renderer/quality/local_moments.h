// Windowed first and second moments of two images: the five local statistics SSIM is built from
// (Wang et al. 2004, eqs. 14-16). The window is separable (a Gaussian or a box is the outer
// product of a 1-D kernel with itself), so a pixel costs 2 * (2r + 1) multiply-adds per statistic
// instead of (2r + 1)^2, and only 2r + 1 filtered rows are held at a time.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

namespace monoplane::quality {

// One output row of local means, for the pixels x in [r, width - r) where the window fits; element
// i belongs to pixel x = r + i. mean_aa is E[a^2], mean_ab is E[a b], and so on, each the
// window-weighted mean over the (2r + 1) x (2r + 1) neighbourhood.
struct MomentRow {
    std::span<const double> mean_a;
    std::span<const double> mean_b;
    std::span<const double> mean_aa;
    std::span<const double> mean_bb;
    std::span<const double> mean_ab;
};

// Calls row_done(y, row) for every y in [r, height - r), in increasing order, where r is
// (kernel.size() - 1) / 2; the row's spans are valid only during the call. a and b are
// width * height values, row-major. Requires an odd kernel summing to 1 and
// width, height >= kernel.size(). Identical inputs give bit-identical statistics for a and b
// (same operations in the same order), which is what makes SSIM exactly 1 for identical images.
void local_moments(std::span<const double> a, std::span<const double> b, std::uint32_t width,
                   std::uint32_t height, std::span<const double> kernel,
                   const std::function<void(std::uint32_t y, const MomentRow& row)>& row_done);

}  // namespace monoplane::quality
