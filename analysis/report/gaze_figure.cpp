#include "analysis/report/gaze_figure.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "analysis/report/html_format.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {
namespace {

using charts::format_number;
using charts::xml_escaped;

constexpr double kImageWidth = 540.0;  // user units of the picture's area
constexpr double kTop = 58.0;          // title and subtitle above the picture
constexpr double kBottom = 56.0;       // colour bar and note below
// Bins below this share of the peak are left clear: the picture shows through where nobody
// looked.
constexpr double kClearBelow = 0.03;

// The picture's area: the scene image's aspect where there is one, else the eye's frustum's.
double image_height(const SeatEye& eye, const std::optional<SceneImage>& image) {
    if (image && image->width > 0 && image->height > 0)
        return kImageWidth * image->height / image->width;
    return kImageWidth * (eye.tan_up - eye.tan_down) / (eye.tan_right - eye.tan_left);
}

std::string rect(double x, double y, double w, double h, const std::string& fill, double opacity) {
    return "<rect x=\"" + format_number(x) + "\" y=\"" + format_number(y) + "\" width=\"" +
           format_number(w) + "\" height=\"" + format_number(h) + "\" fill=\"" + fill +
           "\" fill-opacity=\"" + format_number(opacity, 3) + "\"/>\n";
}

std::string text(double x, double y, const std::string& content, double size,
                 const char* anchor = "start", bool bold = false) {
    return "<text x=\"" + format_number(x) + "\" y=\"" + format_number(y) + "\" font-size=\"" +
           format_number(size) + "\" text-anchor=\"" + anchor + "\"" +
           (bold ? " font-weight=\"bold\"" : "") + ">" + xml_escaped(content) + "</text>\n";
}

// The colour map's position of a density relative to the peak: from the map's purple on, since
// its near-black start would read as a shadow on the scene.
double shade(double relative) {
    return 0.2 + 0.8 * relative;
}

// The heat map's bins over the picture's area; more opaque where more gaze fell.
std::string heat_map(const GazeDensity& d, double top, double height) {
    const double peak = d.peak();
    if (!(peak > 0.0)) return {};
    const double w = kImageWidth / d.columns;
    const double h = height / d.rows;
    std::string out = "<g class=\"gaze-density\">\n";
    for (int r = 0; r < d.rows; ++r)
        for (int c = 0; c < d.columns; ++c) {
            const double relative = d.at(c, r) / peak;
            if (relative < kClearBelow) continue;
            // Bins overlap by a hair so that no seams show between them when rasterized.
            out += rect(c * w, top + r * h, w + 0.3, h + 0.3, heat_color(shade(relative)),
                        0.25 + 0.5 * relative);
        }
    return out + "</g>\n";
}

// Below the picture: the colour bar from clear to the peak, and what the figure shows.
std::string legend(const GazeDensity& d, double y) {
    std::string out = "<g class=\"legend\">\n";
    constexpr int kSteps = 40;
    constexpr double kBarWidth = 200.0;
    for (int i = 0; i < kSteps; ++i) {
        const double relative = (i + 0.5) / kSteps;
        out += rect(10 + i * kBarWidth / kSteps, y + 8, kBarWidth / kSteps + 0.3, 10,
                    heat_color(shade(relative)), 0.25 + 0.5 * relative);
    }
    out += text(10, y + 32, "less", 11) + text(10 + kBarWidth, y + 32, "more gaze", 11, "end");
    out += text(
        kImageWidth - 10, y + 18,
        std::to_string(d.inside) + " of " + std::to_string(d.samples) + " samples inside the view",
        11, "end");
    out += text(kImageWidth - 10, y + 32, "+ straight ahead from the seat", 11, "end");
    return out + "</g>\n";
}

}  // namespace

std::string heat_color(double relative) {
    // Six stops of inferno, evenly spaced.
    static constexpr std::array<std::array<double, 3>, 6> kStops{
        {{0, 0, 4}, {66, 10, 104}, {147, 38, 103}, {221, 81, 58}, {252, 165, 10}, {252, 255, 164}}};
    const double x = std::clamp(relative, 0.0, 1.0) * (kStops.size() - 1);
    const std::size_t i = std::min(static_cast<std::size_t>(x), kStops.size() - 2);
    const double f = x - static_cast<double>(i);
    char out[8];
    const auto channel = [&](int k) {
        return static_cast<int>(std::lround(kStops[i][k] + f * (kStops[i + 1][k] - kStops[i][k])));
    };
    std::snprintf(out, sizeof out, "#%02x%02x%02x", channel(0), channel(1), channel(2));
    return out;
}

std::string base64(const std::string& bytes) {
    static constexpr char kDigits[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::size_t left = bytes.size() - i;
        std::uint32_t n = static_cast<unsigned char>(bytes[i]) << 16;
        if (left > 1) n |= static_cast<unsigned char>(bytes[i + 1]) << 8;
        if (left > 2) n |= static_cast<unsigned char>(bytes[i + 2]);
        out += kDigits[(n >> 18) & 63];
        out += kDigits[(n >> 12) & 63];
        out += left > 1 ? kDigits[(n >> 6) & 63] : '=';
        out += left > 2 ? kDigits[n & 63] : '=';
    }
    return out;
}

std::string gaze_density_svg(const GazeDensity& d, const SeatEye& eye,
                             const std::optional<SceneImage>& image) {
    const double height = image_height(eye, image);
    const double total = kTop + height + kBottom;
    std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                      format_number(kImageWidth) + "\" height=\"" + format_number(total) +
                      "\" viewBox=\"0 0 " + format_number(kImageWidth) + " " +
                      format_number(total) +
                      "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n";
    out += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    out += text(10, 24, "Where participants looked: " + upper_case(d.scene), 16, "start", true);
    out += text(10, 44, "gaze density over the left eye's view from the seat", 12);
    if (image) {
        out += "<image x=\"0\" y=\"" + format_number(kTop) + "\" width=\"" +
               format_number(kImageWidth) + "\" height=\"" + format_number(height) +
               "\" preserveAspectRatio=\"none\" href=\"data:image/png;base64," +
               base64(image->png) + "\"/>\n";
    } else {
        out += rect(0, kTop, kImageWidth, height, "#d9d9d9", 1.0);
        out += text(kImageWidth / 2, kTop + 20, "(no picture of the scene: density alone)", 12,
                    "middle");
    }
    out += heat_map(d, kTop, height);
    // Straight ahead from the seat: the direction (0, 0, -1), tangents (0, 0).
    const double ax = kImageWidth * (0.0 - eye.tan_left) / (eye.tan_right - eye.tan_left);
    const double ay = kTop + height * eye.tan_up / (eye.tan_up - eye.tan_down);
    out += "<path d=\"M" + format_number(ax - 7) + " " + format_number(ay) + "h14M" +
           format_number(ax) + " " + format_number(ay - 7) +
           "v14\" stroke=\"#00d0ff\" stroke-width=\"2\"/>\n";
    out += legend(d, kTop + height);
    return out + "</svg>\n";
}

}  // namespace monoplane::analysis::report
