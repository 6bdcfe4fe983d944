// The charts library: tick positions and labels, the data-to-pixel mapping, and the SVG documents
// themselves, read back with a small XML reader that also proves them well formed. Expected pixel
// positions are worked out by hand from the layouts given here.
#include <gtest/gtest-spi.h>
#include <gtest/gtest.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "charts/axis.h"
#include "charts/bar_chart.h"
#include "charts/chart_frame.h"
#include "charts/line_chart.h"
#include "charts/palette.h"
#include "charts/svg_writer.h"

namespace monoplane::charts {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// --- a minimal XML reader: enough for the documents the library writes ------------------------

struct Element {
    std::string name;
    std::map<std::string, std::string> attributes;
    std::string text;   // character data directly inside, entities left as written
    std::string group;  // class of the innermost enclosing <g class=...>, "" if none
    double number(const std::string& attribute) const {
        return std::stod(attributes.at(attribute));
    }
};

// Character data and attribute values may hold '&' only as one of XML's five entities, and never
// '<'.
bool valid_character_data(const std::string& text) {
    if (text.find('<') != std::string::npos) return false;
    for (std::size_t at = text.find('&'); at != std::string::npos; at = text.find('&', at + 1)) {
        bool known = false;
        for (const char* entity : {"&amp;", "&lt;", "&gt;", "&quot;", "&apos;"}) {
            known = known || text.compare(at, std::char_traits<char>::length(entity), entity) == 0;
        }
        if (!known) return false;
    }
    return true;
}

// Parses `svg` into its elements in document order; fails the test (and returns what it has) if
// the document is not well formed: one root <svg>, tags nested and closed, text escaped.
std::vector<Element> parse_svg(const std::string& svg) {
    std::vector<Element> elements;
    std::vector<std::size_t> open;  // indices into elements
    std::vector<std::string> group_classes;
    std::size_t roots = 0;
    std::size_t at = 0;
    const auto fail = [&](const std::string& why) {
        ADD_FAILURE() << why << " at offset " << at << ": " << svg.substr(at, 60);
        return elements;
    };
    while (at < svg.size()) {
        if (svg[at] != '<') {
            const std::size_t next = svg.find('<', at);
            const std::string text = svg.substr(at, next - at);
            if (!valid_character_data(text)) return fail("unescaped character data");
            if (open.empty()) {
                if (text.find_first_not_of(" \n") != std::string::npos) {
                    return fail("text outside the root");
                }
            } else {
                elements[open.back()].text += text;
            }
            at = next == std::string::npos ? svg.size() : next;
            continue;
        }
        if (svg.compare(at, 2, "</") == 0) {
            const std::size_t end = svg.find('>', at);
            if (end == std::string::npos) return fail("unterminated end tag");
            const std::string name = svg.substr(at + 2, end - at - 2);
            if (open.empty() || elements[open.back()].name != name)
                return fail("mismatched </" + name);
            if (name == "g") group_classes.pop_back();
            open.pop_back();
            at = end + 1;
            continue;
        }
        Element element;
        std::size_t i = at + 1;
        while (i < svg.size() && (std::isalnum(static_cast<unsigned char>(svg[i])) ||
                                  svg[i] == '-' || svg[i] == ':')) {
            element.name += svg[i++];
        }
        if (element.name.empty()) return fail("bad tag");
        bool self_closing = false;
        while (true) {
            while (i < svg.size() && svg[i] == ' ') ++i;
            if (i >= svg.size()) return fail("unterminated tag");
            if (svg[i] == '>') {
                ++i;
                break;
            }
            if (svg.compare(i, 2, "/>") == 0) {
                self_closing = true;
                i += 2;
                break;
            }
            const std::size_t equals = svg.find("=\"", i);
            if (equals == std::string::npos) return fail("bad attribute");
            const std::string name = svg.substr(i, equals - i);
            const std::size_t close = svg.find('"', equals + 2);
            if (close == std::string::npos) return fail("unterminated attribute");
            const std::string value = svg.substr(equals + 2, close - equals - 2);
            if (!valid_character_data(value)) return fail("unescaped attribute " + name);
            if (name.find_first_of(" <>\"") != std::string::npos) return fail("bad attribute name");
            if (!element.attributes.emplace(name, value).second) return fail("repeated " + name);
            i = close + 1;
        }
        if (open.empty()) {
            ++roots;
            if (element.name != "svg") return fail("root is not <svg>");
        }
        element.group = group_classes.empty() ? "" : group_classes.back();
        elements.push_back(element);
        if (!self_closing) {
            open.push_back(elements.size() - 1);
            if (element.name == "g") {
                const auto css = element.attributes.find("class");
                group_classes.push_back(css == element.attributes.end() ? element.group
                                                                        : css->second);
            }
        }
        at = i;
    }
    EXPECT_TRUE(open.empty()) << "unclosed elements";
    EXPECT_EQ(roots, 1u);
    return elements;
}

std::vector<Element> all_named(const std::vector<Element>& elements, const std::string& name,
                               const std::string& group = "*") {
    std::vector<Element> found;
    for (const Element& e : elements) {
        if (e.name == name && (group == "*" || e.group == group)) found.push_back(e);
    }
    return found;
}

bool has_text(const std::vector<Element>& elements, const std::string& text) {
    for (const Element& e : all_named(elements, "text")) {
        if (e.text == text) return true;
    }
    return false;
}

std::vector<double> tick_values(const Ticks& ticks) {
    std::vector<double> values;
    for (const Tick& tick : ticks.major) values.push_back(tick.value);
    return values;
}

std::vector<std::string> tick_labels(const Ticks& ticks) {
    std::vector<std::string> labels;
    for (const Tick& tick : ticks.major) labels.push_back(tick.label);
    return labels;
}

// A layout with round numbers: plot area x 80..580, y 40..340, no legend.
Layout test_layout() {
    Layout layout;
    layout.width = 600.0;
    layout.height = 400.0;
    layout.margins = {80.0, 20.0, 40.0, 60.0};
    layout.legend = LegendPosition::none;
    return layout;
}

// The reader must reject what a browser would: otherwise "well formed" below proves nothing.
TEST(ChartsTestReader, RejectsMalformedDocuments) {
    EXPECT_NONFATAL_FAILURE(parse_svg("<svg><text>a & b</text></svg>"), "unescaped");
    EXPECT_NONFATAL_FAILURE(parse_svg("<svg><text>a < b</text></svg>"), "bad tag");
    EXPECT_NONFATAL_FAILURE(parse_svg("<svg><g></svg>"), "mismatched");
    EXPECT_NONFATAL_FAILURE(parse_svg("<svg><text x=\"<\">a</text></svg>"), "unescaped");
    EXPECT_NONFATAL_FAILURE(parse_svg("<svg><g>"), "unclosed");
    EXPECT_EQ(parse_svg("<svg a=\"1\"><text>x &amp; y</text></svg>\n").size(), 2u);
}

// --- numbers and text -----------------------------------------------------------------------

TEST(ChartsFormat, NumbersAreFixedPrecisionAndTrimmed) {
    EXPECT_EQ(format_number(330.0), "330");
    EXPECT_EQ(format_number(2.5), "2.5");
    EXPECT_EQ(format_number(1.0 / 3.0), "0.33");
    EXPECT_EQ(format_number(2.0 / 3.0, 3), "0.667");
    EXPECT_EQ(format_number(-0.001), "0");
    EXPECT_EQ(format_number(-12.345678, 4), "-12.3457");
    EXPECT_EQ(format_number(1e7), "10000000");
    EXPECT_EQ(format_fixed(0.5, 2), "0.50");
    EXPECT_EQ(format_fixed(-0.0001, 2), "0.00");
    EXPECT_EQ(format_fixed(40.0, 0), "40");
}

TEST(ChartsFormat, XmlEscaping) {
    EXPECT_EQ(xml_escaped("a < b & c > \"d\" 'e'"),
              "a &lt; b &amp; c &gt; &quot;d&quot; &apos;e&apos;");
    // Control characters XML forbids are dropped; tab, newline and UTF-8 pass.
    EXPECT_EQ(xml_escaped(std::string("x\x01y\tz\n\xc2\xb5s")), "xy\tz\n\xc2\xb5s");
}

TEST(ChartsPalette, OkabeItoThenDashedRounds) {
    EXPECT_EQ(series_look(0).color, "#0072B2");
    EXPECT_EQ(series_look(0).dash, "");
    EXPECT_EQ(series_look(1).color, "#E69F00");
    EXPECT_EQ(series_look(8).color, series_look(0).color);
    EXPECT_NE(series_look(8).dash, "");
    EXPECT_NE(series_look(16).dash, series_look(8).dash);
}

// --- ticks and scales ------------------------------------------------------------------------

TEST(ChartsAxis, NiceStepIsOneTwoOrFiveTimesAPowerOfTen) {
    EXPECT_DOUBLE_EQ(nice_step(37.0, 5), 10.0);
    EXPECT_DOUBLE_EQ(nice_step(0.074, 5), 0.02);
    EXPECT_DOUBLE_EQ(nice_step(10.0, 5), 2.0);
    EXPECT_DOUBLE_EQ(nice_step(1.0, 5), 0.2);
    EXPECT_DOUBLE_EQ(nice_step(100.0, 4), 50.0);
    EXPECT_DOUBLE_EQ(nice_step(7.0, 1), 10.0);
    EXPECT_DOUBLE_EQ(nice_step(17.23, 6), 5.0);  // the Fig. 2 y axis
}

TEST(ChartsAxis, ZeroToThirtySevenGivesTensUpToForty) {
    const Ticks ticks = linear_ticks(0.0, 37.0);
    EXPECT_EQ(tick_values(ticks), (std::vector<double>{0, 10, 20, 30, 40}));
    EXPECT_EQ(tick_labels(ticks), (std::vector<std::string>{"0", "10", "20", "30", "40"}));
    EXPECT_EQ(ticks.min, 0.0);
    EXPECT_EQ(ticks.max, 40.0);
    EXPECT_TRUE(ticks.minor.empty());
}

TEST(ChartsAxis, SmallFractionsGetHundredthsSteps) {
    const Ticks ticks = linear_ticks(0.013, 0.087);
    ASSERT_GE(ticks.major.size(), 2u);
    const double step = ticks.major[1].value - ticks.major[0].value;
    EXPECT_TRUE(std::abs(step - 0.01) < 1e-12 || std::abs(step - 0.02) < 1e-12) << step;
    EXPECT_LE(ticks.min, 0.013);
    EXPECT_GE(ticks.max, 0.087);
    EXPECT_GT(ticks.min, 0.013 - step);
    EXPECT_LT(ticks.max, 0.087 + step);
    // With a step of 0.02: 0.00 .. 0.10, each the double nearest its label (0.06, not 3 * 0.02).
    EXPECT_EQ(tick_labels(ticks),
              (std::vector<std::string>{"0.00", "0.02", "0.04", "0.06", "0.08", "0.10"}));
    EXPECT_EQ(ticks.major[3].value, 0.06);
    EXPECT_EQ(ticks.major[5].value, 0.1);
}

TEST(ChartsAxis, NegativeAndOffsetRanges) {
    EXPECT_EQ(tick_values(linear_ticks(-37.0, -3.0)), (std::vector<double>{-40, -30, -20, -10, 0}));
    const Ticks ticks = linear_ticks(1.6, 39.5);
    EXPECT_EQ(ticks.min, 0.0);
    EXPECT_EQ(ticks.max, 40.0);
    EXPECT_EQ(tick_labels(linear_ticks(0.25, 0.75)),
              (std::vector<std::string>{"0.2", "0.3", "0.4", "0.5", "0.6", "0.7", "0.8"}));
}

TEST(ChartsAxis, DegenerateRangesStillGiveAValidAxis) {
    for (const auto& [lo, hi] : std::vector<std::pair<double, double>>{{5.0, 5.0},
                                                                       {0.0, 0.0},
                                                                       {-3.0, -3.0},
                                                                       {1e-9, 1e-9},
                                                                       {kNaN, kNaN},
                                                                       {kInf, -kInf},
                                                                       {7.0, 2.0}}) {
        const Ticks ticks = linear_ticks(lo, hi);
        EXPECT_LT(ticks.min, ticks.max) << lo << ".." << hi;
        EXPECT_GE(ticks.major.size(), 2u) << lo << ".." << hi;
        if (std::isfinite(lo) && lo <= hi) {
            EXPECT_LE(ticks.min, lo);
            EXPECT_GE(ticks.max, hi);
        }
    }
    const Ticks five = linear_ticks(5.0, 5.0);  // widened to 4.5..5.5, step 0.2
    EXPECT_NEAR(five.min, 4.4, 1e-12);
    EXPECT_NEAR(five.max, 5.6, 1e-12);
    const Ticks zero = linear_ticks(0.0, 0.0);
    EXPECT_EQ(zero.min, 0.0);
    EXPECT_EQ(zero.max, 1.0);
}

TEST(ChartsAxis, LogTicksAreDecadesWithMinorMultiples) {
    const Ticks ticks = log_ticks(1.6, 1000.0);
    EXPECT_EQ(ticks.min, 1.0);
    EXPECT_EQ(ticks.max, 1000.0);
    EXPECT_EQ(tick_labels(ticks), (std::vector<std::string>{"1", "10", "100", "1000"}));
    EXPECT_EQ(ticks.minor.size(), 3u * 8u);
    EXPECT_EQ(ticks.minor.front(), 2.0);
    EXPECT_EQ(ticks.minor.back(), 900.0);

    const Ticks fractions = log_ticks(0.013, 0.087);  // one decade: 2 and 5 labelled too
    EXPECT_EQ(tick_labels(fractions), (std::vector<std::string>{"0.01", "0.02", "0.05", "0.1"}));
    EXPECT_EQ(fractions.minor.size(), 6u);

    const Ticks single = log_ticks(10.0, 10.0);
    EXPECT_EQ(single.min, 1.0);
    EXPECT_EQ(single.max, 100.0);
    const Ticks invalid = log_ticks(0.0, -5.0);
    EXPECT_EQ(invalid.min, 1.0);
    EXPECT_EQ(invalid.max, 10.0);
    EXPECT_EQ(log_ticks(1e11, 1e12).major.front().label, "1e11");
}

TEST(ChartsAxis, ResolveHonoursFixedEndsAndZero) {
    AxisSpec spec;
    spec.include_zero = true;
    Ticks ticks = resolve_axis(spec, 3.0, 37.0);
    EXPECT_EQ(ticks.min, 0.0);
    EXPECT_EQ(ticks.max, 40.0);

    spec = {};
    spec.min = 0.5;
    spec.max = 9.5;
    ticks = resolve_axis(spec, 2.0, 7.0);
    EXPECT_EQ(ticks.min, 0.5);
    EXPECT_EQ(ticks.max, 9.5);
    EXPECT_EQ(tick_values(ticks), (std::vector<double>{2, 4, 6, 8}));

    spec = {};
    spec.scale = ScaleKind::log10;
    spec.max = 500.0;
    ticks = resolve_axis(spec, 3.0, 40.0);
    EXPECT_EQ(ticks.min, 1.0);
    EXPECT_EQ(ticks.max, 500.0);
    EXPECT_EQ(tick_labels(ticks), (std::vector<std::string>{"1", "10", "100"}));
    EXPECT_EQ(ticks.minor.back(), 500.0);

    // No data at all: still a usable axis.
    ticks = resolve_axis(AxisSpec{}, kInf, -kInf);
    EXPECT_EQ(ticks.min, 0.0);
    EXPECT_EQ(ticks.max, 1.0);
}

TEST(ChartsAxis, ScalesMapDomainEndsToPixelEnds) {
    const Scale x(ScaleKind::linear, 0.0, 10.0, 80.0, 580.0);
    EXPECT_DOUBLE_EQ(x.pixel(0.0), 80.0);
    EXPECT_DOUBLE_EQ(x.pixel(5.0), 330.0);
    EXPECT_DOUBLE_EQ(x.pixel(10.0), 580.0);
    const Scale y(ScaleKind::linear, 0.0, 100.0, 340.0, 40.0);  // SVG y grows downwards
    EXPECT_DOUBLE_EQ(y.pixel(25.0), 265.0);
    const Scale log_x(ScaleKind::log10, 1.0, 1000.0, 80.0, 720.0);
    EXPECT_NEAR(log_x.pixel(10.0), 80.0 + 640.0 / 3.0, 1e-9);
    EXPECT_NEAR(log_x.pixel(2.0), 80.0 + 640.0 * std::log10(2.0) / 3.0, 1e-9);
    EXPECT_FALSE(log_x.maps(0.0));
    EXPECT_FALSE(x.maps(kNaN));
    EXPECT_TRUE(x.maps(-1.0));
}

// --- line charts -----------------------------------------------------------------------------

TEST(ChartsLine, PlotAreaFollowsMarginsAndLegend) {
    Layout layout = test_layout();
    PlotArea area = plot_area(layout, true);  // legend none: no room taken
    EXPECT_EQ(area.left, 80.0);
    EXPECT_EQ(area.right, 580.0);
    EXPECT_EQ(area.top, 40.0);
    EXPECT_EQ(area.bottom, 340.0);
    layout.legend = LegendPosition::right;
    layout.legend_width = 200.0;
    EXPECT_EQ(plot_area(layout, true).right, 380.0);
    EXPECT_EQ(plot_area(layout, false).right, 580.0);
}

TEST(ChartsLine, AKnownPointLandsOnItsPixel) {
    LineChart chart;
    chart.layout = test_layout();
    chart.x_axis.min = 0.0;
    chart.x_axis.max = 10.0;
    chart.y_axis.min = 0.0;
    chart.y_axis.max = 100.0;
    chart.series.push_back(
        {"s", {{5.0, 25.0, {}, ""}, {10.0, 100.0, {}, ""}}, true, MarkerShape::circle, ""});
    const std::vector<Element> svg = parse_svg(render_svg(chart));
    const std::vector<Element> circles = all_named(svg, "circle", "series");
    ASSERT_EQ(circles.size(), 2u);
    EXPECT_DOUBLE_EQ(circles[0].number("cx"), 330.0);
    EXPECT_DOUBLE_EQ(circles[0].number("cy"), 265.0);
    EXPECT_DOUBLE_EQ(circles[1].number("cx"), 580.0);
    EXPECT_DOUBLE_EQ(circles[1].number("cy"), 40.0);
    const std::vector<Element> lines = all_named(svg, "polyline");
    ASSERT_EQ(lines.size(), 1u);
    EXPECT_EQ(lines[0].attributes.at("points"), "330,265 580,40");
    EXPECT_EQ(lines[0].attributes.at("stroke"), "#0072B2");
    // The y tick at 60 sits 180 px above the bottom; its label 4 px lower, to centre it.
    bool found = false;
    for (const Element& text : all_named(svg, "text", "y-ticks")) {
        if (text.text == "60") {
            found = true;
            EXPECT_DOUBLE_EQ(text.number("y"), 164.0);
            EXPECT_DOUBLE_EQ(text.number("x"), 70.0);
        }
    }
    EXPECT_TRUE(found);
}

TEST(ChartsLine, LogXPutsDecadesAtEqualSpacing) {
    LineChart chart;
    chart.layout = test_layout();
    chart.x_axis.scale = ScaleKind::log10;
    chart.series.push_back({"",
                            {{1.0, 0.0, {}, ""}, {10.0, 1.0, {}, ""}, {100.0, 2.0, {}, ""}},
                            true,
                            MarkerShape::none,
                            ""});
    const std::vector<Element> svg = parse_svg(render_svg(chart));
    const std::vector<Element> lines = all_named(svg, "polyline");
    ASSERT_EQ(lines.size(), 1u);
    // x domain 1..100, y domain 0..2: the middle point is the plot's centre.
    EXPECT_EQ(lines[0].attributes.at("points"), "80,340 330,190 580,40");
    EXPECT_TRUE(all_named(svg, "circle").empty());
    EXPECT_EQ(all_named(svg, "line", "grid").size(), 3u + 8u * 2u + 5u);  // x major, minor; y
}

LineChart three_series_chart() {
    LineChart chart;
    chart.text = {"Primitives per view", "vive, BEAMS", "monoplane bench"};
    chart.x_axis.label = "mono-plane distance m (m)";
    chart.y_axis.label = "primitives (millions)";
    chart.y_axis.include_zero = true;
    const std::vector<double> m = {1.6, 3, 5, 8, 12};
    const char* names[] = {"left eye", "right eye", "centre view C"};
    for (int s = 0; s < 3; ++s) {
        LineSeries series;
        series.name = names[s];
        for (double distance : m)
            series.points.push_back({distance, (s + 1) * 10.0 / distance, {}, ""});
        chart.series.push_back(series);
    }
    return chart;
}

TEST(ChartsLine, OnePolylinePerSeriesAndALegendEntryEach) {
    const LineChart chart = three_series_chart();
    const std::vector<Element> svg = parse_svg(render_svg(chart));
    EXPECT_EQ(all_named(svg, "polyline").size(), chart.series.size());
    EXPECT_EQ(all_named(svg, "circle", "series").size(), 15u);
    const std::vector<Element> legend_texts = all_named(svg, "text", "legend");
    ASSERT_EQ(legend_texts.size(), 3u);
    EXPECT_EQ(legend_texts[0].text, "left eye");
    EXPECT_EQ(legend_texts[1].text, "right eye");
    EXPECT_EQ(legend_texts[2].text, "centre view C");
    // Legend samples use the series' colours, in order.
    const std::vector<Element> legend_lines = all_named(svg, "line", "legend");
    ASSERT_EQ(legend_lines.size(), 3u);
    EXPECT_EQ(legend_lines[1].attributes.at("stroke"), series_look(1).color);
    EXPECT_TRUE(has_text(svg, "Primitives per view"));
    EXPECT_TRUE(has_text(svg, "vive, BEAMS"));
    EXPECT_TRUE(has_text(svg, "monoplane bench"));
    EXPECT_TRUE(has_text(svg, "mono-plane distance m (m)"));
    EXPECT_TRUE(has_text(svg, "primitives (millions)"));
    // The default layout (800 px wide) gives the legend 220 px on the right: plot 80..560.
    EXPECT_EQ(all_named(svg, "rect", "").back().attributes.at("width"), "480");
}

TEST(ChartsLine, OutputIsDeterministic) {
    EXPECT_EQ(render_svg(three_series_chart()), render_svg(three_series_chart()));
}

TEST(ChartsLine, TitlesAreEscaped) {
    LineChart chart = three_series_chart();
    chart.text.title = "time < 5 ms & error > 0";
    chart.series[0].name = "<script>";
    const std::string svg = render_svg(chart);
    EXPECT_NE(svg.find("time &lt; 5 ms &amp; error &gt; 0"), std::string::npos);
    EXPECT_EQ(svg.find("time < 5"), std::string::npos);
    EXPECT_EQ(svg.find("<script>"), std::string::npos);
    const std::vector<Element> elements = parse_svg(svg);
    EXPECT_TRUE(has_text(elements, "time &lt; 5 ms &amp; error &gt; 0"));
}

TEST(ChartsLine, ErrorBarsAndAReferenceLine) {
    LineChart chart;
    chart.layout = test_layout();
    chart.y_axis.min = 0.0;
    chart.y_axis.max = 1.0;
    chart.x_axis.min = 0.0;
    chart.x_axis.max = 40.0;
    LineSeries hybrid;
    hybrid.name = "SPHERES";
    hybrid.points = {{10.0, 0.6, ErrorRange{0.4, 0.8}, ""}, {20.0, 0.5, std::nullopt, ""}};
    chart.series.push_back(hybrid);
    chart.reference_lines.push_back({0.5, "chance (50 %)", "#555555"});
    const std::vector<Element> svg = parse_svg(render_svg(chart));

    // Error bar at x = 80 + 10/40 * 500 = 205 from y(0.4) = 220 to y(0.8) = 100, with caps.
    const std::vector<Element> bars = all_named(svg, "line", "series");
    ASSERT_EQ(bars.size(), 3u);
    EXPECT_DOUBLE_EQ(bars[0].number("x1"), 205.0);
    EXPECT_DOUBLE_EQ(bars[0].number("y1"), 220.0);
    EXPECT_DOUBLE_EQ(bars[0].number("y2"), 100.0);
    EXPECT_DOUBLE_EQ(bars[1].number("x1"), 201.0);
    EXPECT_DOUBLE_EQ(bars[1].number("x2"), 209.0);

    const std::vector<Element> reference = all_named(svg, "line", "reference-lines");
    ASSERT_EQ(reference.size(), 1u);
    EXPECT_DOUBLE_EQ(reference[0].number("y1"), 190.0);
    EXPECT_DOUBLE_EQ(reference[0].number("x1"), 80.0);
    EXPECT_DOUBLE_EQ(reference[0].number("x2"), 580.0);
    EXPECT_FALSE(reference[0].attributes.at("stroke-dasharray").empty());
    EXPECT_TRUE(has_text(svg, "chance (50 %)"));
}

TEST(ChartsLine, ReferenceLineAndErrorBarsWidenAnAutomaticAxis) {
    LineChart chart;
    LineSeries series;
    series.points = {{1.0, 0.7, ErrorRange{0.62, 0.97}, ""}, {2.0, 0.8, std::nullopt, ""}};
    chart.series.push_back(series);
    chart.reference_lines.push_back({0.5, "50 %", "#555555"});
    const std::vector<Element> svg = parse_svg(render_svg(chart));
    std::vector<std::string> labels;
    for (const Element& text : all_named(svg, "text", "y-ticks")) labels.push_back(text.text);
    ASSERT_FALSE(labels.empty());
    EXPECT_EQ(labels.front(), "0.5");
    EXPECT_EQ(labels.back(), "1.0");
    EXPECT_EQ(all_named(svg, "line", "reference-lines").size(), 1u);
}

TEST(ChartsLine, ScatterWithLabels) {
    LineChart chart;
    chart.layout = test_layout();
    chart.x_axis.min = 0.0;
    chart.x_axis.max = 10.0;
    chart.y_axis.min = 0.0;
    chart.y_axis.max = 100.0;
    LineSeries scatter;
    scatter.name = "BEAMS";
    scatter.connect = false;
    scatter.marker = MarkerShape::square;
    scatter.points = {{5.0, 25.0, {}, "m = 8"}, {2.0, 50.0, {}, "m = 1.6 & <near>"}};
    chart.series.push_back(scatter);
    const std::vector<Element> svg = parse_svg(render_svg(chart));
    EXPECT_TRUE(all_named(svg, "polyline").empty());
    const std::vector<Element> markers = all_named(svg, "rect", "series");
    ASSERT_EQ(markers.size(), 2u);
    EXPECT_DOUBLE_EQ(markers[0].number("x") + markers[0].number("width") / 2.0, 330.0);
    EXPECT_DOUBLE_EQ(markers[0].number("y") + markers[0].number("height") / 2.0, 265.0);
    const std::vector<Element> labels = all_named(svg, "text", "point-labels");
    ASSERT_EQ(labels.size(), 2u);
    EXPECT_EQ(labels[0].text, "m = 8");
    EXPECT_DOUBLE_EQ(labels[0].number("x"), 336.0);
    EXPECT_DOUBLE_EQ(labels[0].number("y"), 259.0);
    EXPECT_EQ(labels[1].text, "m = 1.6 &amp; &lt;near&gt;");
}

TEST(ChartsLine, NonFiniteValuesAreSkippedAndBreakTheLine) {
    LineChart chart;
    chart.layout = test_layout();
    LineSeries series;
    series.name = "with gaps";
    series.points = {{1.0, 1.0, {}, ""},  {2.0, 2.0, {}, ""},
                     {3.0, kNaN, {}, ""}, {kInf, 3.0, {}, ""},
                     {4.0, 4.0, {}, ""},  {5.0, 5.0, ErrorRange{kNaN, 6.0}, ""}};
    chart.series.push_back(series);
    LineSeries all_bad;
    all_bad.name = "all bad";
    all_bad.points = {{kNaN, kNaN, {}, ""}, {-kInf, 1.0, {}, ""}};
    chart.series.push_back(all_bad);
    const std::string text = render_svg(chart);
    EXPECT_EQ(text.find("nan"), std::string::npos);
    EXPECT_EQ(text.find("inf"), std::string::npos);
    const std::vector<Element> svg = parse_svg(text);
    const std::vector<Element> lines = all_named(svg, "polyline");
    ASSERT_EQ(lines.size(), 2u);  // 1-2, then 4-5
    EXPECT_EQ(all_named(svg, "circle", "series").size(), 4u);
    EXPECT_TRUE(all_named(svg, "line", "series").empty());  // the NaN error bar is left out
    // The axes cover the finite points only: x 1..5, y 1..5.
    EXPECT_EQ(all_named(svg, "text", "x-ticks").front().text, "1");
    EXPECT_EQ(all_named(svg, "text", "x-ticks").back().text, "5");
}

TEST(ChartsLine, LogYSkipsNonPositiveValues) {
    LineChart chart;
    chart.y_axis.scale = ScaleKind::log10;
    LineSeries series;
    series.points = {
        {1.0, 0.0, {}, ""}, {2.0, 10.0, {}, ""}, {3.0, 1000.0, {}, ""}, {4.0, -1.0, {}, ""}};
    chart.series.push_back(series);
    const std::vector<Element> svg = parse_svg(render_svg(chart));
    EXPECT_EQ(all_named(svg, "circle", "series").size(), 2u);
    std::vector<std::string> labels;
    for (const Element& text : all_named(svg, "text", "y-ticks")) labels.push_back(text.text);
    EXPECT_EQ(labels, (std::vector<std::string>{"10", "100", "1000"}));
}

TEST(ChartsLine, EmptyChartSaysNoData) {
    LineChart chart;
    chart.text.title = "Time against error";
    chart.x_axis.label = "SSIM error";
    const std::vector<Element> empty = parse_svg(render_svg(chart));
    EXPECT_TRUE(has_text(empty, "no data"));
    EXPECT_TRUE(has_text(empty, "Time against error"));
    EXPECT_TRUE(all_named(empty, "polyline").empty());
    EXPECT_TRUE(all_named(empty, "text", "legend").empty());

    LineSeries nothing_finite;
    nothing_finite.name = "BEAMS";
    nothing_finite.points = {{kNaN, 1.0, {}, ""}};
    chart.series.push_back(nothing_finite);
    chart.series.push_back(LineSeries{});
    const std::vector<Element> svg = parse_svg(render_svg(chart));
    EXPECT_TRUE(has_text(svg, "no data"));
    EXPECT_TRUE(all_named(svg, "text", "legend").empty());
}

// --- stacked bars ----------------------------------------------------------------------------

StackedBarChart two_by_two_bars() {
    StackedBarChart chart;
    chart.layout = test_layout();
    chart.categories = {"1.6", "3"};
    chart.x_label = "m (m)";
    chart.y_axis.label = "GPU time (ms)";
    chart.components = {{"near (stereo)", {2.0, 4.0}, ""}, {"far (mono)", {3.0, 1.0}, ""}};
    return chart;
}

TEST(ChartsBar, ComponentsStackAndScaleWithTheirValues) {
    // Totals 5 and 5: y 0..5, 60 px per ms from y = 340 up. Bands 250 px, bars 150 px wide.
    const std::vector<Element> svg = parse_svg(render_svg(two_by_two_bars()));
    const std::vector<Element> rects = all_named(svg, "rect", "bars");
    ASSERT_EQ(rects.size(), 4u);  // component by component: near 1.6, near 3, far 1.6, far 3
    const Element& near0 = rects[0];
    const Element& far0 = rects[2];
    EXPECT_DOUBLE_EQ(near0.number("x"), 130.0);
    EXPECT_DOUBLE_EQ(near0.number("width"), 150.0);
    EXPECT_DOUBLE_EQ(near0.number("y") + near0.number("height"), 340.0);
    EXPECT_DOUBLE_EQ(near0.number("height"), 120.0);
    EXPECT_DOUBLE_EQ(far0.number("y") + far0.number("height"), near0.number("y"));
    EXPECT_DOUBLE_EQ(far0.number("height"), 180.0);
    EXPECT_DOUBLE_EQ(far0.number("x"), near0.number("x"));
    // Second category: 4 then 1.
    EXPECT_DOUBLE_EQ(rects[1].number("x"), 380.0);
    EXPECT_DOUBLE_EQ(rects[1].number("height") / rects[3].number("height"), 4.0);
    EXPECT_DOUBLE_EQ(rects[3].number("y") + rects[3].number("height"), rects[1].number("y"));
    EXPECT_TRUE(has_text(svg, "1.6"));
    EXPECT_TRUE(has_text(svg, "GPU time (ms)"));
}

TEST(ChartsBar, StackingIsExactWithUnevenValues) {
    StackedBarChart chart = two_by_two_bars();
    chart.components = {{"a", {0.37}, ""}, {"b", {1.234}, ""}, {"c", {0.111}, ""}};
    chart.categories = {"x"};
    const std::vector<Element> rects = all_named(parse_svg(render_svg(chart)), "rect", "bars");
    ASSERT_EQ(rects.size(), 3u);
    for (std::size_t i = 1; i < rects.size(); ++i) {
        EXPECT_NEAR(rects[i].number("y") + rects[i].number("height"), rects[i - 1].number("y"),
                    1e-9);
    }
    EXPECT_NEAR(rects[1].number("height") / rects[0].number("height"), 1.234 / 0.37, 0.01);
}

TEST(ChartsBar, LegendListsTheTopComponentFirstThenLines) {
    StackedBarChart chart = two_by_two_bars();
    chart.layout.legend = LegendPosition::right;
    chart.lines.push_back({"stereo total", {6.0, 6.5}, MarkerShape::diamond, ""});
    chart.reference_lines.push_back({5.5, "budget", "#555555"});
    chart.total_decimals = 1;
    const std::vector<Element> svg = parse_svg(render_svg(chart));
    const std::vector<Element> legend = all_named(svg, "text", "legend");
    ASSERT_EQ(legend.size(), 3u);
    EXPECT_EQ(legend[0].text, "far (mono)");
    EXPECT_EQ(legend[1].text, "near (stereo)");
    EXPECT_EQ(legend[2].text, "stereo total");
    const std::vector<Element> swatches = all_named(svg, "rect", "legend");
    ASSERT_EQ(swatches.size(), 2u);
    EXPECT_EQ(swatches[0].attributes.at("fill"), series_look(1).color);
    EXPECT_EQ(all_named(svg, "polyline").size(), 1u);
    EXPECT_EQ(all_named(svg, "polygon", "series").size(), 2u);  // diamonds
    EXPECT_EQ(all_named(svg, "line", "reference-lines").size(), 1u);
    const std::vector<Element> totals = all_named(svg, "text", "totals");
    ASSERT_EQ(totals.size(), 2u);
    EXPECT_EQ(totals[0].text, "5.0");
    // The line (6.5 at most) widens the axis beyond the stacks: 0..8 in steps of 2.
    EXPECT_EQ(all_named(svg, "text", "y-ticks").back().text, "8");
}

TEST(ChartsBar, BadValuesAreLeftOut) {
    StackedBarChart chart = two_by_two_bars();
    chart.components[0].values = {kNaN, -1.0};
    chart.components[1].values = {3.0};  // shorter than the categories
    const std::string text = render_svg(chart);
    EXPECT_EQ(text.find("nan"), std::string::npos);
    const std::vector<Element> rects = all_named(parse_svg(text), "rect", "bars");
    ASSERT_EQ(rects.size(), 1u);
    EXPECT_DOUBLE_EQ(rects[0].number("y") + rects[0].number("height"), 340.0);
}

TEST(ChartsBar, EmptyChartSaysNoData) {
    StackedBarChart chart;
    chart.text.title = "GPU time per pass";
    const std::vector<Element> no_categories = parse_svg(render_svg(chart));
    EXPECT_TRUE(has_text(no_categories, "no data"));
    chart.categories = {"1.6", "3"};
    chart.components = {{"near", {kNaN, kInf}, ""}};
    const std::vector<Element> nothing_finite = parse_svg(render_svg(chart));
    EXPECT_TRUE(has_text(nothing_finite, "no data"));
    EXPECT_TRUE(all_named(nothing_finite, "rect", "bars").empty());
}

// --- files -----------------------------------------------------------------------------------

TEST(ChartsFile, WritesAndReportsFailures) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "charts_test_file";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string svg = render_svg(three_series_chart());
    const Result<void> written = write_svg_file(dir / "figure.svg", svg);
    ASSERT_TRUE(written.ok()) << written.error().message;
    std::ifstream in(dir / "figure.svg", std::ios::binary);
    std::stringstream back;
    back << in.rdbuf();
    EXPECT_EQ(back.str(), svg);

    const Result<void> failed = write_svg_file(dir / "missing" / "figure.svg", svg);
    ASSERT_FALSE(failed.ok());
    EXPECT_NE(failed.error().message.find("missing/figure.svg"), std::string::npos);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace monoplane::charts
