#include "renderer/quality/local_moments.h"

#include <array>
#include <cstddef>
#include <vector>

#include "common/programming_error.h"

namespace monoplane::quality {
namespace {

// The five per-pixel quantities whose local means SSIM needs.
enum Quantity : std::size_t { kA, kB, kAA, kBB, kAB, kQuantities };

// out[i] = sum_k kernel[k] * in[i + k] for i in [0, out.size()). The loop over i is innermost so
// it vectorises, and every out[i] is summed in the same k order whatever the lane, which keeps
// results deterministic and identical across quantities.
void filter(const double* in, std::span<double> out, std::span<const double> kernel) {
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = kernel[0] * in[i];
    for (std::size_t k = 1; k < kernel.size(); ++k) {
        const double weight = kernel[k];
        for (std::size_t i = 0; i < out.size(); ++i) out[i] += weight * in[i + k];
    }
}

}  // namespace

void local_moments(std::span<const double> a, std::span<const double> b, std::uint32_t width,
                   std::uint32_t height, std::span<const double> kernel,
                   const std::function<void(std::uint32_t y, const MomentRow& row)>& row_done) {
    const std::size_t taps = kernel.size();
    MONOPLANE_EXPECTS(taps % 2 == 1 && width >= taps && height >= taps);
    MONOPLANE_EXPECTS(a.size() == std::size_t{width} * height && b.size() == a.size());
    const std::size_t r = taps / 2;
    const std::size_t out_width = width - 2 * r;

    // Products of the current input row, then a ring of the last `taps` horizontally filtered
    // rows per quantity: slot (row % taps).
    std::array<std::vector<double>, kQuantities> products;
    for (auto& p : products) p.resize(width);
    std::array<std::vector<double>, kQuantities> ring;
    for (auto& slots : ring) slots.resize(taps * out_width);
    std::array<std::vector<double>, kQuantities> vertical;
    for (auto& v : vertical) v.resize(out_width);

    for (std::size_t row = 0; row < height; ++row) {
        const double* ra = a.data() + row * width;
        const double* rb = b.data() + row * width;
        for (std::size_t x = 0; x < width; ++x) {
            products[kA][x] = ra[x];
            products[kB][x] = rb[x];
            products[kAA][x] = ra[x] * ra[x];
            products[kBB][x] = rb[x] * rb[x];
            products[kAB][x] = ra[x] * rb[x];
        }
        const std::size_t slot = row % taps;
        for (std::size_t q = 0; q < kQuantities; ++q) {
            filter(products[q].data(),
                   std::span<double>(ring[q].data() + slot * out_width, out_width), kernel);
        }
        if (row + 1 < taps) continue;

        // Rows row - 2r .. row are filtered: the window centred on y = row - r fits.
        const std::size_t first = row + 1 - taps;
        for (std::size_t q = 0; q < kQuantities; ++q) {
            std::span<double> out(vertical[q]);
            const double* slots = ring[q].data();
            const double* top = slots + (first % taps) * out_width;
            for (std::size_t i = 0; i < out_width; ++i) out[i] = kernel[0] * top[i];
            for (std::size_t k = 1; k < taps; ++k) {
                const double weight = kernel[k];
                const double* in = slots + ((first + k) % taps) * out_width;
                for (std::size_t i = 0; i < out_width; ++i) out[i] += weight * in[i];
            }
        }
        row_done(
            static_cast<std::uint32_t>(first + r),
            MomentRow{vertical[kA], vertical[kB], vertical[kAA], vertical[kBB], vertical[kAB]});
    }
}

}  // namespace monoplane::quality
