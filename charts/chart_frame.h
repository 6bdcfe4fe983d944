// What every chart kind shares: the canvas and its plot area, titles, axes with gridlines,
// horizontal reference lines, markers, the legend and the "no data" note. The public structs are
// part of each chart's description; the draw_* functions are the building blocks line_chart.cpp
// and bar_chart.cpp paint with, in the order they are declared here.
#pragma once

#include <string>
#include <vector>

#include "charts/axis.h"
#include "charts/svg_writer.h"

namespace monoplane::charts {

// Text above the plot, centred: a bold title, a subtitle (e.g. device and settings) and a smaller
// grey note (e.g. how the figure was made). Empty lines are left out.
struct ChartText {
    std::string title;
    std::string subtitle;
    std::string note;
};

// Space around the plot area, in pixels. The defaults fit a title, a subtitle and a note above,
// tick labels and an axis label below, and tick labels of up to about six characters and a
// rotated axis label on the left. Labels are not measured: widen `left` for longer tick labels
// (or scale the data, e.g. to millions, and say so in the axis label).
struct Margins {
    double left = 80.0;
    double right = 20.0;
    double top = 90.0;
    double bottom = 70.0;
};

enum class LegendPosition { right, none };

struct Layout {
    double width = 800.0;
    double height = 480.0;
    Margins margins;
    LegendPosition legend = LegendPosition::right;
    // Taken from the plot's width, right of the plot, when a legend is drawn.
    double legend_width = 220.0;
};

// The rectangle data is drawn in, in SVG pixels (y grows downwards: top < bottom).
struct PlotArea {
    double left = 0.0;
    double top = 0.0;
    double right = 0.0;
    double bottom = 0.0;

    double width() const { return right - left; }
    double height() const { return bottom - top; }
};

// The plot area of `layout`; `legend_drawn` when the chart has at least one legend entry and
// layout.legend is not none. Requires margins (and legend) that leave a positive area.
PlotArea plot_area(const Layout& layout, bool legend_drawn);

// A horizontal line across the plot at a y value, labelled at its right end (e.g. chance at
// 50 % in a 2AFC proportion plot). It widens an automatic y domain so it is always visible.
struct ReferenceLine {
    double y = 0.0;
    std::string label;
    std::string color = "#555555";
};

enum class MarkerShape { none, circle, square, triangle, diamond };

// One row of the legend: a line sample (with marker), a marker alone, or a filled swatch.
struct LegendEntry {
    std::string label;
    std::string color;
    std::string dash;
    bool line = true;
    MarkerShape marker = MarkerShape::none;
    bool swatch = false;  // a filled square, for bar components; line and marker are ignored
};

// --- building blocks, in painting order ----------------------------------------------------

void draw_chart_text(SvgWriter& svg, const Layout& layout, const ChartText& text);
// Gridlines at every tick; on log axes decades darker than their 2..9 multiples.
void draw_vertical_gridlines(SvgWriter& svg, const PlotArea& area, const Ticks& ticks,
                             const Scale& scale);
void draw_horizontal_gridlines(SvgWriter& svg, const PlotArea& area, const Ticks& ticks,
                               const Scale& scale);
// Tick marks outside the plot and their labels.
void draw_x_ticks(SvgWriter& svg, const PlotArea& area, const Ticks& ticks, const Scale& scale);
void draw_y_ticks(SvgWriter& svg, const PlotArea& area, const Ticks& ticks, const Scale& scale);
// Category names centred under equal bands across the plot (bar charts).
void draw_category_ticks(SvgWriter& svg, const PlotArea& area,
                         const std::vector<std::string>& categories);
void draw_axis_labels(SvgWriter& svg, const PlotArea& area, const std::string& x_label,
                      const std::string& y_label);
// Lines whose y is not drawable or lies outside the domain are left out.
void draw_reference_lines(SvgWriter& svg, const PlotArea& area, const Ticks& y_ticks,
                          const Scale& y_scale, const std::vector<ReferenceLine>& lines);
void draw_marker(SvgWriter& svg, MarkerShape shape, double x, double y, const std::string& color);
void draw_plot_frame(SvgWriter& svg, const PlotArea& area);
void draw_legend(SvgWriter& svg, const PlotArea& area, const std::vector<LegendEntry>& entries);
// For a chart with nothing drawable: a frame and "no data" in its middle instead of axes.
void draw_no_data(SvgWriter& svg, const PlotArea& area);

// The id of the clip rectangle around `area`. Made from the area's geometry, so two figures
// inlined in one HTML page share an id only when their clip rectangles are the same anyway.
std::string clip_id(const PlotArea& area);

}  // namespace monoplane::charts
