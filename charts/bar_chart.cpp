#include "charts/bar_chart.h"

#include <algorithm>
#include <cmath>

#include "charts/palette.h"
#include "common/programming_error.h"

namespace monoplane::charts {
namespace {

// The value component or line `values` holds for category `index`, if it has a usable one.
std::optional<double> stacked_value(const std::vector<double>& values, std::size_t index) {
    if (index >= values.size() || !std::isfinite(values[index]) || values[index] < 0.0) {
        return std::nullopt;
    }
    return values[index];
}

std::optional<double> line_value(const std::vector<double>& values, std::size_t index) {
    if (index >= values.size() || !std::isfinite(values[index])) return std::nullopt;
    return values[index];
}

std::string component_color(const StackedBarChart& chart, std::size_t index) {
    const std::string& chosen = chart.components[index].color;
    return chosen.empty() ? series_look(index).color : chosen;
}

SeriesLook line_look(const StackedBarChart& chart, std::size_t index) {
    const std::string& chosen = chart.lines[index].color;
    if (!chosen.empty()) return {chosen, ""};
    return series_look(chart.components.size() + index);
}

// Pixels rounded to the precision written to the file, so that one rectangle's top is exactly
// the next one's bottom in the SVG as well.
double snapped(double pixel) {
    return std::round(pixel * 100.0) / 100.0;
}

// The values the stacks and lines hold over every category: the y extent they span, and whether
// there is any to draw.
struct DataExtent {
    Extent y;
    bool has_data = false;
};

DataExtent data_extent(const StackedBarChart& chart) {
    DataExtent extent;
    for (std::size_t i = 0; i < chart.categories.size(); ++i) {
        double total = 0.0;
        bool stacked = false;
        for (const BarComponent& component : chart.components) {
            if (const auto value = stacked_value(component.values, i)) {
                total += *value;
                stacked = true;
            }
        }
        if (stacked) extent.y.include(ScaleKind::linear, total);
        for (const CategoryLine& line : chart.lines) {
            if (const auto value = line_value(line.values, i)) {
                extent.y.include(ScaleKind::linear, *value);
                stacked = true;
            }
        }
        extent.has_data = extent.has_data || stacked;
    }
    return extent;
}

// The components top of the stack first, then the named lines.
std::vector<LegendEntry> legend_entries(const StackedBarChart& chart) {
    std::vector<LegendEntry> legend;
    for (std::size_t i = chart.components.size(); i-- > 0;) {
        LegendEntry entry;
        entry.label = chart.components[i].name;
        entry.color = component_color(chart, i);
        entry.swatch = true;
        legend.push_back(std::move(entry));
    }
    for (std::size_t i = 0; i < chart.lines.size(); ++i) {
        if (chart.lines[i].name.empty()) continue;
        const SeriesLook look = line_look(chart, i);
        LegendEntry entry;
        entry.label = chart.lines[i].name;
        entry.color = look.color;
        entry.dash = look.dash;
        entry.marker = chart.lines[i].marker;
        legend.push_back(std::move(entry));
    }
    return legend;
}

// Where the data goes: the plot area, the y axis, and each category's band along x.
struct BarGeometry {
    PlotArea area;
    Ticks y_ticks;
    Scale y_scale;
    double band = 0.0;  // each category's width
    double bar_width = 0.0;

