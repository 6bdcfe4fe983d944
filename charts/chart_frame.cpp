#include "charts/chart_frame.h"

#include <algorithm>

#include "common/programming_error.h"

namespace monoplane::charts {
namespace {

constexpr double kTickLength = 6.0;
constexpr const char* kLightGrid = "#e5e5e5";
constexpr const char* kDecadeGrid = "#c8c8c8";

std::string gridline_color(const Ticks& ticks, const Scale& scale) {
    return scale.kind() == ScaleKind::log10 && !ticks.minor.empty() ? kDecadeGrid : kLightGrid;
}

// A tick whose pixel lies off the plot (a fixed domain ending between ticks) is not drawn.
bool within(double pixel, double a, double b) {
    const double tolerance = 0.01;
    return pixel >= std::min(a, b) - tolerance && pixel <= std::max(a, b) + tolerance;
}

}  // namespace

PlotArea plot_area(const Layout& layout, bool legend_drawn) {
    const bool legend_right = legend_drawn && layout.legend == LegendPosition::right;
    PlotArea area;
    area.left = layout.margins.left;
    area.top = layout.margins.top;
    area.right = layout.width - layout.margins.right - (legend_right ? layout.legend_width : 0.0);
    area.bottom = layout.height - layout.margins.bottom;
    MONOPLANE_EXPECTS(area.width() > 0.0 && area.height() > 0.0 &&
                      "charts: margins leave no plot area");
    return area;
}

void draw_chart_text(SvgWriter& svg, const Layout& layout, const ChartText& text) {
    const double centre = layout.width / 2.0;
    double y = 28.0;
    if (!text.title.empty()) {
        TextStyle title_style = text_style(TextAnchor::middle, 17.0);
        title_style.bold = true;
        svg.text(centre, y, text.title, title_style);
        y += 22.0;
    }
    if (!text.subtitle.empty()) {
        svg.text(centre, y, text.subtitle, text_style(TextAnchor::middle));
        y += 20.0;
    }
    if (!text.note.empty()) {
        svg.text(centre, y, text.note, text_style(TextAnchor::middle, 12.0, "#555"));
    }
}

void draw_vertical_gridlines(SvgWriter& svg, const PlotArea& area, const Ticks& ticks,
                             const Scale& scale) {
    svg.open_group("grid", stroke_paint(kLightGrid, 1.0));
    for (double value : ticks.minor) {
        const double x = scale.pixel(value);
        if (within(x, area.left, area.right)) svg.line(x, area.top, x, area.bottom, {});
    }
    const std::string major_color = gridline_color(ticks, scale);
    for (const Tick& tick : ticks.major) {
        const double x = scale.pixel(tick.value);
        if (!within(x, area.left, area.right)) continue;
        svg.line(x, area.top, x, area.bottom,
                 stroke_paint(major_color == kLightGrid ? "" : major_color));
    }
    svg.close_group();
}

void draw_horizontal_gridlines(SvgWriter& svg, const PlotArea& area, const Ticks& ticks,
                               const Scale& scale) {
    svg.open_group("grid", stroke_paint(kLightGrid, 1.0));
    for (double value : ticks.minor) {
        const double y = scale.pixel(value);
        if (within(y, area.top, area.bottom)) svg.line(area.left, y, area.right, y, {});
    }
    const std::string major_color = gridline_color(ticks, scale);
    for (const Tick& tick : ticks.major) {
        const double y = scale.pixel(tick.value);
        if (!within(y, area.top, area.bottom)) continue;
        svg.line(area.left, y, area.right, y,
                 stroke_paint(major_color == kLightGrid ? "" : major_color));
    }
    svg.close_group();
}

void draw_x_ticks(SvgWriter& svg, const PlotArea& area, const Ticks& ticks, const Scale& scale) {
    svg.open_group("x-ticks");
    for (const Tick& tick : ticks.major) {
        const double x = scale.pixel(tick.value);
        if (!within(x, area.left, area.right)) continue;
        svg.line(x, area.bottom, x, area.bottom + kTickLength, stroke_paint("black"));
        svg.text(x, area.bottom + 22.0, tick.label, text_style(TextAnchor::middle));
    }
    svg.close_group();
}

void draw_y_ticks(SvgWriter& svg, const PlotArea& area, const Ticks& ticks, const Scale& scale) {
    svg.open_group("y-ticks");
    for (const Tick& tick : ticks.major) {
        const double y = scale.pixel(tick.value);
        if (!within(y, area.top, area.bottom)) continue;
        svg.line(area.left - kTickLength, y, area.left, y, stroke_paint("black"));
        svg.text(area.left - 10.0, y + 4.0, tick.label, text_style(TextAnchor::end));
    }
    svg.close_group();
}

void draw_category_ticks(SvgWriter& svg, const PlotArea& area,
                         const std::vector<std::string>& categories) {
    if (categories.empty()) return;
    const double band = area.width() / static_cast<double>(categories.size());
    svg.open_group("x-ticks");
    for (std::size_t i = 0; i < categories.size(); ++i) {
        const double x = area.left + band * (static_cast<double>(i) + 0.5);
        svg.line(x, area.bottom, x, area.bottom + kTickLength, stroke_paint("black"));
        svg.text(x, area.bottom + 22.0, categories[i], text_style(TextAnchor::middle));
    }
    svg.close_group();
}

void draw_axis_labels(SvgWriter& svg, const PlotArea& area, const std::string& x_label,
                      const std::string& y_label) {
    if (!x_label.empty()) {
        svg.text((area.left + area.right) / 2.0, area.bottom + 48.0, x_label,
                 text_style(TextAnchor::middle));
    }
    if (!y_label.empty()) {
        TextStyle rotated = text_style(TextAnchor::middle);
        rotated.rotate_degrees = -90.0;
        svg.text(area.left - 52.0, (area.top + area.bottom) / 2.0, y_label, rotated);
    }
}

void draw_reference_lines(SvgWriter& svg, const PlotArea& area, const Ticks& y_ticks,
                          const Scale& y_scale, const std::vector<ReferenceLine>& lines) {
    bool opened = false;
    for (const ReferenceLine& reference : lines) {
        if (!y_scale.maps(reference.y) || reference.y < y_ticks.min || reference.y > y_ticks.max) {
            continue;
        }
        if (!opened) {
            svg.open_group("reference-lines");
            opened = true;
        }
        const double y = y_scale.pixel(reference.y);
        svg.line(area.left, y, area.right, y, stroke_paint(reference.color, 1.5, "6 4"));
        if (!reference.label.empty()) {
            svg.text(area.right - 4.0, y - 5.0, reference.label,
                     text_style(TextAnchor::end, 12.0, reference.color));
        }
    }
    if (opened) svg.close_group();
}

void draw_marker(SvgWriter& svg, MarkerShape shape, double x, double y, const std::string& color) {
    // A thin white outline keeps overlapping markers apart.
    const Paint paint = fill_paint(color, "white", 0.75);
    switch (shape) {
        case MarkerShape::none:
            return;
        case MarkerShape::circle:
            svg.circle(x, y, 3.5, paint);
            return;
        case MarkerShape::square:
            svg.rect(x - 3.25, y - 3.25, 6.5, 6.5, paint);
            return;
        case MarkerShape::triangle:
            svg.polygon({{x, y - 4.5}, {x + 4.25, y + 3.0}, {x - 4.25, y + 3.0}}, paint);
            return;
        case MarkerShape::diamond:
            svg.polygon({{x, y - 4.5}, {x + 4.0, y}, {x, y + 4.5}, {x - 4.0, y}}, paint);
            return;
    }
}

void draw_plot_frame(SvgWriter& svg, const PlotArea& area) {
    svg.rect(area.left, area.top, area.width(), area.height(), fill_paint("none", "black"));
}

void draw_legend(SvgWriter& svg, const PlotArea& area, const std::vector<LegendEntry>& entries) {
    if (entries.empty()) return;
    const double x = area.right + 20.0;
    svg.open_group("legend");
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const LegendEntry& entry = entries[i];
        const double y = area.top + 12.0 + 22.0 * static_cast<double>(i);
        if (entry.swatch) {
            svg.rect(x + 7.0, y - 7.0, 14.0, 14.0, fill_paint(entry.color));
        } else {
            if (entry.line) {
                svg.line(x, y, x + 28.0, y, stroke_paint(entry.color, 3.0, entry.dash));
            }
            draw_marker(svg, entry.marker, x + 14.0, y, entry.color);
        }
        svg.text(x + 34.0, y + 4.0, entry.label);
    }
    svg.close_group();
}

void draw_no_data(SvgWriter& svg, const PlotArea& area) {
    draw_plot_frame(svg, area);
    svg.text((area.left + area.right) / 2.0, (area.top + area.bottom) / 2.0, "no data",
             text_style(TextAnchor::middle, 15.0, "#777"));
}

std::string clip_id(const PlotArea& area) {
    // Decimal points and minus signs are legal in ids but read badly inside url(#...): written
    // as 'p' and 'm', with '_' between the numbers.
    const auto encoded = [](double value) {
        std::string text = format_number(value);
        std::replace(text.begin(), text.end(), '.', 'p');
        std::replace(text.begin(), text.end(), '-', 'm');
        return text;
    };
    return "plot_" + encoded(area.left) + "_" + encoded(area.top) + "_" + encoded(area.width()) +
           "_" + encoded(area.height());
}

}  // namespace monoplane::charts
