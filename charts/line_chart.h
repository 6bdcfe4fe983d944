// Line and scatter charts over two numeric axes: e.g. drawn primitives per view over the
// mono-plane distance m, GPU time against image error per scene (points labelled with m), or the
// proportion of hybrid choices over m with confidence intervals and a 50 % chance line.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "charts/axis.h"
#include "charts/chart_frame.h"

namespace monoplane::charts {

// The ends of an error bar in data units (e.g. a confidence interval), not offsets from y.
struct ErrorRange {
    double lower = 0.0;
    double upper = 0.0;
};

struct DataPoint {
    double x = 0.0;
    double y = 0.0;
    std::optional<ErrorRange> error;
    std::string label;  // written beside the marker, e.g. "m = 8"; empty: none
};

struct LineSeries {
    std::string name;  // the legend entry; empty: not in the legend
    std::vector<DataPoint> points;
    bool connect = true;  // false: markers only (a scatter series)
    MarkerShape marker = MarkerShape::circle;
    std::string color;  // empty: the palette's colour (and dash) for the series' index
};

struct LineChart {
    ChartText text;
    AxisSpec x_axis;
    AxisSpec y_axis;
    std::vector<LineSeries> series;
    std::vector<ReferenceLine> reference_lines;
    Layout layout;
};

// The chart as a self-contained SVG document. Any time after the chart is filled in; pure.
//
// Points are drawn in the order given (a line follows the order, not x). A point whose x or y is
// not drawable (NaN, infinite, or <= 0 on a log axis) is left out and its series' line is broken
// there, so a gap in the data shows as a gap: each unbroken run of two or more points is one
// <polyline>. An error bar end that is not drawable leaves out the bar, not the point. The axes
// cover all drawable points, error bars and reference lines unless their ends are fixed; data
// beyond a fixed end is clipped at the plot's edge. With nothing drawable the figure shows its
// titles, a frame and "no data".
std::string render_svg(const LineChart& chart);

}  // namespace monoplane::charts
