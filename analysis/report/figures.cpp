#include "analysis/report/figures.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "analysis/report/box_chart.h"
#include "analysis/report/gaze_section.h"
#include "analysis/report/html_format.h"
#include "analysis/report/psychometric_figure.h"
#include "analysis/report/report.h"
#include "charts/line_chart.h"
#include "charts/palette.h"

namespace monoplane::analysis::report {
namespace {

std::string upper(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

BoxChart boxes(const std::vector<GroupSummary>& groups) {
    BoxChart chart;
    for (const GroupSummary& g : groups) {
        Box box;
        box.category = upper(g.group) + " (n = " + std::to_string(g.summary.n) + ")";
        box.empty = g.summary.n == 0;
        box.min = g.summary.min;
        box.q1 = g.summary.q1;
        box.median = g.summary.median;
        box.q3 = g.summary.q3;
        box.max = g.summary.max;
        box.mean = g.summary.mean;
        chart.boxes.push_back(box);
    }
    chart.x_label = "scene";
    chart.layout.width = 760;
    chart.layout.height = 440;
    chart.layout.legend_width = 170;
    return chart;
}

}  // namespace

std::string scene_file_stem(const std::string& scene) {
    std::string stem = scene;
    for (char& c : stem) {
        const bool safe =
            std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '-' || c == '_' || c == '.';
        if (!safe) c = '_';
    }
    return stem;
}

std::string choices_svg(const std::vector<ChoiceRate>& by_scene_and_distance,
                        const std::string& test_mode, const std::string& reference_mode,
                        const std::string& subtitle) {
    std::vector<std::string> scenes;
    double m_min = INFINITY, m_max = -INFINITY;
    for (const ChoiceRate& r : by_scene_and_distance) {
        if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) {
            scenes.push_back(r.scene);
        }
        if (std::isfinite(r.mono_plane)) {
            m_min = std::min(m_min, r.mono_plane);
            m_max = std::max(m_max, r.mono_plane);
        }
    }
    // A dodge of 0.8 % of the span per scene: visible apart, too small to misread m.
    const double dodge = m_max > m_min ? 0.008 * (m_max - m_min) : 0.0;

    charts::LineChart chart;
    chart.text.title = "Decisions for " + test_mode + " per scene over the mono-plane distance";
    chart.text.subtitle = subtitle;
    chart.text.note = "% of valid decisions for " + test_mode + " (vs " + reference_mode +
                      "); error bars: 95 % Wilson intervals; scenes offset slightly along m";
    chart.x_axis.label = "mono-plane distance m (metres)";
    chart.x_axis.include_zero = true;
    chart.y_axis.label = test_mode + " chosen (%)";
    chart.y_axis.min = 0.0;
    chart.y_axis.max = 100.0;
    chart.layout.width = 860;
    chart.layout.height = 500;
    chart.layout.legend_width = 170;
    const charts::MarkerShape shapes[] = {charts::MarkerShape::circle, charts::MarkerShape::square,
                                          charts::MarkerShape::triangle,
                                          charts::MarkerShape::diamond};
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        charts::LineSeries series;
        series.name = upper(scenes[s]);
        series.marker = shapes[s % 4];
        const double offset =
            (static_cast<double>(s) - (static_cast<double>(scenes.size()) - 1.0) / 2.0) * dodge;
        for (const ChoiceRate& r : by_scene_and_distance) {
            if (r.scene != scenes[s] || r.n == 0) continue;
            charts::DataPoint point;
            point.x = r.mono_plane + offset;
            point.y = 100.0 * r.rate;
            point.error = charts::ErrorRange{100.0 * r.wilson.lower, 100.0 * r.wilson.upper};
            series.points.push_back(point);
        }
        chart.series.push_back(std::move(series));
    }
    chart.reference_lines.push_back({50.0, "50 %", "#000000"});
    return charts::render_svg(chart);
}

std::string decision_times_svg(const std::vector<GroupSummary>& by_scene,
                               const std::string& subtitle) {
    BoxChart chart = boxes(by_scene);
    chart.text.title = "Decision time per scene";
    chart.text.subtitle = subtitle;
    chart.text.note = "first view to confirmation, pauses excluded";
    chart.y_axis.label = "decision time (s)";
    return render_svg(chart);
}

std::string switches_svg(const std::vector<GroupSummary>& by_scene, const std::string& subtitle) {
    BoxChart chart = boxes(by_scene);
    chart.text.title = "Switches between the alternatives per scene";
    chart.text.subtitle = subtitle;
    chart.text.note = "switches per trial before the decision";
    chart.y_axis.label = "switches per trial";
    chart.color = "#D55E00";
    return render_svg(chart);
}

std::vector<Figure> report_figures(const AnalysisResults& r) {
    const std::string counts = std::to_string(r.exclusions.kept) + " valid decisions of " +
                               std::to_string(r.participants) + " participants (" +
                               std::to_string(r.sessions) + " sessions)";
    std::vector<Figure> figures;
    figures.push_back({"choices",
                       "Decisions for " + r.test_mode +
                           " per scene over the mono-plane distance m, as "
                           "papers/000 Fig. 7; the line marks 50 % (no preference).",
                       choices_svg(r.by_scene_distance, r.test_mode, r.reference_mode, counts)});
    figures.push_back({"decision_times",
                       "Decision time per scene: quartile boxes, median line, mean diamond, "
                       "whiskers from minimum to maximum.",
                       decision_times_svg(r.decision_times, counts)});
    figures.push_back({"switches", "Switches between the two alternatives per trial, per scene.",
                       switches_svg(r.switches, counts)});
    for (const PsychometricFit& f : r.psychometric) {
        if (f.participant != "all") continue;
        figures.push_back({"psychometric_" + scene_file_stem(f.scene),
                           "Choices of " + r.reference_mode + " in " + upper_case(f.scene) +
                               " over the mono-plane distance m with the fitted psychometric "
                               "functions: the group's (green, with its threshold and 95 % "
                               "interval) and each participant's (grey).",
                           psychometric_svg(r.psychometric, f.scene, r.reference_mode)});
    }
    for (Figure& f : gaze_figures(r)) figures.push_back(std::move(f));
    return figures;
}

}  // namespace monoplane::analysis::report
