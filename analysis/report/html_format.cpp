#include "analysis/report/html_format.h"

#include <cctype>
#include <cmath>

#include "charts/svg_writer.h"

namespace monoplane::analysis::report {

using charts::format_fixed;

std::string percent(double proportion, int decimals) {
    if (!std::isfinite(proportion)) return "&ndash;";
    return format_fixed(100.0 * proportion, decimals) + "&nbsp;%";
}

std::string interval_percent(const Interval& interval) {
    return "[" + format_fixed(100.0 * interval.lower, 1) + ", " +
           format_fixed(100.0 * interval.upper, 1) + "]";
}

std::string fixed(double value, int decimals) {
    if (!std::isfinite(value)) return "&ndash;";
    return format_fixed(value, decimals);
}

std::string p_value(double p) {
    if (!std::isfinite(p)) return "&ndash;";
    if (p < 0.001) return "&lt;&nbsp;0.001";
    return format_fixed(p, 3);
}

std::string p_statement(double p) {
    return p < 0.001 ? "p " + p_value(p) : "p = " + p_value(p);
}

std::string metres(double m) {
    if (!std::isfinite(m)) return "all";
    return charts::format_number(m, 3);
}

std::string upper_case(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

std::string scene_name(const std::string& scene) {
    return scene.empty() ? "all scenes" : upper_case(scene);
}

std::string Table::html() const {
    std::string out = "<table>\n<thead><tr>";
    for (std::size_t c = 0; c < header.size(); ++c) {
        out += numeric[c] ? "<th class=\"num\">" : "<th>";
        out += header[c] + "</th>";
    }
    out += "</tr></thead>\n<tbody>\n";
    for (const auto& row : rows) {
        out += "<tr>";
        for (std::size_t c = 0; c < row.size(); ++c) {
            out += c < numeric.size() && numeric[c] ? "<td class=\"num\">" : "<td>";
            out += row[c] + "</td>";
        }
        out += "</tr>\n";
    }
    return out + "</tbody>\n</table>\n";
}

std::string inline_svg(const std::string& svg) {
    std::string out = svg;
    const std::string ns = " xmlns=\"http://www.w3.org/2000/svg\"";
    if (const auto at = out.find(ns); at != std::string::npos) out.erase(at, ns.size());
    if (const auto at = out.find("<svg"); at != std::string::npos) {
        out.insert(at + 4, " role=\"img\"");
    }
    return out;
}

}  // namespace monoplane::analysis::report
