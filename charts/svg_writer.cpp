#include "charts/svg_writer.h"

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <fstream>
#include <utility>

#include "common/programming_error.h"

namespace monoplane::charts {

std::string xml_escaped(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char ch : text) {
        switch (ch) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&apos;";
                break;
            case '\t':
            case '\n':
            case '\r':
                out += ch;
                break;
            default:
                if (static_cast<unsigned char>(ch) >= 0x20) out += ch;
        }
    }
    return out;
}

std::string format_fixed(double value, int decimals) {
    MONOPLANE_EXPECTS(std::isfinite(value) && "charts: only finite numbers reach the SVG");
    MONOPLANE_EXPECTS(decimals >= 0 && decimals <= 20);
    if (!std::isfinite(value)) return "0";
    // Room for the largest double in fixed notation (309 digits) and the decimals.
    std::array<char, 400> buffer{};
    const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value,
                                            std::chars_format::fixed, decimals);
    if (error != std::errc{}) return "0";
    std::string text(buffer.data(), end);
    // A negative value that rounds to zero prints as "-0.00"; a figure should not show the sign.
    if (text.front() == '-' && text.find_first_not_of("-0.") == std::string::npos) {
        text.erase(0, 1);
    }
    return text;
}

std::string format_number(double value, int decimals) {
    std::string text = format_fixed(value, decimals);
    if (text.find('.') != std::string::npos) {
        while (text.back() == '0') text.pop_back();
        if (text.back() == '.') text.pop_back();
    }
    return text;
}

Paint stroke_paint(std::string color, double width, std::string dash) {
    Paint paint;
    paint.stroke = std::move(color);
    paint.stroke_width = width;
    paint.dash = std::move(dash);
    return paint;
}

Paint fill_paint(std::string fill, std::string stroke, double stroke_width) {
    Paint paint;
    paint.fill = std::move(fill);
    paint.stroke = std::move(stroke);
    paint.stroke_width = stroke_width;
    return paint;
}

TextStyle text_style(TextAnchor anchor, double font_size, std::string fill) {
    TextStyle style;
    style.anchor = anchor;
    style.font_size = font_size;
    style.fill = std::move(fill);
    return style;
}

namespace {

const char* anchor_name(TextAnchor anchor) {
    switch (anchor) {
        case TextAnchor::start:
            return "start";
        case TextAnchor::middle:
            return "middle";
        case TextAnchor::end:
            return "end";
    }
    return "start";
}

}  // namespace

