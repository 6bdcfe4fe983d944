#include "renderer/plan/depth_histogram.h"

#include <algorithm>
#include <bit>
#include <numeric>

#include "common/programming_error.h"

namespace monoplane::plan {

int DepthHistogram::bin_of(double depth) const {
    if (!(depth > near)) return 0;
    const double position = std::log(depth / near) / std::log(far / near) * kBins;
    return std::clamp(static_cast<int>(std::floor(position)), 0, kBins - 1);
}

std::uint64_t DepthHistogram::geometry_pixels() const {
    return std::accumulate(counts.begin(), counts.end(), std::uint64_t{0});
}

DepthHistogram depth_histogram_of(std::span<const std::uint32_t> words, double near, double far) {
    MONOPLANE_EXPECTS(words.size() >= MONOPLANE_DEPTH_HISTOGRAM_WORDS && near > 0.0 && far > near);
    DepthHistogram histogram;
    histogram.near = near;
    histogram.far = far;
    std::copy_n(words.begin(), DepthHistogram::kBins, histogram.counts.begin());
    histogram.sky = words[MONOPLANE_DEPTH_HISTOGRAM_SKY_WORD];
    histogram.farthest = std::bit_cast<float>(words[MONOPLANE_DEPTH_HISTOGRAM_FARTHEST_WORD]);
    return histogram;
}

double DepthHistogram::share_beyond(double depth) const {
    const std::uint64_t all = geometry_pixels();
    if (all == 0) return 0.0;
    std::uint64_t beyond = 0;
    for (int b = bin_of(depth); b < kBins; ++b) beyond += counts[static_cast<std::size_t>(b)];
    return static_cast<double>(beyond) / static_cast<double>(all);
}

}  // namespace monoplane::plan
