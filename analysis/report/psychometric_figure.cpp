#include "analysis/report/psychometric_figure.h"

#include <cmath>

#include "analysis/proportion.h"
#include "analysis/report/html_format.h"
#include "charts/line_chart.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {
namespace {

// Bluish green (Okabe-Ito): apart from the choices figure's first two scenes (blue, orange),
// so the group's curve reads as a different kind of line.
constexpr const char* kGroupColor = "#009E73";
constexpr const char* kParticipantColor = "#B8B8B8";
constexpr int kCurvePoints = 96;

// The fitted curve over [from, to], evenly spaced in log m, in percent.
charts::LineSeries curve(const PsychometricParameters& parameters, double from, double to) {
    charts::LineSeries series;
    series.marker = charts::MarkerShape::none;
    for (int i = 0; i < kCurvePoints; ++i) {
        const double m = from * std::pow(to / from, static_cast<double>(i) / (kCurvePoints - 1));
        series.points.push_back({m, 100.0 * reference_probability(parameters, m), {}, ""});
    }
    return series;
}

charts::LineSeries data_points(const PsychometricFit& group) {
    charts::LineSeries series;
    series.name = "all participants' choices";
    series.connect = false;
    series.marker = charts::MarkerShape::circle;
    series.color = "#000000";
    for (const StimulusLevel& level : group.levels) {
        const Proportion proportion{level.reference, level.trials};
        const Interval wilson = wilson_interval(proportion);
        series.points.push_back({level.m, 100.0 * estimate(proportion),
                                 charts::ErrorRange{100.0 * wilson.lower, 100.0 * wilson.upper},
                                 ""});
    }
    return series;
}

// The group threshold as a diamond at P(T), its interval as a horizontal segment through it (an
// open end drawn to the last distance tested).
charts::LineSeries threshold_marks(const PsychometricFit& group) {
    const double t = group.parameters.threshold;
    const double y = 100.0 * reference_probability(group.parameters, t);
    const double lower = group.threshold_lower.value_or(group.levels.front().m);
    const double upper = group.threshold_upper.value_or(group.levels.back().m);
    charts::LineSeries series;
    series.name = "threshold " + charts::format_number(t, 2) + " m, 95 % CI";
    series.marker = charts::MarkerShape::diamond;
    series.color = kGroupColor;
    series.points = {{lower, y, {}, ""}, {t, y, {}, ""}, {upper, y, {}, ""}};
    return series;
}

}  // namespace

std::string psychometric_svg(const std::vector<PsychometricFit>& fits, const std::string& scene,
                             const std::string& reference_mode) {
    charts::LineChart chart;
    chart.text.title = "Psychometric function, " + upper_case(scene);
    chart.text.note = "P(" + reference_mode +
                      " chosen) = 0.5 + (0.5 - lapse) / (1 + (m/T)^B); "
                      "bars: 95 % Wilson; grey: participants' fits";
    chart.x_axis.label = "mono-plane distance m (metres, log scale)";
    chart.x_axis.scale = charts::ScaleKind::log10;
    chart.y_axis.label = reference_mode + " chosen (%)";
    chart.y_axis.min = 0.0;
    chart.y_axis.max = 100.0;
    chart.layout.width = 860;
    chart.layout.height = 460;
    chart.layout.legend_width = 230;
    chart.reference_lines.push_back({50.0, "chance", "#000000"});
    const PsychometricFit* group = nullptr;
    int estimable = 0, participants = 0;
    for (const PsychometricFit& f : fits) {
        if (f.scene != scene) continue;
        if (f.participant == "all") {
            group = &f;
            continue;
        }
        ++participants;
        if (!f.estimable) continue;
        charts::LineSeries series = curve(f.parameters, f.levels.front().m, f.levels.back().m);
        series.color = kParticipantColor;
        series.name = estimable++ == 0 ? "participants' fits" : "";
        chart.series.push_back(std::move(series));
    }
    chart.text.subtitle = std::to_string(estimable) + " of " + std::to_string(participants) +
                          " participants' thresholds estimable";
    if (group == nullptr || group->levels.empty()) return charts::render_svg(chart);
    chart.text.subtitle += "; " + std::to_string(group->n) + " trials";
    if (group->estimable) {
        charts::LineSeries fitted =
            curve(group->parameters, group->levels.front().m, group->levels.back().m);
        fitted.name = "group fit";
        fitted.color = kGroupColor;
        chart.series.push_back(std::move(fitted));
        chart.series.push_back(threshold_marks(*group));
    } else {
        chart.text.subtitle += "; group threshold not estimable";
    }
    chart.series.push_back(data_points(*group));
    return charts::render_svg(chart);
}

}  // namespace monoplane::analysis::report
