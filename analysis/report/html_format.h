// The report page's building blocks: numbers formatted for people (percent, fixed decimals,
// p-values, metres) and HTML tables. Every section of report.html uses them, so one section
// reads like the next. Output is HTML text (entities such as &ndash; for a missing number).
#pragma once

#include <string>
#include <vector>

#include "analysis/proportion.h"

namespace monoplane::analysis::report {

// "12.5&nbsp;%" from 0.125; "&ndash;" when not finite.
std::string percent(double proportion, int decimals = 1);
// "[10.2, 31.4]" in percent.
std::string interval_percent(const Interval& interval);
// `decimals` fixed decimals; "&ndash;" when not finite.
std::string fixed(double value, int decimals);
// "0.042", "&lt;&nbsp;0.001"; "&ndash;" when not finite.
std::string p_value(double p);
// "p &lt; 0.001" or "p = 0.042", for a sentence.
std::string p_statement(double p);
// Up to 3 significant digits; "all" when not finite (a rate pooled over distances).
std::string metres(double m);
std::string upper_case(std::string text);
// "BEAMS"; "all scenes" for "".
std::string scene_name(const std::string& scene);

// A table whose cells are HTML already; numeric columns are right-aligned.
struct Table {
    std::vector<std::string> header;
    std::vector<bool> numeric;  // per column
    std::vector<std::vector<std::string>> rows;

    std::string html() const;
};

// An SVG document ready to sit inside the page: without the namespace URL (HTML puts <svg> into
// the SVG namespace itself, and the page keeps nothing that looks like an external reference),
// with role="img".
std::string inline_svg(const std::string& svg);

}  // namespace monoplane::analysis::report
