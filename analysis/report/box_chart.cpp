#include "analysis/report/box_chart.h"

#include <cmath>

#include "charts/svg_writer.h"

namespace monoplane::analysis::report {

using namespace monoplane::charts;

namespace {

bool drawable(const Box& box) {
    return !box.empty && std::isfinite(box.min) && std::isfinite(box.q1) &&
           std::isfinite(box.median) && std::isfinite(box.q3) && std::isfinite(box.max);
}

}  // namespace

std::string render_svg(const BoxChart& chart) {
    AxisSpec y_axis = chart.y_axis;
    y_axis.scale = ScaleKind::linear;
    y_axis.include_zero = true;
    Extent extent;
    for (const Box& box : chart.boxes) {
        if (!drawable(box)) continue;
        extent.include(ScaleKind::linear, box.min);
        extent.include(ScaleKind::linear, box.max);
    }
    const bool has_data = !extent.empty();
    std::vector<LegendEntry> legend;
    if (has_data) {
        legend.push_back({"quartiles Q1-Q3", "#cfe3f1", "", false, MarkerShape::none, true});
        legend.push_back({"median", chart.color, "", true, MarkerShape::none, false});
        legend.push_back({"mean", chart.color, "", false, MarkerShape::diamond, false});
        legend.push_back({"min to max", "#555555", "", true, MarkerShape::none, false});
    }
    const Layout& layout = chart.layout;
    const PlotArea area =
        plot_area(layout, !legend.empty() && layout.legend != LegendPosition::none);
    SvgWriter svg(layout.width, layout.height);
    draw_chart_text(svg, layout, chart.text);
    if (!has_data) {
        draw_axis_labels(svg, area, chart.x_label, y_axis.label);
        draw_no_data(svg, area);
        return svg.finish();
    }
    const Ticks ticks = resolve_axis(y_axis, extent.min, extent.max);
    const Scale y(ScaleKind::linear, ticks, area.bottom, area.top);
    std::vector<std::string> categories;
    for (const Box& box : chart.boxes) categories.push_back(box.category);
    draw_horizontal_gridlines(svg, area, ticks, y);
    draw_category_ticks(svg, area, categories);
    draw_y_ticks(svg, area, ticks, y);
    draw_axis_labels(svg, area, chart.x_label, y_axis.label);

    const std::string clip = clip_id(area);
    svg.define_clip_rect(clip, area.left, area.top, area.width(), area.height());
    svg.open_group("data", {}, clip);
    const double band = area.width() / static_cast<double>(chart.boxes.size());
    const double half = std::min(40.0, band * 0.25);
    for (std::size_t i = 0; i < chart.boxes.size(); ++i) {
        const Box& box = chart.boxes[i];
        if (!drawable(box)) continue;
        const double x = area.left + band * (static_cast<double>(i) + 0.5);
        svg.open_group("box");
        const Paint whisker = stroke_paint("#555555", 1.2);
        svg.line(x, y.pixel(box.min), x, y.pixel(box.q1), whisker);
        svg.line(x, y.pixel(box.q3), x, y.pixel(box.max), whisker);
        svg.line(x - half / 2, y.pixel(box.min), x + half / 2, y.pixel(box.min), whisker);
        svg.line(x - half / 2, y.pixel(box.max), x + half / 2, y.pixel(box.max), whisker);
        const double top = y.pixel(box.q3);
        const double bottom = y.pixel(box.q1);
        svg.rect(x - half, top, 2 * half, std::max(bottom - top, 0.5),
                 fill_paint("#cfe3f1", chart.color, 1.5));
        svg.line(x - half, y.pixel(box.median), x + half, y.pixel(box.median),
                 stroke_paint(chart.color, 3.0));
        if (std::isfinite(box.mean)) {
            draw_marker(svg, MarkerShape::diamond, x, y.pixel(box.mean), chart.color);
        }
        svg.close_group();
    }
    svg.close_group();
    draw_plot_frame(svg, area);
    if (layout.legend != LegendPosition::none) draw_legend(svg, area, legend);
    return svg.finish();
}

}  // namespace monoplane::analysis::report
