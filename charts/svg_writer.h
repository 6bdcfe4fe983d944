// Low-level SVG output: XML escaping, deterministic number formatting and element emission. The
// charts build on it; nothing here knows about axes or data.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"

namespace monoplane::charts {

// `text` with &, <, >, " and ' replaced by entities, so it is safe as element content and as an
// attribute value. Control characters that XML 1.0 forbids are dropped: one stray byte from a
// user's label would otherwise make the whole figure unreadable. Bytes >= 0x80 (UTF-8) pass.
std::string xml_escaped(std::string_view text);

// `value` with at most `decimals` decimals, trailing zeros removed and "-0" written "0". Formatted
// with std::to_chars, so the output is byte-for-byte the same on every platform and locale, and
// two runs over the same data give the same file. `value` must be finite (a programming error
// otherwise; release builds write "0" so the document stays valid).
std::string format_number(double value, int decimals = 2);

// `value` with exactly `decimals` decimals ("0.50"), "-0.00" written "0.00": tick labels of one
// axis share their decimals. `value` must be finite, as for format_number.
std::string format_fixed(double value, int decimals);

struct Point {
    double x = 0.0;
    double y = 0.0;
};

// Presentation attributes; an empty string or a zero width means "not set here, inherit".
struct Paint {
    std::string fill;
    std::string stroke;
    double stroke_width = 0.0;
    std::string dash;  // stroke-dasharray, e.g. "6 3"
};

// Shorthands for the paints charts use most.
Paint stroke_paint(std::string color, double width = 0.0, std::string dash = {});
Paint fill_paint(std::string fill, std::string stroke = {}, double stroke_width = 0.0);

enum class TextAnchor { start, middle, end };

struct TextStyle {
    TextAnchor anchor = TextAnchor::start;
    double font_size = 0.0;  // 0: the document's default
    bool bold = false;
    std::string fill;             // empty: inherited (black)
    double rotate_degrees = 0.0;  // about the anchor point, e.g. -90 for a y-axis label
};

TextStyle text_style(TextAnchor anchor, double font_size = 0.0, std::string fill = {});

// Writes one SVG document, one element per line. Coordinates are user units (pixels) with the
// origin at the top left and y down, as SVG has them. Call the element functions in painting
// order (later elements cover earlier ones), then finish() once.
class SvgWriter {
  public:
    // Starts the document with a white background, so the figure reads the same on dark pages.
    SvgWriter(double width, double height);

    // A rectangle other elements can be clipped to with open_group(..., clip_id).
    void define_clip_rect(std::string_view id, double x, double y, double width, double height);
    // `css_class` names the group for readers of the file (and tests); may be empty.
    void open_group(std::string_view css_class, const Paint& paint = {},
                    std::string_view clip_id = {});
    void close_group();

    void rect(double x, double y, double width, double height, const Paint& paint);
    void line(double x1, double y1, double x2, double y2, const Paint& paint);
    void polyline(const std::vector<Point>& points, const Paint& paint);
    void polygon(const std::vector<Point>& points, const Paint& paint);
    void circle(double cx, double cy, double radius, const Paint& paint);
    // `content` is escaped here; pass plain text.
    void text(double x, double y, std::string_view content, const TextStyle& style = {});

    // Closes the document and returns it. Every group must have been closed.
    std::string finish();

  private:
    void paint_attributes(const Paint& paint);
    void points_attribute(const std::vector<Point>& points);

    std::string out_;
    int open_groups_ = 0;
};

// Writes `svg` to `path` (replacing it); the error says which file and why, for a user to act on.
Result<void> write_svg_file(const std::filesystem::path& path, std::string_view svg);

}  // namespace monoplane::charts
