#include "analysis/report/power.h"

#include <algorithm>
#include <cmath>

#include "analysis/report/text_output.h"
#include "charts/line_chart.h"
#include "charts/svg_writer.h"

namespace monoplane::analysis::report {

PowerPoint power_point(int participants, int runs, int detected, int not_estimable,
                       int detected_cr2) {
    PowerPoint p;
    p.participants = participants;
    p.runs = runs;
    p.detected = detected;
    p.not_estimable = not_estimable;
    const Proportion proportion{detected, runs};
    p.power = estimate(proportion);
    p.wilson = wilson_interval(proportion);
    p.detected_cr2 = detected_cr2;
    const Proportion proportion_cr2{detected_cr2, runs};
    p.power_cr2 = estimate(proportion_cr2);
    p.wilson_cr2 = wilson_interval(proportion_cr2);
    return p;
}

std::vector<int> participant_grid(int max_participants) {
    if (max_participants <= 2) return {std::max(1, max_participants)};
    std::vector<int> grid;
    const int step = max_participants <= 16
                         ? 2
                         : std::max(2, static_cast<int>(std::ceil((max_participants - 2) / 9.0)));
    for (int n = 2; n < max_participants; n += step) grid.push_back(n);
    grid.push_back(max_participants);
    return grid;
}

std::string power_csv(const PowerStudy& study) {
    std::string out =
        csv_line({"participants", "runs", "detected", "not_estimable", "power", "ci_lower",
                  "ci_upper", "detected_cr2", "power_cr2", "ci_lower_cr2", "ci_upper_cr2"});
    for (const PowerPoint& p : study.points) {
        out += csv_line(
            {std::to_string(p.participants), std::to_string(p.runs), std::to_string(p.detected),
             std::to_string(p.not_estimable), number_text(p.power), number_text(p.wilson.lower),
             number_text(p.wilson.upper), std::to_string(p.detected_cr2), number_text(p.power_cr2),
             number_text(p.wilson_cr2.lower), number_text(p.wilson_cr2.upper)});
    }
    return out;
}

std::string power_json(const PowerStudy& study) {
    JsonWriter json(kReportJson);
    json.begin_object()
        .value("protocol", study.protocol)
        .value("observer", study.observer)
        .value("hmd", study.hmd)
        .value("alpha", study.alpha)
        .value("seed", std::to_string(study.seed))
        .value("runs", study.runs)
        .value("trials_per_participant", study.trials_per_participant)
        .value("distance_term", study.distance_term)
        .begin_array("points");
    for (const PowerPoint& p : study.points) {
        json.begin_object()
            .value("participants", p.participants)
            .value("runs", p.runs)
            .value("detected", p.detected)
            .value("not_estimable", p.not_estimable)
            .value("power", p.power)
            .value("ci_lower", p.wilson.lower)
            .value("ci_upper", p.wilson.upper)
            .value("detected_cr2", p.detected_cr2)
            .value("power_cr2", p.power_cr2)
            .value("ci_lower_cr2", p.wilson_cr2.lower)
            .value("ci_upper_cr2", p.wilson_cr2.upper)
            .end_object();
    }
    json.end_array().end_object();
    return json.str();
}

std::string power_svg(const PowerStudy& study) {
    charts::LineChart chart;
    chart.text.title = "Power to detect the distance effect";
    chart.text.subtitle = "protocol " + study.protocol + ", observer " + study.observer + ", " +
                          std::to_string(study.runs) + " simulated studies per n, alpha " +
                          charts::format_number(study.alpha, 3);
    chart.text.note = "detected: p < alpha for " + study.distance_term +
                      " (clustered logistic regression); bars: 95 % Wilson; a null observer "
                      "should stay at alpha";
    chart.x_axis.label = "participants n";
    chart.x_axis.include_zero = true;
    int largest = 1;
    for (const PowerPoint& p : study.points) largest = std::max(largest, p.participants);
    // A margin right of the largest n, so its error bar is not drawn on the frame.
    chart.x_axis.max = largest + std::max(0.5, 0.05 * largest);
    chart.y_axis.label = "power";
    chart.y_axis.min = 0.0;
    chart.y_axis.max = 1.0;
    // The two tests side by side, nudged apart along n so their error bars stay readable.
    const double dodge = 0.01 * largest;
    for (const bool cr2 : {false, true}) {
        charts::LineSeries series;
        series.name = cr2 ? "CR2, Satterthwaite t" : "CR1, normal z";
        series.marker = cr2 ? charts::MarkerShape::square : charts::MarkerShape::circle;
        for (const PowerPoint& p : study.points) {
            charts::DataPoint point;
            point.x = p.participants + (cr2 ? dodge : -dodge);
            point.y = cr2 ? p.power_cr2 : p.power;
            const Interval& ci = cr2 ? p.wilson_cr2 : p.wilson;
            point.error = charts::ErrorRange{ci.lower, ci.upper};
            series.points.push_back(point);
        }
        chart.series.push_back(std::move(series));
    }
    chart.reference_lines.push_back({0.8, "0.8", "#000000"});
    chart.reference_lines.push_back(
        {study.alpha, "alpha " + charts::format_number(study.alpha, 3), "#777777"});
    return charts::render_svg(chart);
}

}  // namespace monoplane::analysis::report
