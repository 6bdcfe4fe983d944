#include "study/weighted_up_down.h"

#include <algorithm>
#include <cmath>

#include "common/programming_error.h"

namespace monoplane::study {

WeightedUpDown::WeightedUpDown(double low, double high, double start, double target,
                               double step_log10, int skip_reversals)
    : low_(low),
      high_(high),
      step_farther_(step_log10),
      step_nearer_(step_log10 * target / (1.0 - target)),
      skip_reversals_(skip_reversals),
      next_(start) {
    MONOPLANE_EXPECTS(0.0 < low && low <= start && start <= high);
    MONOPLANE_EXPECTS(target > 0.5 && target < 1.0 && step_log10 > 0.0 && skip_reversals >= 0);
}

void WeightedUpDown::record(double m, bool reference_chosen) {
    MONOPLANE_EXPECTS(m > 0.0);
    const int direction = reference_chosen ? 1 : -1;
    if (last_direction_ != 0 && direction != last_direction_) reversals_.push_back(m);
    last_direction_ = direction;
    const double step = reference_chosen ? step_farther_ : -step_nearer_;
    next_ = std::clamp(m * std::pow(10.0, step), low_, high_);
    ++trials_;
}

ThresholdEstimate WeightedUpDown::estimate() const {
    ThresholdEstimate estimate;
    estimate.trials = trials_;
    const auto counted = static_cast<std::size_t>(skip_reversals_);
    if (reversals_.size() <= counted) {
        estimate.threshold_m = next_;
        return estimate;
    }
    double sum = 0.0;
    for (std::size_t i = counted; i < reversals_.size(); ++i) sum += std::log(reversals_[i]);
    estimate.threshold_m = std::exp(sum / static_cast<double>(reversals_.size() - counted));
    return estimate;
}

}  // namespace monoplane::study
