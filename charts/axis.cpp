#include "charts/axis.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>

#include "charts/svg_writer.h"
#include "common/programming_error.h"

namespace monoplane::charts {
namespace {

// Tolerance for floating-point noise when a value sits on a tick (0.3 / 0.1 = 2.9999999999999996).
constexpr double kSnap = 1e-9;

// Beyond this, powers of ten leave the range of doubles.
constexpr int kMaxExponent = 300;

// 10^exponent, exact while representable, else correctly rounded from exact integers.
double power_of_ten(int exponent) {
    double power = 1.0;
    for (int i = 0; i < std::abs(exponent); ++i) power *= 10.0;
    return exponent >= 0 ? power : 1.0 / power;
}

// multiple x 10^exponent as the double nearest to that decimal: for negative exponents divide
// two exact integers (one rounding) instead of multiplying by an inexact 0.01 (two roundings).
double decimal_value(std::int64_t multiple, int exponent) {
    const double m = static_cast<double>(multiple);
    return exponent >= 0 ? m * power_of_ten(exponent) : m / power_of_ten(-exponent);
}

// A 1-2-5 step: factor x 10^exponent.
struct DecimalStep {
    int factor = 1;
    int exponent = 0;

    double value() const { return decimal_value(factor, exponent); }
};

DecimalStep nice_decimal_step(double span, int target_intervals) {
    const double raw = span / target_intervals;
    const int exponent = static_cast<int>(std::floor(std::log10(raw)));
    for (int factor : {1, 2, 5}) {
        // The tolerance keeps 10 / 5 at a step of 2 when log10 rounds the decade down a hair.
        if (decimal_value(factor, exponent) >= raw * (1.0 - kSnap)) return {factor, exponent};
    }
    return {1, exponent + 1};
}

std::string log_tick_label(int multiple, int exponent) {
    // Plain decimals read best while short; beyond that, the compact e-notation.
    if (exponent >= -6 && exponent <= 9) {
        return format_fixed(decimal_value(multiple, exponent), std::max(0, -exponent));
    }
    return std::to_string(multiple) + "e" + std::to_string(exponent);
}

void keep_within(Ticks& ticks) {
    const double tolerance = kSnap * (ticks.max - ticks.min);
    const auto outside = [&](double v) {
        return v < ticks.min - tolerance || v > ticks.max + tolerance;
    };
    std::erase_if(ticks.major, [&](const Tick& tick) { return outside(tick.value); });
    std::erase_if(ticks.minor, outside);
}

}  // namespace

bool is_drawable(ScaleKind scale, double value) {
    return std::isfinite(value) && (scale == ScaleKind::linear || value > 0.0);
}

double nice_step(double span, int target_intervals) {
    MONOPLANE_EXPECTS(span > 0.0 && target_intervals > 0);
    return nice_decimal_step(span, target_intervals).value();
}

Ticks linear_ticks(double data_min, double data_max, int target_intervals) {
    if (target_intervals <= 0) target_intervals = 5;
    double lo = data_min;
    double hi = data_max;
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
        lo = 0.0;
        hi = 1.0;
    }
    if (lo == hi) {
        if (lo == 0.0) {
            hi = 1.0;
        } else {
            const double pad = 0.1 * std::abs(lo);
            lo -= pad;
            hi += pad;
        }
    }
    const DecimalStep step = nice_decimal_step(hi - lo, target_intervals);
    const double step_value = step.value();
    // Tick i sits at i x step; the domain runs from the last tick at or below lo to the first at
    // or above hi.
    const auto first = static_cast<std::int64_t>(std::floor(lo / step_value + kSnap));
    auto last = static_cast<std::int64_t>(std::ceil(hi / step_value - kSnap));
    if (last <= first) last = first + 1;

    Ticks ticks;
    const int decimals = std::max(0, -step.exponent);
    for (std::int64_t i = first; i <= last; ++i) {
        const double value = decimal_value(i * step.factor, step.exponent);
        ticks.major.push_back({value, format_fixed(value, decimals)});
    }
    ticks.min = ticks.major.front().value;
    ticks.max = ticks.major.back().value;
    return ticks;
}

