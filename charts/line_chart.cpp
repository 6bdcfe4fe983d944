#include "charts/line_chart.h"

#include <utility>

#include "charts/palette.h"

namespace monoplane::charts {
namespace {

bool point_drawable(const LineChart& chart, const DataPoint& point) {
    return is_drawable(chart.x_axis.scale, point.x) && is_drawable(chart.y_axis.scale, point.y);
}

bool error_drawable(const LineChart& chart, const DataPoint& point) {
    return point.error && is_drawable(chart.y_axis.scale, point.error->lower) &&
           is_drawable(chart.y_axis.scale, point.error->upper);
}

SeriesLook look_of(const LineSeries& series, std::size_t index) {
    SeriesLook look = series_look(index);
    if (!series.color.empty()) look = {series.color, ""};
    return look;
}

void draw_series(SvgWriter& svg, const LineChart& chart, const LineSeries& series,
                 const SeriesLook& look, const Scale& x_scale, const Scale& y_scale) {
    svg.open_group("series");
    for (const DataPoint& point : series.points) {
        if (!point_drawable(chart, point) || !error_drawable(chart, point)) continue;
        const double x = x_scale.pixel(point.x);
        const double lower = y_scale.pixel(point.error->lower);
        const double upper = y_scale.pixel(point.error->upper);
        const Paint paint = stroke_paint(look.color, 1.5);
        svg.line(x, lower, x, upper, paint);
        svg.line(x - 4.0, lower, x + 4.0, lower, paint);
        svg.line(x - 4.0, upper, x + 4.0, upper, paint);
    }
    if (series.connect) {
        Paint paint = fill_paint("none", look.color, 2.0);
        paint.dash = look.dash;
        std::vector<Point> run;
        const auto flush = [&] {
            // A lone point between gaps has no line to draw; its marker shows it.
            if (run.size() >= 2) svg.polyline(run, paint);
            run.clear();
        };
        for (const DataPoint& point : series.points) {
            if (!point_drawable(chart, point)) {
                flush();
                continue;
            }
            run.push_back({x_scale.pixel(point.x), y_scale.pixel(point.y)});
        }
        flush();
    }
    for (const DataPoint& point : series.points) {
        if (!point_drawable(chart, point)) continue;
        draw_marker(svg, series.marker, x_scale.pixel(point.x), y_scale.pixel(point.y), look.color);
    }
    svg.close_group();
}

// Outside the clip group, so a label next to a point at the plot's edge is not cut off; points
// outside a fixed domain keep theirs hidden.
void draw_point_labels(SvgWriter& svg, const LineChart& chart, const Ticks& x_ticks,
                       const Ticks& y_ticks, const Scale& x_scale, const Scale& y_scale) {
    bool opened = false;
    for (const LineSeries& series : chart.series) {
        for (const DataPoint& point : series.points) {
            if (point.label.empty() || !point_drawable(chart, point)) continue;
            if (point.x < x_ticks.min || point.x > x_ticks.max || point.y < y_ticks.min ||
                point.y > y_ticks.max) {
                continue;
            }
            if (!opened) {
                svg.open_group("point-labels");
                opened = true;
            }
            svg.text(x_scale.pixel(point.x) + 6.0, y_scale.pixel(point.y) - 6.0, point.label,
                     text_style(TextAnchor::start, 11.0, "#333"));
        }
    }
    if (opened) svg.close_group();
}

}  // namespace

std::string render_svg(const LineChart& chart) {
    Extent x_extent;
    Extent y_extent;
    for (const LineSeries& series : chart.series) {
        for (const DataPoint& point : series.points) {
            if (!point_drawable(chart, point)) continue;
            x_extent.include(chart.x_axis.scale, point.x);
            y_extent.include(chart.y_axis.scale, point.y);
            if (error_drawable(chart, point)) {
                y_extent.include(chart.y_axis.scale, point.error->lower);
                y_extent.include(chart.y_axis.scale, point.error->upper);
            }
        }
    }
    const bool has_data = !x_extent.empty();
    std::vector<LegendEntry> legend;
    for (std::size_t i = 0; i < chart.series.size() && has_data; ++i) {
        const LineSeries& series = chart.series[i];
        if (series.name.empty()) continue;
        const SeriesLook look = look_of(series, i);
        LegendEntry entry;
        entry.label = series.name;
        entry.color = look.color;
        entry.dash = look.dash;
        entry.line = series.connect;
        entry.marker = series.marker;
        legend.push_back(std::move(entry));
    }

    const Layout& layout = chart.layout;
    const PlotArea area =
        plot_area(layout, !legend.empty() && layout.legend != LegendPosition::none);
    SvgWriter svg(layout.width, layout.height);
    draw_chart_text(svg, layout, chart.text);
    if (!has_data) {
        draw_axis_labels(svg, area, chart.x_axis.label, chart.y_axis.label);
        draw_no_data(svg, area);
        return svg.finish();
    }
    for (const ReferenceLine& reference : chart.reference_lines) {
        y_extent.include(chart.y_axis.scale, reference.y);
    }

    const Ticks x_ticks = resolve_axis(chart.x_axis, x_extent.min, x_extent.max);
    const Ticks y_ticks = resolve_axis(chart.y_axis, y_extent.min, y_extent.max);
    const Scale x_scale(chart.x_axis.scale, x_ticks, area.left, area.right);
    const Scale y_scale(chart.y_axis.scale, y_ticks, area.bottom, area.top);

    draw_vertical_gridlines(svg, area, x_ticks, x_scale);
    draw_horizontal_gridlines(svg, area, y_ticks, y_scale);
    draw_x_ticks(svg, area, x_ticks, x_scale);
    draw_y_ticks(svg, area, y_ticks, y_scale);
    draw_axis_labels(svg, area, chart.x_axis.label, chart.y_axis.label);
    draw_reference_lines(svg, area, y_ticks, y_scale, chart.reference_lines);

    const std::string clip = clip_id(area);
    svg.define_clip_rect(clip, area.left, area.top, area.width(), area.height());
    svg.open_group("data", {}, clip);
    for (std::size_t i = 0; i < chart.series.size(); ++i) {
        draw_series(svg, chart, chart.series[i], look_of(chart.series[i], i), x_scale, y_scale);
    }
    svg.close_group();
    draw_point_labels(svg, chart, x_ticks, y_ticks, x_scale, y_scale);
    draw_plot_frame(svg, area);
    if (layout.legend != LegendPosition::none) draw_legend(svg, area, legend);
    return svg.finish();
}

}  // namespace monoplane::charts
