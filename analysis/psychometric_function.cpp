#include "analysis/psychometric_function.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <memory>

#include <nlopt.h>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/tools/roots.hpp>

#include "common/programming_error.h"

namespace monoplane::analysis {
namespace {

// The parts of P that the likelihood and its gradient share: with z = slope (ln m - ln
// threshold) and s = 1 / (1 + e^z), P = 0.5 + (0.5 - lapse) s and 1 - P = 0.5 (1 - s) + lapse s,
// both computed without cancellation.
struct Point {
    double s = 0.0, p = 0.0, q = 0.0, z = 0.0;
};

Point evaluate_point(double log_threshold, double slope, double lapse, double m) {
    Point point;
    point.z = slope * (std::log(m) - log_threshold);
    // s and 1 - s as logistic functions of -z and z, each exact where it is small.
    const double e = std::exp(-std::abs(point.z));
    const double small = e / (1.0 + e), large = 1.0 / (1.0 + e);
    point.s = point.z > 0 ? small : large;
    const double one_minus_s = point.z > 0 ? large : small;
    point.p = 0.5 + (0.5 - lapse) * point.s;
    point.q = 0.5 * one_minus_s + lapse * point.s;
    return point;
}

// x = (ln threshold, ln slope, lapse), or (ln slope, lapse) with the threshold held fixed.
struct Objective {
    const std::vector<StimulusLevel>* levels = nullptr;
    std::optional<double> log_threshold;  // set: profile
};

// Negative log-likelihood and its gradient, NLopt's callback.
double negative_log_likelihood(unsigned dimension, const double* x, double* gradient, void* data) {
    const Objective& o = *static_cast<const Objective*>(data);
    const bool profile = o.log_threshold.has_value();
    const double log_threshold = profile ? *o.log_threshold : x[0];
    const double slope = std::exp(x[profile ? 0 : 1]);
    const double lapse = x[profile ? 1 : 2];
    double value = 0.0;
    std::array<double, 3> g{0.0, 0.0, 0.0};  // d/d(ln threshold), d/d(ln slope), d/d(lapse)
    for (const StimulusLevel& level : *o.levels) {
        const Point pt = evaluate_point(log_threshold, slope, lapse, level.m);
        const double k = level.reference, n_minus_k = level.trials - level.reference;
        value -= k * std::log(pt.p) + n_minus_k * std::log(pt.q);
        const double dl_dp = k / pt.p - n_minus_k / pt.q;
        const double ds_dz = -pt.s * (1.0 - pt.s);
        g[0] -= dl_dp * (0.5 - lapse) * ds_dz * -slope;
        g[1] -= dl_dp * (0.5 - lapse) * ds_dz * pt.z;
        g[2] -= dl_dp * -pt.s;
    }
    if (gradient != nullptr) {
        for (unsigned i = 0; i < dimension; ++i) gradient[i] = g[profile ? i + 1 : i];
    }
    return value;
}

struct Start {
    double log_threshold, log_slope, lapse, value;
};

// The best few points of a coarse grid: thresholds spread over the tested distances, slopes
// from shallow to steep, a small lapse rate.
std::vector<Start> grid_starts(Objective& objective, const PsychometricBounds& bounds, double m_min,
                               double m_max) {
    std::vector<Start> grid;
    const bool profile = objective.log_threshold.has_value();
    const int thresholds = profile ? 1 : 12;
    for (int t = 0; t < thresholds; ++t) {
        const double log_threshold =
            profile ? *objective.log_threshold
                    : std::log(m_min) + (std::log(m_max) - std::log(m_min)) * t / (thresholds - 1);
        for (const double slope : {1.0, 3.0, 10.0, 40.0}) {
            const double lapse = std::clamp(0.01, bounds.lapse_min, bounds.lapse_max);
            const double x[3] = {log_threshold, std::log(slope), lapse};
            const double value =
                negative_log_likelihood(profile ? 2 : 3, profile ? x + 1 : x, nullptr, &objective);
            grid.push_back({log_threshold, std::log(slope), lapse, value});
        }
    }
    std::sort(grid.begin(), grid.end(),
              [](const Start& a, const Start& b) { return a.value < b.value; });
    grid.resize(std::min<std::size_t>(grid.size(), 3));
    return grid;
}

using Optimizer = std::unique_ptr<std::remove_pointer_t<nlopt_opt>, decltype(&nlopt_destroy)>;

// One bounded L-BFGS run from `x` (updated in place); returns the minimum.
double minimize(Objective& objective, const PsychometricBounds& bounds, std::vector<double>& x) {
    const bool profile = objective.log_threshold.has_value();
    const unsigned dimension = profile ? 2 : 3;
    Optimizer opt(nlopt_create(NLOPT_LD_LBFGS, dimension), &nlopt_destroy);
    MONOPLANE_EXPECTS(opt != nullptr);
    std::vector<double> lower = {std::log(bounds.threshold_min), std::log(bounds.slope_min),
                                 bounds.lapse_min};
    std::vector<double> upper = {std::log(bounds.threshold_max), std::log(bounds.slope_max),
                                 bounds.lapse_max};
    if (profile) {
        lower.erase(lower.begin());
        upper.erase(upper.begin());
    }
    nlopt_set_lower_bounds(opt.get(), lower.data());
    nlopt_set_upper_bounds(opt.get(), upper.data());
    nlopt_set_min_objective(opt.get(), &negative_log_likelihood, &objective);
    nlopt_set_ftol_rel(opt.get(), 1e-14);
    nlopt_set_xtol_rel(opt.get(), 1e-10);
    nlopt_set_maxeval(opt.get(), 5000);
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::clamp(x[i], lower[i], upper[i]);
    double value = negative_log_likelihood(dimension, x.data(), nullptr, &objective);
    // Stopping short (round-off near the optimum, evaluation limit) still leaves the best point
    // found in x, which is what is wanted; only a failure to start leaves x unusable.
    const nlopt_result result = nlopt_optimize(opt.get(), x.data(), &value);
    MONOPLANE_EXPECTS(result != NLOPT_INVALID_ARGS && result != NLOPT_OUT_OF_MEMORY);
    (void)result;
    return value;
}

struct Range {
    double min, max;
};

Range tested_range(const std::vector<StimulusLevel>& levels) {
    Range range{levels.front().m, levels.front().m};
    for (const StimulusLevel& level : levels) {
        range.min = std::min(range.min, level.m);
        range.max = std::max(range.max, level.m);
    }
    return range;
}

}  // namespace

double reference_probability(const PsychometricParameters& parameters, double m) {
    MONOPLANE_EXPECTS(m > 0.0 && parameters.threshold > 0.0 && parameters.slope > 0.0);
    MONOPLANE_EXPECTS(parameters.lapse >= 0.0 && parameters.lapse < 0.5);
    return evaluate_point(std::log(parameters.threshold), parameters.slope, parameters.lapse, m).p;
}

PsychometricBounds bounds_for(const std::vector<StimulusLevel>& levels) {
    MONOPLANE_EXPECTS(!levels.empty());
    const Range tested = tested_range(levels);
    PsychometricBounds bounds;
    bounds.threshold_min = tested.min / 10.0;
    bounds.threshold_max = tested.max * 10.0;
    return bounds;
}

double psychometric_log_likelihood(const std::vector<StimulusLevel>& levels,
                                   const PsychometricParameters& parameters) {
    Objective objective{&levels, std::nullopt};
    const double x[3] = {std::log(parameters.threshold), std::log(parameters.slope),
                         parameters.lapse};
    return -negative_log_likelihood(3, x, nullptr, &objective);
}

PsychometricMaximum maximize_psychometric_likelihood(const std::vector<StimulusLevel>& levels,
                                                     const PsychometricBounds& bounds,
                                                     std::optional<double> fixed_threshold) {
    MONOPLANE_EXPECTS(!levels.empty());
    Objective objective{&levels, std::nullopt};
    if (fixed_threshold) {
        MONOPLANE_EXPECTS(*fixed_threshold >= bounds.threshold_min &&
                          *fixed_threshold <= bounds.threshold_max);
        objective.log_threshold = std::log(*fixed_threshold);
    }
    const Range tested = tested_range(levels);
    PsychometricMaximum best;
    best.log_likelihood = -std::numeric_limits<double>::infinity();
    for (const Start& start : grid_starts(objective, bounds, tested.min, tested.max)) {
        std::vector<double> x = {start.log_threshold, start.log_slope, start.lapse};
        if (fixed_threshold) x.erase(x.begin());
        const double value = -minimize(objective, bounds, x);
        if (!(value > best.log_likelihood)) continue;
        best.log_likelihood = value;
        const std::size_t o = fixed_threshold ? 0 : 1;
        best.parameters.threshold = fixed_threshold ? *fixed_threshold : std::exp(x[0]);
        best.parameters.slope = std::exp(x[o]);
        best.parameters.lapse = x[o + 1];
    }
    return best;
}

ThresholdInterval profile_threshold_interval(const std::vector<StimulusLevel>& levels,
                                             const PsychometricBounds& bounds,
                                             const PsychometricMaximum& maximum, double search_min,
                                             double search_max, double confidence) {
    MONOPLANE_EXPECTS(confidence > 0.0 && confidence < 1.0);
    const double estimate = maximum.parameters.threshold;
    MONOPLANE_EXPECTS(search_min <= estimate && estimate <= search_max);
    const boost::math::chi_squared_distribution<double> chi_square(1.0);
    const double drop = boost::math::quantile(chi_square, confidence) / 2.0;
    // Positive inside the interval, negative outside; searched over log threshold.
    const auto inside = [&](double log_threshold) {
        const double threshold = std::exp(log_threshold);
        return maximize_psychometric_likelihood(levels, bounds, threshold).log_likelihood -
               (maximum.log_likelihood - drop);
    };
    const auto end = [&](double far) -> std::optional<double> {
        if (inside(std::log(far)) > 0.0) return std::nullopt;
        if (far == estimate) return far;
        boost::uintmax_t iterations = 60;
        const auto [a, b] = boost::math::tools::toms748_solve(
            inside, std::log(std::min(far, estimate)), std::log(std::max(far, estimate)),
            boost::math::tools::eps_tolerance<double>(40), iterations);
        return std::exp(0.5 * (a + b));
    };
    return {end(search_min), end(search_max)};
}

}  // namespace monoplane::analysis
