// Box-like summaries per category, drawn with the charts' building blocks (charts/chart_frame.h):
// a box from the first to the third quartile, the median as a thick line across it, whiskers to
// the minimum and maximum, and the mean as a diamond. For skewed quantities such as decision
// times and switch counts, where a mean with a standard error would hide the long tail.
#pragma once

#include <string>
#include <vector>

#include "charts/axis.h"
#include "charts/chart_frame.h"

namespace monoplane::analysis::report {

struct Box {
    std::string category;  // under the box, e.g. "beams (n = 20)"
    double min = 0.0, q1 = 0.0, median = 0.0, q3 = 0.0, max = 0.0, mean = 0.0;
    bool empty = false;  // no values: the category is named, nothing drawn
};

struct BoxChart {
    charts::ChartText text;
    std::string x_label;
    charts::AxisSpec y_axis;  // linear; include_zero is implied
    std::vector<Box> boxes;
    std::string color = "#0072B2";
    charts::Layout layout;
};

// A self-contained SVG document; "no data" when every box is empty.
std::string render_svg(const BoxChart& chart);

}  // namespace monoplane::analysis::report