    double centre(std::size_t i) const { return area.left + band * (static_cast<double>(i) + 0.5); }
};

// One group per component, so a reader of the file finds each pass's bars together. Returns the
// top of each category's stack.
std::vector<double> draw_stacks(SvgWriter& svg, const StackedBarChart& chart,
                                const BarGeometry& geometry) {
    const std::size_t count = chart.categories.size();
    std::vector<double> stack_tops(count, 0.0);
    for (std::size_t c = 0; c < chart.components.size(); ++c) {
        svg.open_group("bars", fill_paint(component_color(chart, c)));
        for (std::size_t i = 0; i < count; ++i) {
            const auto value = stacked_value(chart.components[c].values, i);
            if (!value) continue;
            const double bottom = snapped(geometry.y_scale.pixel(stack_tops[i]));
            stack_tops[i] += *value;
            const double top = snapped(geometry.y_scale.pixel(stack_tops[i]));
            if (bottom - top <= 0.0) continue;
            svg.rect(geometry.centre(i) - geometry.bar_width / 2.0, top, geometry.bar_width,
                     bottom - top, {});
        }
        svg.close_group();
    }
    return stack_tops;
}

// Line `index` over the bars: broken where a value is missing, with a marker at each value.
void draw_line(SvgWriter& svg, const StackedBarChart& chart, std::size_t index,
               const BarGeometry& geometry) {
    const std::size_t count = chart.categories.size();
    const CategoryLine& line = chart.lines[index];
    const SeriesLook look = line_look(chart, index);
    svg.open_group("series");
    Paint paint = fill_paint("none", look.color, 2.0);
    paint.dash = look.dash;
    std::vector<Point> run;
    const auto flush = [&] {
        if (run.size() >= 2) svg.polyline(run, paint);
        run.clear();
    };
    for (std::size_t i = 0; i < count; ++i) {
        const auto value = line_value(line.values, i);
        if (!value) {
            flush();
            continue;
        }
        run.push_back({geometry.centre(i), geometry.y_scale.pixel(*value)});
    }
    flush();
    for (std::size_t i = 0; i < count; ++i) {
        if (const auto value = line_value(line.values, i)) {
            draw_marker(svg, line.marker, geometry.centre(i), geometry.y_scale.pixel(*value),
                        look.color);
        }
    }
    svg.close_group();
}

// The stacks, then the lines over them, clipped to the plot area. Returns each stack's top.
std::vector<double> draw_data(SvgWriter& svg, const StackedBarChart& chart,
                              const BarGeometry& geometry) {
    const PlotArea& area = geometry.area;
    const std::string clip = clip_id(area);
    svg.define_clip_rect(clip, area.left, area.top, area.width(), area.height());
    svg.open_group("data", {}, clip);
    std::vector<double> stack_tops = draw_stacks(svg, chart, geometry);
    for (std::size_t l = 0; l < chart.lines.size(); ++l) draw_line(svg, chart, l, geometry);
    svg.close_group();
    return stack_tops;
}

// Each stack's total above it, where the stack has a value and its top is on the axis.
void draw_totals(SvgWriter& svg, const StackedBarChart& chart, const BarGeometry& geometry,
                 const std::vector<double>& stack_tops) {
    svg.open_group("totals");
    for (std::size_t i = 0; i < chart.categories.size(); ++i) {
        bool stacked = false;
        for (const BarComponent& component : chart.components) {
            stacked = stacked || stacked_value(component.values, i).has_value();
        }
        if (!stacked || stack_tops[i] > geometry.y_ticks.max) continue;
        svg.text(geometry.centre(i), geometry.y_scale.pixel(stack_tops[i]) - 5.0,
                 format_fixed(stack_tops[i], std::clamp(*chart.total_decimals, 0, 12)),
                 text_style(TextAnchor::middle, 11.0, "#333"));
    }
    svg.close_group();
}

}  // namespace

std::string render_svg(const StackedBarChart& chart) {
    MONOPLANE_EXPECTS(chart.y_axis.scale == ScaleKind::linear &&
                      "charts: stacked bars need a linear y axis");
    AxisSpec y_axis = chart.y_axis;
    y_axis.scale = ScaleKind::linear;
    y_axis.include_zero = true;

    DataExtent extent = data_extent(chart);
    const std::vector<LegendEntry> legend =
        extent.has_data ? legend_entries(chart) : std::vector<LegendEntry>{};
    const Layout& layout = chart.layout;
    const PlotArea area =
        plot_area(layout, !legend.empty() && layout.legend != LegendPosition::none);
    SvgWriter svg(layout.width, layout.height);
    draw_chart_text(svg, layout, chart.text);
    if (!extent.has_data) {
        draw_axis_labels(svg, area, chart.x_label, y_axis.label);
        draw_no_data(svg, area);
        return svg.finish();
    }
    for (const ReferenceLine& reference : chart.reference_lines) {
        extent.y.include(ScaleKind::linear, reference.y);
    }
    const Ticks y_ticks = resolve_axis(y_axis, extent.y.min, extent.y.max);
    const double band = area.width() / static_cast<double>(chart.categories.size());
    const BarGeometry geometry{area, y_ticks,
                               Scale(ScaleKind::linear, y_ticks, area.bottom, area.top), band,
                               band * std::clamp(chart.bar_width_fraction, 0.05, 1.0)};

    draw_horizontal_gridlines(svg, area, y_ticks, geometry.y_scale);
    draw_category_ticks(svg, area, chart.categories);
    draw_y_ticks(svg, area, y_ticks, geometry.y_scale);
    draw_axis_labels(svg, area, chart.x_label, y_axis.label);
    const std::vector<double> stack_tops = draw_data(svg, chart, geometry);
    // Over the bars, unlike in line charts: a budget line hidden behind a bar would be no use.
    draw_reference_lines(svg, area, y_ticks, geometry.y_scale, chart.reference_lines);
    if (chart.total_decimals) draw_totals(svg, chart, geometry, stack_tops);
    draw_plot_frame(svg, area);
    if (layout.legend != LegendPosition::none) draw_legend(svg, area, legend);
    return svg.finish();
}

}  // namespace monoplane::charts
