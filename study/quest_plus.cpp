#include "study/quest_plus.h"

#include <algorithm>
#include <cmath>

#include "common/programming_error.h"

namespace monoplane::study {
namespace {

// -sum p log p over the grid of prior[j] * likelihood[j] / z, z their sum.
double entropy_after(const std::vector<double>& prior, const double* likelihood, double z) {
    double h = 0.0;
    for (std::size_t j = 0; j < prior.size(); ++j) {
        const double p = prior[j] * likelihood[j] / z;
        if (p > 0.0) h -= p * std::log(p);
    }
    return h;
}

// The marginal posterior of the threshold, by threshold index.
std::vector<double> threshold_marginal(const std::vector<double>& posterior, std::size_t count) {
    std::vector<double> marginal(count, 0.0);
    for (std::size_t j = 0; j < posterior.size(); ++j) marginal[j % count] += posterior[j];
    return marginal;
}

// The q-quantile of a distribution over log thresholds spread evenly over bins centred on the
// grid points (edges halfway between neighbours, half a step beyond the ends): the credible
// interval moves smoothly with the posterior instead of jumping from grid point to grid point.
double log_quantile(const std::vector<double>& log_t, const std::vector<double>& weights,
                    double q) {
    const std::size_t n = log_t.size();
    double cumulative = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const double lo =
            i == 0 ? log_t[0] - (log_t[1] - log_t[0]) / 2 : (log_t[i - 1] + log_t[i]) / 2;
        const double hi = i + 1 == n ? log_t[n - 1] + (log_t[n - 1] - log_t[n - 2]) / 2
                                     : (log_t[i] + log_t[i + 1]) / 2;
        if (cumulative + weights[i] >= q && weights[i] > 0.0) {
            return lo + (hi - lo) * (q - cumulative) / weights[i];
        }
        cumulative += weights[i];
    }
    return log_t[n - 1] + (log_t[n - 1] - log_t[n - 2]) / 2;
}

}  // namespace

std::vector<double> log_spaced(double low, double high, int steps) {
    MONOPLANE_EXPECTS(low > 0.0 && low < high && steps >= 2);
    std::vector<double> values(static_cast<std::size_t>(steps));
    const double step = std::log(high / low) / (steps - 1);
    for (int i = 0; i < steps; ++i) values[static_cast<std::size_t>(i)] = low * std::exp(step * i);
    values.back() = high;  // exactly, not by rounding
    return values;
}

QuestPlus::QuestPlus(std::vector<double> stimuli, QuestPlusGrid grid)
    : stimuli_(std::move(stimuli)), grid_(std::move(grid)) {
    MONOPLANE_EXPECTS(!stimuli_.empty() && grid_.thresholds.size() >= 2 && !grid_.slopes.empty() &&
                      !grid_.lapses.empty());
    std::ranges::sort(stimuli_);
    const std::size_t count = grid_.thresholds.size() * grid_.slopes.size() * grid_.lapses.size();
    posterior_.assign(count, 1.0 / static_cast<double>(count));
    reference_likelihood_.resize(stimuli_.size() * count);
    test_likelihood_.resize(stimuli_.size() * count);
    for (std::size_t i = 0; i < stimuli_.size(); ++i) {
        MONOPLANE_EXPECTS(stimuli_[i] > 0.0);
        for (std::size_t j = 0; j < count; ++j) {
            reference_likelihood_[i * count + j] =
                reference_probability(parameters(j), stimuli_[i]);
            test_likelihood_[i * count + j] = test_probability(parameters(j), stimuli_[i]);
        }
    }
}

PsychometricFunction QuestPlus::parameters(std::size_t index) const {
    const std::size_t nt = grid_.thresholds.size(), ns = grid_.slopes.size();
    return {grid_.thresholds[index % nt], grid_.slopes[(index / nt) % ns],
            grid_.lapses[index / (nt * ns)]};
}

double QuestPlus::expected_entropy(std::size_t i) const {
    MONOPLANE_EXPECTS(i < stimuli_.size());
    const std::size_t count = posterior_.size();
    const double* reference = &reference_likelihood_[i * count];
    const double* test = &test_likelihood_[i * count];
    double p_reference = 0.0, p_test = 0.0;
    for (std::size_t j = 0; j < count; ++j) {
        p_reference += posterior_[j] * reference[j];
        p_test += posterior_[j] * test[j];
    }
    return p_reference * entropy_after(posterior_, reference, p_reference) +
           p_test * entropy_after(posterior_, test, p_test);
}

double QuestPlus::next_mono_plane() const {
    // Ties (equal to the last bit) go to the nearer m, so the choice is reproducible.
    std::size_t best = 0;
    double best_entropy = expected_entropy(0);
    for (std::size_t i = 1; i < stimuli_.size(); ++i) {
        const double h = expected_entropy(i);
        if (h < best_entropy) {
            best = i;
            best_entropy = h;
        }
    }
    return stimuli_[best];
}

void QuestPlus::record(double m, bool reference_chosen) {
    MONOPLANE_EXPECTS(m > 0.0);
    double z = 0.0;
    for (std::size_t j = 0; j < posterior_.size(); ++j) {
        const PsychometricFunction f = parameters(j);
        posterior_[j] *= reference_chosen ? reference_probability(f, m) : test_probability(f, m);
        z += posterior_[j];
    }
    for (double& p : posterior_) p /= z;
    ++trials_;
}

ThresholdEstimate QuestPlus::estimate() const {
    const std::vector<double> marginal = threshold_marginal(posterior_, grid_.thresholds.size());
    std::vector<double> log_t(grid_.thresholds.size());
    std::ranges::transform(grid_.thresholds, log_t.begin(), [](double t) { return std::log(t); });
    double mean = 0.0, square = 0.0;
    for (std::size_t i = 0; i < log_t.size(); ++i) {
        mean += marginal[i] * log_t[i];
        square += marginal[i] * log_t[i] * log_t[i];
    }
    const double variance = std::max(0.0, square - mean * mean);
    ThresholdEstimate estimate;
    // The median, not the mean: the marginal posterior is skewed (answers far above the
    // threshold are near chance and say little), so its mean lies above its median; the median
    // was unbiased in simulation (docs/analysis.md) and is the same on the m and log m scales.
    estimate.threshold_m = std::exp(log_quantile(log_t, marginal, 0.5));
    estimate.sd_log10 = std::sqrt(variance) / std::log(10.0);
    estimate.lower_m = std::exp(log_quantile(log_t, marginal, 0.025));
    estimate.upper_m = std::exp(log_quantile(log_t, marginal, 0.975));
    estimate.trials = trials_;
    return estimate;
}

}  // namespace monoplane::study
