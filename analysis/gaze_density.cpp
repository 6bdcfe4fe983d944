#include "analysis/gaze_density.h"

#include <algorithm>
#include <cmath>

namespace monoplane::analysis {
namespace {

// A normalised Gaussian kernel over -3 sigma .. 3 sigma; one tap of weight 1 for sigma <= 0.
std::vector<double> gaussian_kernel(double sigma) {
    if (!(sigma > 0.0)) return {1.0};
    const int radius = static_cast<int>(std::ceil(3.0 * sigma));
    std::vector<double> kernel(static_cast<std::size_t>(2 * radius + 1));
    double sum = 0.0;
    for (int i = -radius; i <= radius; ++i) {
        const double w = std::exp(-0.5 * (i / sigma) * (i / sigma));
        kernel[static_cast<std::size_t>(i + radius)] = w;
        sum += w;
    }
    for (double& w : kernel) w /= sum;
    return kernel;
}

// One pass of the separable blur along columns (horizontal) or rows; zero outside the grid.
std::vector<double> blurred(const std::vector<double>& in, int columns, int rows,
                            const std::vector<double>& kernel, bool horizontal) {
    const int radius = static_cast<int>(kernel.size() / 2);
    std::vector<double> out(in.size(), 0.0);
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c) {
            double sum = 0.0;
            for (int k = -radius; k <= radius; ++k) {
                const int cc = horizontal ? c + k : c;
                const int rr = horizontal ? r : r + k;
                if (cc < 0 || cc >= columns || rr < 0 || rr >= rows) continue;
                sum += kernel[static_cast<std::size_t>(k + radius)] *
                       in[static_cast<std::size_t>(rr * columns + cc)];
            }
            out[static_cast<std::size_t>(r * columns + c)] = sum;
        }
    return out;
}

}  // namespace

double GazeDensity::peak() const {
    return share.empty() ? 0.0 : *std::max_element(share.begin(), share.end());
}

std::pair<int, int> GazeDensity::peak_bin() const {
    if (share.empty()) return {0, 0};
    const auto at = std::max_element(share.begin(), share.end()) - share.begin();
    return {static_cast<int>(at % columns), static_cast<int>(at / columns)};
}

int density_column(const EyeImagePoint& p, const DensityGrid& grid) {
    return std::clamp(static_cast<int>(std::floor(p.u * grid.columns)), 0, grid.columns - 1);
}

int density_row(const EyeImagePoint& p, const DensityGrid& grid) {
    return std::clamp(static_cast<int>(std::floor(p.v * grid.rows)), 0, grid.rows - 1);
}

GazeDensity gaze_density(const std::vector<GazeSampleRow>& samples, const std::string& scene,
                         const SeatEye& eye, const DensityGrid& grid) {
    GazeDensity d;
    d.scene = scene;
    d.columns = grid.columns;
    d.rows = grid.rows;
    std::vector<double> counts(static_cast<std::size_t>(grid.columns * grid.rows), 0.0);
    for (const GazeSampleRow& s : samples) {
        if (s.scene != scene) continue;
        ++d.samples;
        const std::optional<EyeImagePoint> p = project_into_left_eye(s, eye);
        if (!p || !p->inside()) continue;
        ++d.inside;
        counts[static_cast<std::size_t>(density_row(*p, grid) * grid.columns +
                                        density_column(*p, grid))] += 1.0;
    }
    if (d.inside > 0)
        for (double& c : counts) c /= d.inside;
    const std::vector<double> kernel = gaussian_kernel(grid.blur_sigma_bins);
    d.share = blurred(blurred(counts, grid.columns, grid.rows, kernel, true), grid.columns,
                      grid.rows, kernel, false);
    return d;
}

}  // namespace monoplane::analysis