Ticks log_ticks(double data_min, double data_max) {
    double lo = data_min;
    double hi = data_max;
    if (!is_drawable(ScaleKind::log10, lo) || !is_drawable(ScaleKind::log10, hi) || lo > hi) {
        lo = 1.0;
        hi = 10.0;
    }
    int lo_exponent = static_cast<int>(std::floor(std::log10(lo) + kSnap));
    int hi_exponent = static_cast<int>(std::ceil(std::log10(hi) - kSnap));
    lo_exponent = std::clamp(lo_exponent, -kMaxExponent, kMaxExponent - 1);
    hi_exponent = std::clamp(hi_exponent, lo_exponent, kMaxExponent);
    if (hi_exponent == lo_exponent) {
        // A single power of ten: one decade each side keeps it off the edge.
        --lo_exponent;
        ++hi_exponent;
    }
    const bool single_decade = hi_exponent - lo_exponent == 1;

    Ticks ticks;
    ticks.min = power_of_ten(lo_exponent);
    ticks.max = power_of_ten(hi_exponent);
    for (int exponent = lo_exponent; exponent <= hi_exponent; ++exponent) {
        ticks.major.push_back({decimal_value(1, exponent), log_tick_label(1, exponent)});
        if (exponent == hi_exponent) break;
        for (int multiple = 2; multiple <= 9; ++multiple) {
            const double value = decimal_value(multiple, exponent);
            // One decade alone would have only two labels; 2 and 5 give the reader a scale.
            if (single_decade && (multiple == 2 || multiple == 5)) {
                ticks.major.push_back({value, log_tick_label(multiple, exponent)});
            } else {
                ticks.minor.push_back(value);
            }
        }
    }
    return ticks;
}

Ticks resolve_axis(const AxisSpec& spec, double data_min, double data_max) {
    std::optional<double> fixed_min = spec.min;
    std::optional<double> fixed_max = spec.max;
    const auto unusable = [&](const std::optional<double>& end) {
        return end && !is_drawable(spec.scale, *end);
    };
    MONOPLANE_EXPECTS(!unusable(fixed_min) && !unusable(fixed_max) &&
                      "charts: fixed end off the scale");
    if (unusable(fixed_min)) fixed_min.reset();
    if (unusable(fixed_max)) fixed_max.reset();
    MONOPLANE_EXPECTS(!(fixed_min && fixed_max && *fixed_min >= *fixed_max) &&
                      "charts: fixed min >= max");
    if (fixed_min && fixed_max && *fixed_min >= *fixed_max) {
        fixed_min.reset();
        fixed_max.reset();
    }

    double lo = fixed_min.value_or(data_min);
    double hi = fixed_max.value_or(data_max);
    if (!std::isfinite(lo) && !std::isfinite(hi)) {
        // No data and no fixed end: an empty but valid axis.
        lo = spec.scale == ScaleKind::linear ? 0.0 : 1.0;
        hi = spec.scale == ScaleKind::linear ? 1.0 : 10.0;
    } else if (!std::isfinite(lo)) {
        lo = hi;
    } else if (!std::isfinite(hi)) {
        hi = lo;
    }
    if (spec.scale == ScaleKind::linear && spec.include_zero) {
        lo = std::min(lo, 0.0);
        hi = std::max(hi, 0.0);
    }
    // A fixed end beyond all the data: the axis collapses onto that end and is widened from it.
    if (lo > hi) {
        if (fixed_min)
            hi = lo;
        else
            lo = hi;
    }

    Ticks ticks = spec.scale == ScaleKind::linear ? linear_ticks(lo, hi, spec.target_intervals)
                                                  : log_ticks(lo, hi);
    if (fixed_min) ticks.min = *fixed_min;
    if (fixed_max) ticks.max = *fixed_max;
    keep_within(ticks);
    return ticks;
}

void Extent::include(ScaleKind scale, double value) {
    if (!is_drawable(scale, value)) return;
    min = std::min(min, value);
    max = std::max(max, value);
}

Scale::Scale(ScaleKind kind, double domain_min, double domain_max, double pixel_at_min,
             double pixel_at_max)
    : kind_(kind), pixel_at_min_(pixel_at_min), pixel_at_max_(pixel_at_max) {
    MONOPLANE_EXPECTS(is_drawable(kind, domain_min) && is_drawable(kind, domain_max));
    MONOPLANE_EXPECTS(domain_min < domain_max);
    transformed_min_ = transformed(domain_min);
    transformed_max_ = transformed(domain_max);
}

double Scale::pixel(double value) const {
    MONOPLANE_EXPECTS(maps(value));
    const double t =
        (transformed(value) - transformed_min_) / (transformed_max_ - transformed_min_);
    return pixel_at_min_ + t * (pixel_at_max_ - pixel_at_min_);
}

double Scale::transformed(double value) const {
    return kind_ == ScaleKind::log10 ? std::log10(value) : value;
}

}  // namespace monoplane::charts
