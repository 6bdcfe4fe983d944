#include "app/bench/bench_plots.h"

#include <algorithm>
#include <set>
#include <utility>

#include "charts/bar_chart.h"
#include "charts/line_chart.h"
#include "charts/svg_writer.h"
#include "renderer/plan/frame_plan.h"

namespace monoplane::app {
namespace {

double thousands(std::uint64_t count) {
    return static_cast<double>(count) / 1000.0;
}

// Passes grouped as the paper's Fig. 5 labels its bars (bench.json keys them by pass name).
std::string pass_group(const std::string& pass) {
    using plan::PassKind;
    using plan::ViewId;
    const auto parsed = plan::parse_pass_name(pass);
    if (!parsed) return pass;
    const auto [kind, view] = *parsed;
    switch (kind) {
        case PassKind::kCulling:
        case PassKind::kDepthPyramid:
        case PassKind::kOcclusionCulling:
            return "Culling + depth pyramid";
        case PassKind::kForward:
            if (view == ViewId::kLeft) return "L (left eye)";
            if (view == ViewId::kRight) return "R (right eye)";
            if (view == ViewId::kMono) return "C (mono camera)";
            return pass;
        case PassKind::kComposite:
            return "C to R,L (composite)";
        case PassKind::kTonemap:
            return "TM (tone mapping)";
        default:
            return pass;  // shadow and anything new
    }
}

std::string plane_label(const BenchRun& run) {
    if (run.mono_plane_auto) return "auto (" + charts::format_number(*run.mono_plane, 1) + ")";
    if (run.mono_plane_is_far) return "far";
    return charts::format_number(*run.mono_plane, 1);
}

// `--mono-planes auto` runs are a configuration of their own: one point each.
// "hybrid occlusion-cull", with " lod off" for full-detail runs (level of detail is the
// default) and " auto" where the renderer chose m.
std::string config_name(const BenchRun& run) {
    std::string name = run.variant.empty() ? run.mode : run.mode + " " + run.variant;
    if (run.lod == "off") name += " lod off";
    return run.mono_plane_auto ? name + " auto" : name;
}

// Runs of one scene and configuration, ordered by m.
std::vector<const BenchRun*> runs_of(const BenchReport& report, const std::string& scene,
                                     const std::string& config) {
    std::vector<const BenchRun*> runs;
    for (const BenchRun& run : report.runs) {
        if (run.scene == scene && run.mono_plane && config_name(run) == config) {
            runs.push_back(&run);
        }
    }
    std::stable_sort(runs.begin(), runs.end(), [](const BenchRun* a, const BenchRun* b) {
        return *a->mono_plane < *b->mono_plane;
    });
    return runs;
}

const BenchRun* stereo_run(const BenchReport& report, const std::string& scene) {
    for (const BenchRun& run : report.runs) {
        if (run.scene == scene && run.mode == "stereo") return &run;
    }
    return nullptr;
}

std::vector<std::string> hybrid_configs(const BenchReport& report, const std::string& scene) {
    std::vector<std::string> configs;
    for (const BenchRun& run : report.runs) {
        if (run.scene != scene || !run.mono_plane) continue;
        const std::string name = config_name(run);
        if (std::find(configs.begin(), configs.end(), name) == configs.end()) {
            configs.push_back(name);
        }
    }
    return configs;
}

std::string subtitle(const BenchReport& report) {
    return report.device + ", " + std::to_string(report.width) + " x " +
           std::to_string(report.height) + " per eye, " + report.hmd + ", detail " + report.detail +
           ", view " + report.view + ", medians of " + std::to_string(report.frames) + " frames";
}

// Fig. 5, middle: the stacked passes of one configuration (the paper shows Discard), with every
// configuration's frame time and stereo's as lines.
std::string time_chart(const BenchReport& report, const std::string& scene,
                       const std::string& stacked_config) {
    const std::vector<const BenchRun*> stacked = runs_of(report, scene, stacked_config);
    charts::StackedBarChart chart;
    chart.text.title = scene + ": GPU time per pass over the mono plane (" + stacked_config + ")";
    chart.text.subtitle = subtitle(report);
    chart.text.note = "Bars: median time per pass of " + stacked_config +
                      "; lines: median frame time of each configuration.";
    chart.x_label = "mono plane m (metres)";
    chart.y_axis.label = "GPU time (ms)";
    chart.y_axis.include_zero = true;
    chart.layout.width = 1000.0;
    chart.layout.legend_width = 300.0;
    // Bottom-up in the order the frame runs them; anything unknown on top.
    std::vector<std::string> groups = {
        "Culling + depth pyramid",
        plan::pass_name(plan::PassKind::kShadow, plan::ViewId::kNone),
        "L (left eye)",
        "R (right eye)",
        "C (mono camera)",
        "C to R,L (composite)",
        "TM (tone mapping)"};
    for (const BenchRun* run : stacked) {
        chart.categories.push_back(plane_label(*run));
        for (const auto& [pass, ms] : run->pass_ms_median) {
            const std::string group = pass_group(pass);
            if (std::find(groups.begin(), groups.end(), group) == groups.end()) {
                groups.push_back(group);
            }
        }
    }
    for (const std::string& group : groups) {
        charts::BarComponent component;
        component.name = group;
        for (const BenchRun* run : stacked) {
            double ms = 0.0;
            for (const auto& [pass, pass_ms] : run->pass_ms_median) {
                if (pass_group(pass) == group) ms += pass_ms;
            }
            component.values.push_back(ms);
        }
        chart.components.push_back(component);
    }
    for (const std::string& config : hybrid_configs(report, scene)) {
        if (config.ends_with(" auto")) continue;  // no category of its own: the m varies
        charts::CategoryLine line;
        line.name = config + " frame";
        for (const BenchRun* run : stacked) {
            double ms = std::numeric_limits<double>::quiet_NaN();
            for (const BenchRun* other : runs_of(report, scene, config)) {
                if (plane_label(*other) == plane_label(*run)) ms = other->frame_ms_median;
            }
            line.values.push_back(ms);
        }
        chart.lines.push_back(line);
    }
    if (const BenchRun* stereo = stereo_run(report, scene)) {
        chart.reference_lines.push_back(
            {stereo->frame_ms_median,
             "stereo " + charts::format_number(stereo->frame_ms_median, 1) + " ms"});
    }
    return charts::render_svg(chart);
}

// Fig. 5, top: drawn primitives per view of the frustum-culled configuration, with the
// occlusion-culled total and stereo's as references.
std::string primitives_chart(const BenchReport& report, const std::string& scene) {
    std::vector<std::string> configs = hybrid_configs(report, scene);
    std::erase_if(configs, [](const std::string& c) { return c.ends_with(" auto"); });
    const std::string base =
        std::find(configs.begin(), configs.end(), "hybrid no-opt") != configs.end()
            ? "hybrid no-opt"
            : configs.front();
    const std::vector<const BenchRun*> runs = runs_of(report, scene, base);
    charts::StackedBarChart chart;
    chart.text.title = scene + ": primitives drawn per view over the mono plane";
    chart.text.subtitle = subtitle(report);
    chart.text.note = "Bars: " + base +
                      " (frustum culling only) per view; lines: totals of the other "
                      "configurations. Primitives entering clipping, pipeline statistics.";
    chart.x_label = "mono plane m (metres)";
    chart.y_axis.label = "primitives (thousands)";
    chart.y_axis.include_zero = true;
    chart.layout.width = 1000.0;
    chart.layout.legend_width = 300.0;
    for (const BenchRun* run : runs) chart.categories.push_back(plane_label(*run));
    for (const auto& [view, label] : std::vector<std::pair<std::string, std::string>>{
             {"left", "L"}, {"right", "R"}, {"mono", "C"}}) {
        charts::BarComponent component;
        component.name = label;
        for (const BenchRun* run : runs) {
            const auto found = run->view_primitives.find(view);
            component.values.push_back(
                found == run->view_primitives.end() ? 0.0 : thousands(found->second));
        }
        chart.components.push_back(component);
    }
    for (const std::string& config : configs) {
        if (config == base) continue;
        charts::CategoryLine line;
        line.name = config;
        for (const BenchRun* run : runs) {
            double total = std::numeric_limits<double>::quiet_NaN();
            for (const BenchRun* other : runs_of(report, scene, config)) {
                if (plane_label(*other) == plane_label(*run)) total = thousands(other->primitives);
            }
            line.values.push_back(total);
        }
        chart.lines.push_back(line);
    }
    if (const BenchRun* stereo = stereo_run(report, scene)) {
        chart.reference_lines.push_back(
            {thousands(stereo->primitives),
             "stereo " + charts::format_number(thousands(stereo->primitives), 1) + "k"});
    }
    return charts::render_svg(chart);
}

// What each configuration costs against what it gets wrong: frame time relative to stereo over
// the analytic maximum error, each point labelled with its m.
// The frame of both time-against-error charts: time relative to stereo (from zero, stereo's 1
// marked) over an error from zero.
charts::LineChart time_against_error_frame(const BenchReport& report, std::string title,
                                           std::string note, std::string x_label,
                                           double legend_width) {
    charts::LineChart chart;
    chart.text.title = std::move(title);
    chart.text.subtitle = subtitle(report);
    chart.text.note = std::move(note);
    chart.x_axis.label = std::move(x_label);
    chart.x_axis.include_zero = true;
    chart.y_axis.label = "frame time / stereo's";
    chart.y_axis.include_zero = true;
    chart.layout.width = 1000.0;
    chart.layout.legend_width = legend_width;
    chart.reference_lines.push_back({1.0, "stereo"});
    return chart;
}

std::string time_vs_error_chart(const BenchReport& report, const std::string& scene) {
    charts::LineChart chart = time_against_error_frame(
        report, scene + ": frame time against error",
        "x: analytic maximum disparity error (px, rig); labels: m and the SSIM against stereo. "
        "Below 1: faster than stereo.",
        "maximum error (px)", 260.0);
    for (const std::string& config : hybrid_configs(report, scene)) {
        charts::LineSeries series;
        series.name = config;
        for (const BenchRun* run : runs_of(report, scene, config)) {
            if (!run->time_ratio || !run->max_error_px) continue;
            charts::DataPoint point;
            point.x = *run->max_error_px;
            point.y = *run->time_ratio;
            if (config.starts_with("hybrid occlusion-cull") ||
                config.starts_with("hybrid-farfield")) {
                point.label = "m " + plane_label(*run);
                if (run->ssim_vs_stereo) {
                    point.label += ", " + charts::format_number(*run->ssim_vs_stereo, 3);
                }
            }
            series.points.push_back(point);
        }
        chart.series.push_back(series);
    }
    return charts::render_svg(chart);
}

// Issue 20's comparison: frame time relative to stereo over the error a visible pixel can have
// (arcminutes at the farthest depth the scene shows), fixed m as lines, auto as its own points.
// An auto point on or below the fixed-m line is on the frontier: no fixed m is both faster and
// more accurate.
std::string time_vs_visible_error_chart(const BenchReport& report, const std::string& scene) {
    charts::LineChart chart = time_against_error_frame(
        report, scene + ": frame time against the visible error, fixed m and auto",
        "x: largest error of a visible pixel beyond m (arcmin, rig at the farthest depth stereo "
        "shows); auto: its largest over the frames. Labels: m. Below 1: faster than stereo.",
        "visible error (arcmin)", 280.0);
    for (const std::string& config : hybrid_configs(report, scene)) {
        charts::LineSeries series;
        series.name = config;
        for (const BenchRun* run : runs_of(report, scene, config)) {
            if (!run->time_ratio || !run->visible_error_arcmin) continue;
            charts::DataPoint point;
            point.x = *run->visible_error_arcmin;
            point.y = *run->time_ratio;
            point.label = "m " + plane_label(*run);
            series.points.push_back(point);
            if (run->mono_plane_auto) {
                series.connect = false;
                series.marker = charts::MarkerShape::diamond;
            }
        }
        if (!series.points.empty()) chart.series.push_back(series);
    }
    return charts::render_svg(chart);
}

}  // namespace

Result<std::vector<std::filesystem::path>> write_bench_plots(const BenchReport& report,
                                                             const std::filesystem::path& out) {
    std::vector<std::filesystem::path> written;
    std::set<std::string> scenes;
    for (const BenchRun& run : report.runs) {
        if (run.mono_plane) scenes.insert(run.scene);
    }
    for (const std::string& scene : scenes) {
        std::vector<std::string> configs = hybrid_configs(report, scene);
        std::erase_if(configs, [](const std::string& c) { return c.ends_with(" auto"); });
        if (configs.empty()) continue;  // auto alone: no sweep over m to draw
        const std::string stacked =
            std::find(configs.begin(), configs.end(), "hybrid discard") != configs.end()
                ? "hybrid discard"
                : configs.front();
        const std::vector<std::pair<std::string, std::string>> figures = {
            {scene + "_time.svg", time_chart(report, scene, stacked)},
            {scene + "_primitives.svg", primitives_chart(report, scene)},
            {scene + "_time_vs_error.svg", time_vs_error_chart(report, scene)},
            {scene + "_time_vs_visible_error.svg", time_vs_visible_error_chart(report, scene)},
        };
        for (const auto& [name, svg] : figures) {
            MONOPLANE_TRY(charts::write_svg_file(out / name, svg));
            written.push_back(out / name);
        }
    }
    return written;
}

}  // namespace monoplane::app