SvgWriter::SvgWriter(double width, double height) {
    const std::string w = format_number(width);
    const std::string h = format_number(height);
    out_ += "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w + "\" height=\"" + h +
            "\" viewBox=\"0 0 " + w + " " + h +
            "\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\"13\">\n";
    out_ += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

void SvgWriter::define_clip_rect(std::string_view id, double x, double y, double width,
                                 double height) {
    out_ += "<defs><clipPath id=\"" + xml_escaped(id) + "\"><rect x=\"" + format_number(x) +
            "\" y=\"" + format_number(y) + "\" width=\"" + format_number(width) + "\" height=\"" +
            format_number(height) + "\"/></clipPath></defs>\n";
}

void SvgWriter::open_group(std::string_view css_class, const Paint& paint,
                           std::string_view clip_id) {
    out_ += "<g";
    if (!css_class.empty()) out_ += " class=\"" + xml_escaped(css_class) + "\"";
    paint_attributes(paint);
    if (!clip_id.empty()) out_ += " clip-path=\"url(#" + xml_escaped(clip_id) + ")\"";
    out_ += ">\n";
    ++open_groups_;
}

void SvgWriter::close_group() {
    MONOPLANE_EXPECTS(open_groups_ > 0);
    out_ += "</g>\n";
    --open_groups_;
}

void SvgWriter::rect(double x, double y, double width, double height, const Paint& paint) {
    out_ += "<rect x=\"" + format_number(x) + "\" y=\"" + format_number(y) + "\" width=\"" +
            format_number(width) + "\" height=\"" + format_number(height) + "\"";
    paint_attributes(paint);
    out_ += "/>\n";
}

void SvgWriter::line(double x1, double y1, double x2, double y2, const Paint& paint) {
    out_ += "<line x1=\"" + format_number(x1) + "\" y1=\"" + format_number(y1) + "\" x2=\"" +
            format_number(x2) + "\" y2=\"" + format_number(y2) + "\"";
    paint_attributes(paint);
    out_ += "/>\n";
}

void SvgWriter::polyline(const std::vector<Point>& points, const Paint& paint) {
    // Round joins: dense data lines (hundreds of samples) would otherwise show mitre spikes.
    out_ += "<polyline stroke-linejoin=\"round\"";
    paint_attributes(paint);
    points_attribute(points);
    out_ += "/>\n";
}

void SvgWriter::polygon(const std::vector<Point>& points, const Paint& paint) {
    out_ += "<polygon";
    paint_attributes(paint);
    points_attribute(points);
    out_ += "/>\n";
}

void SvgWriter::circle(double cx, double cy, double radius, const Paint& paint) {
    out_ += "<circle cx=\"" + format_number(cx) + "\" cy=\"" + format_number(cy) + "\" r=\"" +
            format_number(radius) + "\"";
    paint_attributes(paint);
    out_ += "/>\n";
}

void SvgWriter::text(double x, double y, std::string_view content, const TextStyle& style) {
    out_ += "<text";
    if (style.rotate_degrees != 0.0) {
        // Rotating about the anchor needs the anchor as the origin: translate, then rotate.
        out_ += " transform=\"translate(" + format_number(x) + " " + format_number(y) +
                ") rotate(" + format_number(style.rotate_degrees) + ")\"";
    } else {
        out_ += " x=\"" + format_number(x) + "\" y=\"" + format_number(y) + "\"";
    }
    if (style.anchor != TextAnchor::start) {
        out_ += std::string(" text-anchor=\"") + anchor_name(style.anchor) + "\"";
    }
    if (style.font_size > 0.0) out_ += " font-size=\"" + format_number(style.font_size) + "\"";
    if (style.bold) out_ += " font-weight=\"bold\"";
    if (!style.fill.empty()) out_ += " fill=\"" + xml_escaped(style.fill) + "\"";
    out_ += ">" + xml_escaped(content) + "</text>\n";
}

std::string SvgWriter::finish() {
    MONOPLANE_EXPECTS(open_groups_ == 0 && "charts: a group was left open");
    while (open_groups_ > 0) close_group();
    out_ += "</svg>\n";
    return std::move(out_);
}

void SvgWriter::paint_attributes(const Paint& paint) {
    if (!paint.fill.empty()) out_ += " fill=\"" + xml_escaped(paint.fill) + "\"";
    if (!paint.stroke.empty()) out_ += " stroke=\"" + xml_escaped(paint.stroke) + "\"";
    if (paint.stroke_width > 0.0) {
        out_ += " stroke-width=\"" + format_number(paint.stroke_width) + "\"";
    }
    if (!paint.dash.empty()) out_ += " stroke-dasharray=\"" + xml_escaped(paint.dash) + "\"";
}

void SvgWriter::points_attribute(const std::vector<Point>& points) {
    out_ += " points=\"";
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (i > 0) out_ += ' ';
        out_ += format_number(points[i].x) + "," + format_number(points[i].y);
    }
    out_ += "\"";
}

Result<void> write_svg_file(const std::filesystem::path& path, std::string_view svg) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (!file) {
        return Error{"cannot open " + path.string() + " for writing (" + std::strerror(errno) +
                     "): check that the directory exists and is writable"};
    }
    file.write(svg.data(), static_cast<std::streamsize>(svg.size()));
    file.close();
    if (!file) {
        return Error{"cannot write " + path.string() + " (" + std::strerror(errno) +
                     "): is the disk full?"};
    }
    return Ok{};
}

}  // namespace monoplane::charts
