#include "app/commands/gaze_point_cost.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace monoplane::app {

void GazePointCost::found(double microseconds) {
    const int bin = std::clamp(static_cast<int>(std::floor(microseconds)), 0, kBins - 1);
    ++bins_[static_cast<std::size_t>(bin)];
    ++lookups_;
}

double GazePointCost::quantile_us(double q) const {
    if (lookups_ == 0) return 0.0;
    const auto rank = static_cast<std::int64_t>(std::ceil(q * static_cast<double>(lookups_)));
    std::int64_t seen = 0;
    for (int bin = 0; bin < kBins; ++bin) {
        seen += bins_[static_cast<std::size_t>(bin)];
        if (seen >= std::max<std::int64_t>(rank, 1)) return bin;
    }
    return kBins - 1;
}

std::string GazePointCost::summary() const {
    std::ostringstream out;
    out << "gaze points: " << lookups_ << " lookups";
    if (lookups_ > 0) {
        out << ", " << quantile_us(0.5) << " us each (median), " << quantile_us(0.99)
            << " us (99th percentile)";
    }
    out.precision(3);
    out << "; ray casting prepared in " << build_ms_ << " ms when the session began\n";
    return out.str();
}

}  // namespace monoplane::app
