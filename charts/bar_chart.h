// Stacked bars over categories: e.g. GPU time per pass (one component per pass) stacked for each
// mono-plane distance m, as a rendering paper's per-pass timing figure, optionally with lines over
// the bars on the same y axis (e.g. the conventional-stereo total at each m).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "charts/axis.h"
#include "charts/chart_frame.h"

namespace monoplane::charts {

// One layer of every stack: values[i] belongs to categories[i].
struct BarComponent {
    std::string name;  // the legend entry
    std::vector<double> values;
    std::string color;  // empty: the palette's colour for the component's index
};

// A line over the bars: values[i] is drawn at the centre of categories[i].
struct CategoryLine {
    std::string name;  // the legend entry; empty: not in the legend
    std::vector<double> values;
    MarkerShape marker = MarkerShape::circle;
    std::string color;  // empty: the palette's colour after the components'
};

struct StackedBarChart {
    ChartText text;
    std::vector<std::string> categories;  // the x axis, left to right (e.g. "1.6", "3", ...)
    std::string x_label;
    // Must be linear: stacks grow from zero, which a log axis cannot show. include_zero is implied.
    AxisSpec y_axis;
    std::vector<BarComponent> components;  // stacked bottom-up in this order
    std::vector<CategoryLine> lines;
    std::vector<ReferenceLine> reference_lines;
    // Writes each stack's total above it with this many decimals; unset: no totals.
    std::optional<int> total_decimals;
    double bar_width_fraction = 0.6;  // of each category's band
    Layout layout;
};

// The chart as a self-contained SVG document. Any time after the chart is filled in; pure.
//
// A component value that is missing (values shorter than categories), not finite or negative adds
// nothing to its stack and is not drawn; a zero is drawn as nothing but is data. Line values that
// are missing or not finite break the line there, as in line charts. The legend lists components
// top of the stack first, so it reads in the same order as the bars, then the lines. With no
// category or no finite value the figure shows its titles, a frame and "no data".
std::string render_svg(const StackedBarChart& chart);

}  // namespace monoplane::charts
