#include "app/headset/text_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace monoplane::headset {
namespace {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;
constexpr int kPaddingUnits = 4;      // font units of panel around the text
constexpr double kEdgeMargin = 0.05;  // tangent units kept clear of the view's edges
// However long the text, the panel stays between 30 degrees up and 40 degrees down: beyond, it
// is hard to read, and a flat panel's letters subtend ever less angle (cos^2 of the eccentricity).
const double kHighestTop = std::tan(30.0 * kRadiansPerDegree);
const double kLowestBottom = -std::tan(40.0 * kRadiansPerDegree);

// The ASCII look-alike of a code point, or "?" for one the font has no form of.
std::string_view ascii_for(std::uint32_t code_point) {
    switch (code_point) {
        case 0x2018:
        case 0x2019:
        case 0x201A:
        case 0x201B:
        case 0x2032:
            return "'";
        case 0x201C:
        case 0x201D:
        case 0x201E:
        case 0x2033:
        case 0x00AB:
        case 0x00BB:
            return "\"";
        case 0x2010:
        case 0x2011:
        case 0x2012:
        case 0x2013:
        case 0x2014:
        case 0x2212:
            return "-";
        case 0x2026:
            return "...";
        case 0x00A0:
        case 0x2009:
        case 0x202F:
            return " ";
        case 0x00D7:
            return "x";
        default:
            return "?";
    }
}

// The length of the UTF-8 sequence at text[i] (0: not a valid one) and its code point.
std::size_t utf8_sequence(std::string_view text, std::size_t i, std::uint32_t& code_point) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC0 ? 2 : 0;
    if (length == 0 || i + length > text.size()) return 0;
    code_point = lead & (0x7F >> length);
    for (std::size_t k = 1; k < length; ++k) {
        const auto next = static_cast<unsigned char>(text[i + k]);
        if ((next & 0xC0) != 0x80) return 0;
        code_point = (code_point << 6) | (next & 0x3F);
    }
    return length;
}

// The paragraph (no line breaks) as lines of at most max_units, appended to `lines`.
void wrap_paragraph(const std::string& paragraph, int max_units, std::vector<std::string>& lines) {
    std::string line;
    std::size_t start = 0;
    while (start < paragraph.size()) {
        if (paragraph[start] == ' ') {
            ++start;
            continue;
        }
        const std::size_t end = std::min(paragraph.find(' ', start), paragraph.size());
        std::string word = paragraph.substr(start, end - start);
        start = end;
        const std::string joined = line.empty() ? word : line + " " + word;
        if (text_width_units(joined) <= max_units) {
            line = joined;
            continue;
        }
        if (!line.empty()) lines.push_back(line);
        // A word wider than a whole line: split where it stops fitting (one character at least).
        while (text_width_units(word) > max_units && word.size() > 1) {
            std::size_t fits = 1;
            while (fits + 1 < word.size() &&
                   text_width_units(word.substr(0, fits + 1)) <= max_units)
                ++fits;
            lines.push_back(word.substr(0, fits));
            word.erase(0, fits);
        }
        line = word;
    }
    lines.push_back(line);  // an empty paragraph is an empty line
}

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

struct Wrapped {
    std::vector<std::string> lines;
    int width_units = 0;   // padding included
    int height_units = 0;  // padding included
};

Wrapped wrap_panel(const std::string& body, const std::vector<std::string>& footer,
                   int max_text_units) {
    Wrapped wrapped;
    wrapped.lines = wrap_text(headset_ascii(body), max_text_units);
    if (!footer.empty()) {
        wrapped.lines.emplace_back();
        for (const std::string& line : footer) {
            for (std::string& l : wrap_text(headset_ascii(line), max_text_units))
                wrapped.lines.push_back(std::move(l));
        }
    }
    int widest = 0;
    for (const std::string& line : wrapped.lines) widest = std::max(widest, text_width_units(line));
    wrapped.width_units = widest + 2 * kPaddingUnits;
    wrapped.height_units = static_cast<int>(wrapped.lines.size()) * kLineUnits + 2 * kPaddingUnits;
    return wrapped;
}

}  // namespace

