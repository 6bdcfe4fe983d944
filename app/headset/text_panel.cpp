#include "app/headset/text_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "text/line_break.h"
#include "text/utf8.h"

namespace monoplane::headset {
namespace {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
constexpr double kEdgeMargin = 0.05;  // tangent units kept clear of the view's edges
// However long the text, the panel stays between 30 degrees up and 40 degrees down: beyond, it
// is hard to read, and a flat panel's letters subtend ever less angle (cos^2 of the eccentricity).
const double kHighestTop = std::tan(30.0 * kRadiansPerDegree);
const double kLowestBottom = -std::tan(40.0 * kRadiansPerDegree);

rig::Tangents common_view(const std::array<rig::Tangents, 2>& eyes) {
    rig::Tangents view;
    view.left = std::max(eyes[0].left, eyes[1].left);
    view.right = std::min(eyes[0].right, eyes[1].right);
    view.down = std::max(eyes[0].down, eyes[1].down);
    view.up = std::min(eyes[0].up, eyes[1].up);
    return view;
}

// The smallest angle per tangent unit over a centred panel: at a corner or the middle of its top
// or bottom edge (for fixed y it is smallest at x = 0 or the widest x, for fixed x at the largest
// |y|).
double smallest_radians_per_tangent(double half_width, double top, double bottom) {
    double smallest = radians_per_tangent(0.0, top);
    for (const double x : {0.0, half_width}) {
        for (const double y : {top, bottom})
            smallest = std::min(smallest, radians_per_tangent(x, y));
    }
    return smallest;
}

// A capital letter's share of the panel's padding: 4/7 of a capital on every side.
constexpr double kPaddingCapitals = 4.0 / 7.0;

struct Wrapped {
    std::vector<std::string> lines;
    text::LineGeometry geometry;
    std::uint32_t width_px = 0;  // padding included
    std::uint32_t height_px = 0;
};

// The body and the footer (after a blank line) wrapped to max_width_px pixels of text, measured
// with the font's advances at the style's size.
Wrapped wrap_panel(const std::string& body, const std::vector<std::string>& footer,
                   const TextStyle& style, double max_width_px) {
    const text::Font& font = style_font(style);
    Wrapped wrapped;
    wrapped.geometry = text_geometry(style);
    const double max_em = std::max(0.0, max_width_px) / wrapped.geometry.em_px;
    wrapped.lines = text::wrap_text(shown_text(body), font, max_em);
    if (!footer.empty()) {
        wrapped.lines.emplace_back();
        for (const std::string& line : footer) {
            for (std::string& l : text::wrap_text(shown_text(line), font, max_em))
                wrapped.lines.push_back(std::move(l));
        }
    }
    double widest = 0.0;
    for (const std::string& line : wrapped.lines)
        widest = std::max(widest, text::text_width_em(line, font) * wrapped.geometry.em_px);
    const int padding = wrapped.geometry.padding_px;
    wrapped.width_px = static_cast<std::uint32_t>(std::ceil(widest) + 2 * padding);
    wrapped.height_px =
        static_cast<std::uint32_t>(wrapped.lines.size() * wrapped.geometry.line_px + 2 * padding);
    return wrapped;
}

TextStyle panel_style(double capital_px, const std::string& font) {
    TextStyle style;
    style.font = font;
    style.capital_px = capital_px;
    style.padding_px = static_cast<int>(std::lround(kPaddingCapitals * capital_px));
    return style;
}

}  // namespace

std::string shown_text(std::string_view utf8) {
    std::u32string text = text::decode_utf8_lenient(utf8);
    std::erase(text, U'\r');
    std::ranges::replace(text, U'\t', U' ');
    return text::encode_utf8(text);
}

double pixels_per_degree(const rig::Tangents& eye, vk::Extent2D extent) {
    return extent.height / (eye.up - eye.down) * 2.0 * std::tan(0.5 * kRadiansPerDegree);
}

double radians_per_tangent(double x, double y) {
    return std::sqrt(1.0 + x * x) / (1.0 + x * x + y * y);
}

TextPanel layout_text_panel(const std::string& body, const std::vector<std::string>& footer,
                            const std::array<rig::Tangents, 2>& eyes, vk::Extent2D extent,
                            const TextPanelOptions& options) {
    const rig::Tangents view = common_view(eyes);
    // Pixels per tangent unit of eyes[0], vertically and horizontally (overlay_rect keeps the
    // image's pixel aspect, so a pixel of text spans 1 / px_x tangent units across).
    const double px = extent.height / (eyes[0].up - eyes[0].down);
    const double px_x = extent.width / (eyes[0].right - eyes[0].left);
    const double half_limit = std::min(std::tan(options.max_width_deg * 0.5 * kRadiansPerDegree),
                                       std::min(-view.left, view.right) - kEdgeMargin);
    const double top_limit = std::min(view.up - kEdgeMargin, kHighestTop);
    const double bottom_limit = std::max(view.down + kEdgeMargin, kLowestBottom);
    // Tangent units: a capital centred straight ahead subtends exactly the asked angle.
    double capital = 2.0 * std::tan(options.text_height_deg * kRadiansPerDegree / 2.0);
    Wrapped wrapped;
    TextStyle style;
    double top = 0.0;
    for (int round = 0; round < 12; ++round) {
        style = panel_style(capital * px, options.font);
        const double max_text_px = std::floor(2.0 * half_limit * px_x) - 2.0 * style.padding_px;
        wrapped = wrap_panel(body, footer, style, max_text_px);
        const double height = wrapped.height_px / px;
        top = std::min(top_limit,
                       std::max(std::min(options.top_tan, top_limit), bottom_limit + height));
        if (top - height >= bottom_limit) break;
        // Taller than the view: smaller letters (longer lines make fewer of them).
        capital *= 0.98 * (top_limit - bottom_limit) / height;
    }
    TextPanel panel;
    panel.lines = wrapped.lines;
    panel.style = style;
    // The image's top edge on a pixel row of eyes[0]: the blit then copies the image 1:1.
    const double height_px = wrapped.height_px;
    const double top_px = std::round((eyes[0].up - top) * px);
    panel.placement.tan_height = height_px / px;
    panel.placement.tan_y = eyes[0].up - top_px / px - panel.placement.tan_height / 2.0;
    panel.capital_deg = 2.0 * std::atan(capital / 2.0) / kRadiansPerDegree;
    const double half_width = wrapped.width_px / px_x / 2.0;
    panel.smallest_capital_deg =
        capital *
        smallest_radians_per_tangent(half_width, eyes[0].up - top_px / px,
                                     eyes[0].up - (top_px + height_px) / px) /
        kRadiansPerDegree;
    panel.shrunk = panel.capital_deg < options.text_height_deg * (1.0 - 1e-9);
    return panel;
}

}  // namespace monoplane::headset
