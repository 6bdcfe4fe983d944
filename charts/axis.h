// Axes: where the ticks go (1-2-5 steps on linear scales, decades on log scales) and how data maps
// to pixels. Pure functions with no SVG, shared by every chart kind and tested alone.
#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace monoplane::charts {

enum class ScaleKind { linear, log10 };

// What a chart asks of one axis; the domain itself is resolved from the data (resolve_axis).
struct AxisSpec {
    std::string label;
    ScaleKind scale = ScaleKind::linear;
    // Fixed ends of the domain. An unset end follows the data, widened to the next nice tick.
    std::optional<double> min;
    std::optional<double> max;
    // Linear only: widen the domain to contain 0, as times, counts and proportions are read
    // against zero.
    bool include_zero = false;
    // About how many intervals between labelled ticks on a linear axis (never more).
    int target_intervals = 5;
};

struct Tick {
    double value = 0.0;
    std::string label;
};

// A resolved axis: the domain [min, max] and its ticks, in increasing order.
struct Ticks {
    double min = 0.0;
    double max = 1.0;
    std::vector<Tick> major;    // labelled, with a tick mark and a gridline
    std::vector<double> minor;  // log axes: the 2..9 multiples of each decade, gridline only
};

// Whether `value` can be placed on an axis of this kind: finite, and positive on a log axis.
// Values that cannot are left out of every chart (a skipped point, not a broken figure).
bool is_drawable(ScaleKind scale, double value);

// The smallest step of 1, 2 or 5 times a power of ten that cuts `span` into at most
// `target_intervals` intervals: 37 and 5 give 10, 0.074 and 5 give 0.02. Requires span > 0 and
// target_intervals > 0.
double nice_step(double span, int target_intervals);

// Ticks for data within [data_min, data_max]: the domain widened outwards to multiples of
// nice_step, so 0..37 gives the domain 0..40 with ticks 0, 10, 20, 30, 40. Labels share one
// number of decimals. A single value (data_min == data_max) is widened by 10 % each side (0 to
// 0..1); non-finite or reversed input gives the domain 0..1. Any input gives min < max and at
// least two ticks. Tick values are the doubles nearest to their decimal labels (0.06, not
// 3 * 0.02).
Ticks linear_ticks(double data_min, double data_max, int target_intervals = 5);

// Ticks for positive data on a log10 axis: the domain widened to whole decades, each decade
// labelled and its 2..9 multiples as minor ticks; when the domain is a single decade, 2 and 5 are
// labelled as well. A single value that is a power of ten gets one decade each side; non-positive
// or non-finite input gives 1..10.
Ticks log_ticks(double data_min, double data_max);

// The axis for `spec` over data spanning [data_min, data_max] (pass +inf, -inf when there is no
// data): ticks as above, with fixed ends (spec.min, spec.max) taken as they are and ticks outside
// them dropped. A fixed end that the scale cannot show (<= 0 on log) or fixed ends with
// min >= max are programming errors; release builds ignore them.
Ticks resolve_axis(const AxisSpec& spec, double data_min, double data_max);

// The smallest interval holding every drawable value passed to include().
struct Extent {
    double min = std::numeric_limits<double>::infinity();
    double max = -std::numeric_limits<double>::infinity();

    void include(ScaleKind scale, double value);
    bool empty() const { return min > max; }
};

// Maps data values along one axis to pixel coordinates: domain_min lands on pixel_at_min and
// domain_max on pixel_at_max (for a y axis, pixel_at_min is the bottom of the plot, as SVG's y
// grows downwards). Linear in the value, or in its log10.
class Scale {
  public:
    // Requires domain_min < domain_max, both positive on a log scale.
    Scale(ScaleKind kind, double domain_min, double domain_max, double pixel_at_min,
          double pixel_at_max);
    // The same, over a resolved axis.
    Scale(ScaleKind kind, const Ticks& ticks, double pixel_at_min, double pixel_at_max)
        : Scale(kind, ticks.min, ticks.max, pixel_at_min, pixel_at_max) {}

    ScaleKind kind() const { return kind_; }
    bool maps(double value) const { return is_drawable(kind_, value); }
    // Requires maps(value). Values outside the domain map outside the pixel range.
    double pixel(double value) const;

  private:
    double transformed(double value) const;

    ScaleKind kind_;
    double transformed_min_;
    double transformed_max_;
    double pixel_at_min_;
    double pixel_at_max_;
};

}  // namespace monoplane::charts
