// SVG -> PNG (charts/png): a chart rasterizes at its size (and at twice it), is not blank (text,
// lines and coloured marks are drawn), and a PNG file is written; bad input is an error.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "charts/line_chart.h"
#include "charts/png/svg_to_png.h"

namespace monoplane::charts {
namespace {

std::string chart_svg() {
    LineChart chart;
    chart.text.title = "Decisions for hybrid";
    chart.x_axis.label = "m (metres)";
    chart.y_axis.label = "hybrid chosen (%)";
    chart.y_axis.min = 0.0;
    chart.y_axis.max = 100.0;
    LineSeries series;
    series.name = "BEAMS";
    for (double m : {1.6, 3.0, 8.0, 16.0, 39.5}) {
        series.points.push_back(
            {m, 30.0 + m / 2.0, ErrorRange{20.0 + m / 2.0, 40.0 + m / 2.0}, ""});
    }
    chart.series.push_back(series);
    chart.reference_lines.push_back({50.0, "50 %", "#000000"});
    return render_svg(chart);
}

struct Counts {
    int non_white = 0;
    int dark = 0;  // text and axes
    int blue = 0;  // the series (#0072B2)
};

Counts count(const RgbaImage& image) {
    Counts c;
    for (std::size_t i = 0; i + 3 < image.pixels.size(); i += 4) {
        const int r = image.pixels[i], g = image.pixels[i + 1], b = image.pixels[i + 2];
        if (r < 250 || g < 250 || b < 250) ++c.non_white;
        if (r < 80 && g < 80 && b < 80) ++c.dark;
        if (r < 60 && g > 80 && g < 150 && b > 140) ++c.blue;
    }
    return c;
}

TEST(SvgToPng, ChartHasItsSizeAndIsNotBlank) {
    const auto image = rasterize_svg(chart_svg());
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_EQ(image->width, 800);
    EXPECT_EQ(image->height, 480);
    ASSERT_EQ(image->pixels.size(), 800u * 480u * 4u);
    const Counts c = count(*image);
    EXPECT_GT(c.non_white, 800 * 480 / 50);  // a plot, not a white page
    EXPECT_LT(c.non_white, 800 * 480 / 2);   // and not a black one
    EXPECT_GT(c.dark, 500);                  // text, frame, the 50 % line
    EXPECT_GT(c.blue, 200);                  // the series
    // Opaque everywhere: the charts paint a white background.
    for (std::size_t i = 3; i < image->pixels.size(); i += 4) ASSERT_EQ(image->pixels[i], 255);
}

TEST(SvgToPng, ScaleTwoDoublesTheSize) {
    const auto image = rasterize_svg(chart_svg(), 2.0);
    ASSERT_TRUE(image) << image.error().message;
    EXPECT_EQ(image->width, 1600);
    EXPECT_EQ(image->height, 960);
}

TEST(SvgToPng, WritesAPngFile) {
    const auto path = std::filesystem::temp_directory_path() / "monoplane_report_png_test.png";
    std::filesystem::remove(path);
    const auto ok = write_svg_as_png(chart_svg(), path);
    ASSERT_TRUE(ok) << ok.error().message;
    std::ifstream in(path, std::ios::binary);
    const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                           std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 33u);
    const unsigned char signature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
    EXPECT_TRUE(std::equal(std::begin(signature), std::end(signature), bytes.begin()));
    // IHDR: big-endian width and height at bytes 16 and 20.
    const auto be32 = [&](std::size_t at) {
        return (std::uint32_t(bytes[at]) << 24) | (std::uint32_t(bytes[at + 1]) << 16) |
               (std::uint32_t(bytes[at + 2]) << 8) | std::uint32_t(bytes[at + 3]);
    };
    EXPECT_EQ(be32(16), 800u);
    EXPECT_EQ(be32(20), 480u);
    std::filesystem::remove(path);
}

TEST(SvgToPng, BadInputIsAnError) {
    EXPECT_FALSE(rasterize_svg("this is not svg"));
    EXPECT_FALSE(rasterize_svg(chart_svg(), 0.0));
    const auto bad = write_svg_as_png(chart_svg(), "/nonexistent-dir/x.png");
    ASSERT_FALSE(bad);
    EXPECT_NE(bad.error().message.find("/nonexistent-dir/x.png"), std::string::npos);
}

}  // namespace
}  // namespace monoplane::charts