std::string headset_ascii(std::string_view utf8) {
    std::string out;
    out.reserve(utf8.size());
    for (std::size_t i = 0; i < utf8.size();) {
        const auto c = static_cast<unsigned char>(utf8[i]);
        if (c < 0x80) {
            if (c == '\t')
                out += ' ';
            else if (c != '\r')
                out += static_cast<char>(c);
            ++i;
            continue;
        }
        std::uint32_t code_point = 0;
        const std::size_t length = utf8_sequence(utf8, i, code_point);
        out += length == 0 ? std::string_view("?") : ascii_for(code_point);
        i += std::max<std::size_t>(length, 1);
    }
    return out;
}

std::vector<std::string> wrap_text(const std::string& text, int max_units) {
    std::vector<std::string> lines;
    std::size_t start = 0;
    for (;;) {
        const std::size_t end = text.find('\n', start);
        wrap_paragraph(text.substr(start, end == std::string::npos ? end : end - start), max_units,
                       lines);
        if (end == std::string::npos) break;
        start = end + 1;
    }
    return lines;
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
    // Pixels per tangent unit of eyes[0]; aspect: a font unit's width in tangent units per unit
    // of its height (overlay_rect keeps the image's pixel aspect).
    const double px = extent.height / (eyes[0].up - eyes[0].down);
    const double aspect = px / (extent.width / (eyes[0].right - eyes[0].left));
    const double half_limit = std::min(std::tan(options.max_width_deg * 0.5 * kRadiansPerDegree),
                                       std::min(-view.left, view.right) - kEdgeMargin);
    const double top_limit = std::min(view.up - kEdgeMargin, kHighestTop);
    const double bottom_limit = std::max(view.down + kEdgeMargin, kLowestBottom);
    // Tangent units: a capital centred straight ahead subtends exactly the asked angle.
    double capital = 2.0 * std::tan(options.text_height_deg * kRadiansPerDegree / 2.0);
    Wrapped wrapped;
    double top = 0.0;
    for (int round = 0; round < 12; ++round) {
        const double unit = capital / kCapitalUnits;
        const int max_units = static_cast<int>(std::floor(2.0 * half_limit / (unit * aspect)));
        wrapped = wrap_panel(body, footer, std::max(1, max_units - 2 * kPaddingUnits));
        const double height = wrapped.height_units * unit;
        top = std::min(top_limit,
                       std::max(std::min(options.top_tan, top_limit), bottom_limit + height));
        if (top - height >= bottom_limit) break;
        // Taller than the view: smaller letters (longer lines make fewer of them).
        capital *= 0.98 * (top_limit - bottom_limit) / height;
    }
    TextPanel panel;
    panel.lines = wrapped.lines;
    panel.style.scale = capital / kCapitalUnits * px;
    panel.style.padding = kPaddingUnits;
    // The image's height as render_text rounds it, and its top edge on a pixel row of eyes[0]:
    // the blit then copies the image 1:1.
    const double height_px =
        static_cast<double>(std::lround(wrapped.height_units * panel.style.scale));
    const double top_px = std::round((eyes[0].up - top) * px);
    panel.placement.tan_height = height_px / px;
    panel.placement.tan_y = eyes[0].up - top_px / px - panel.placement.tan_height / 2.0;
    panel.capital_deg = 2.0 * std::atan(capital / 2.0) / kRadiansPerDegree;
    const double half_width = wrapped.width_units * capital / kCapitalUnits * aspect / 2.0;
    panel.smallest_capital_deg =
        capital *
        smallest_radians_per_tangent(half_width, eyes[0].up - top_px / px,
                                     eyes[0].up - (top_px + height_px) / px) /
        kRadiansPerDegree;
    panel.shrunk = panel.capital_deg < options.text_height_deg * (1.0 - 1e-9);
    return panel;
}

}  // namespace monoplane::headset
