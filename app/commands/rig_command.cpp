// `monoplane rig`: the triple-frustum rig of an HMD profile at one mono-plane distance
// (docs/hybrid.md), as a readable summary or JSON, and with --fig2 the projection error over
// depth for several mono planes as CSV and SVG (papers/000 Fig. 2, right). No GPU is touched.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands/commands.h"
#include "app/commands/output_directory.h"
#include "app/commands/rig_error_budget.h"
#include "charts/line_chart.h"
#include "charts/svg_writer.h"
#include "common/json_writer.h"
#include "hmd/profile.h"
#include "rig/angular_error.h"
#include "rig/rig.h"

namespace monoplane::app {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The mono-plane distances of the fink2019 protocol (protocols/fink2019.toml).
const std::vector<double> kFink2019MonoPlanes = {1.6, 3, 5, 8, 12, 16, 20, 25, 31, 39.5};

struct RigOptions {
    std::string hmd = "vive";
    std::optional<double> ipd;
    std::optional<double> mono_plane;
    double near = 0.1;
    double far = 1000.0;
    double overlap_k = 2.0;
    double grazing_deg = 1.0;
    double nearest_mono_plane = 0.0;
    bool json = false;
    std::string fig2_dir;
    std::vector<double> fig2_mono_planes = kFink2019MonoPlanes;
    int fig2_samples = 200;
    std::optional<double> error_budget_arcmin;
    bool disparity = false;           // the budget bounds the disparity error, not each eye's
    double budget_depth = kInfinity;  // ... for content up to this depth
};

rig::RigInputs rig_inputs(const RigOptions& o, const hmd::HmdProfile& profile, double m) {
    rig::RigInputs in = hmd::rig_inputs(profile, m);
    in.ipd = o.ipd.value_or(profile.ipd);
    in.near = o.near;
    in.far = o.far;
    in.overlap_k = o.overlap_k;
    in.grazing_angle = o.grazing_deg * std::numbers::pi / 180.0;
    in.nearest_mono_plane = o.nearest_mono_plane;
    return in;
}

std::string fixed(double value, int digits) {
    std::ostringstream text;
    text.precision(digits);
    text << value;
    return text.str();
}

rig::Rig build_or_throw(const RigOptions& o, const hmd::HmdProfile& profile, double m) {
    Result<rig::Rig> rig = rig::build_rig(rig_inputs(o, profile, m));
    if (!rig) {
        throw UserError(rig.error().message + " (HMD " + profile.source + ", --mono-plane " +
                        fixed(m, 6) + ")");
    }
    return std::move(rig).value();
}

double degrees(double tangent) {
    return std::atan(tangent) * 180.0 / std::numbers::pi;
}

// Depths for the summary's error table: a few multiples of m up to f, then the limit.
std::vector<double> table_depths(double m, double far) {
    std::vector<double> depths;
    for (double factor : {1.1, 1.5, 2.0, 5.0, 10.0, 100.0}) {
        if (m * factor < far) depths.push_back(m * factor);
    }
    depths.push_back(far);
    depths.push_back(kInfinity);
    return depths;
}

void print_tangents(std::ostream& out, const rig::Tangents& t) {
    char line[200];
    std::snprintf(line, sizeof line,
                  "tan left %.6f  right %.6f  down %.6f  up %.6f  (%.2f / %.2f / %.2f / %.2f deg)",
                  t.left, t.right, t.down, t.up, degrees(t.left), degrees(t.right), degrees(t.down),
                  degrees(t.up));
    out << line << "\n";
}

void print_summary(std::ostream& out, const hmd::HmdProfile& profile, const rig::Rig& rig) {
    const rig::RigInputs& in = rig.inputs;
    const rig::MonoCamera& c = rig.mono;
    char line[240];
    out << "HMD             " << profile.name << " (" << profile.source << ")\n";
    out << "eyes            " << in.eye_width << " x " << in.eye_height << " px each\n";
    out << "  left          ";
    print_tangents(out, in.eyes[rig::kLeft]);
    out << "  right         ";
    print_tangents(out, in.eyes[rig::kRight]);
    if (rig::is_canted(in)) {
        std::snprintf(line, sizeof line,
                      "  canted        left %+.3f deg, right %+.3f deg (yaw, positive left); the "
                      "tangents are in each turned eye's frame\n",
                      in.cant[rig::kLeft] * 180.0 / std::numbers::pi,
                      in.cant[rig::kRight] * 180.0 / std::numbers::pi);
        out << line;
    }
    std::snprintf(
        line, sizeof line,
        "ipd d %.4g m, mono plane m %.6g m, near n %.6g m, far f %.6g m, overlap k %.4g\n", in.ipd,
        in.mono_plane, in.near, in.far, in.overlap_k);
    out << line;
    if (rig.mono_skipped) {
        out << "\nm >= f: nothing lies beyond the mono plane. The mono camera C is skipped, the\n"
               "eyes render n..f, hybrid equals stereo and the error is 0.\n";
        return;
    }
    out << "\nmono camera C (eq. 1-4, 8)\n";
    std::snprintf(line, sizeof line,
                  "  s (behind eyes) %.6f m: C at (0, 0, +%.6f) in the head frame\n",
                  c.offset_behind_eyes, c.offset_behind_eyes);
    out << line;
    out << "  frustum       ";
    print_tangents(out, c.tangents);
    std::snprintf(line, sizeof line, "  field         %.2f x %.2f deg\n",
                  degrees(c.tangents.right) - degrees(c.tangents.left),
                  degrees(c.tangents.up) - degrees(c.tangents.down));
    out << line;
    std::snprintf(
        line, sizeof line,
        "  overlap eps   %.6f m (k s m or C's footprint at grazing angles): C starts at %.6f m\n",
        rig.overlap, in.mono_plane - rig.overlap);
    out << line;
    std::snprintf(line, sizeof line, "  near, far     %.6f m, %.6f m (from C)\n", c.near, c.far);
    out << line;
    std::snprintf(line, sizeof line, "  size (eq. 8)  %.3f x %.3f px, rendered %d x %d px\n",
                  c.width, c.height, c.viewport_width, c.viewport_height);
    out << line;
    std::snprintf(line, sizeof line, "  allocation    %d x %d px, uv scale %.6f x %.6f\n",
                  c.allocated_width, c.allocated_height, c.uv_scale.x, c.uv_scale.y);
    out << line;
    out << "\nerror beyond the mono plane, hybrid vs stereo (Fig. 2), largest over both eyes\n";
    std::snprintf(line, sizeof line, "  %-14s %14s %14s %14s %16s\n", "depth (m)", "horizontal px",
                  "2d px", "eye arcmin", "disparity arcmin");
    out << line;
    for (double depth : table_depths(in.mono_plane, in.far)) {
        const rig::PixelError e = rig::error_at_depth(rig, depth);
        const rig::AngularError a = rig::angular_error_at_depth(rig, depth);
        const std::string label = std::isinf(depth) ? "infinity" : fixed(depth, 6);
        std::snprintf(line, sizeof line, "  %-14s %14.4f %14.4f %14.4f %16.4f\n", label.c_str(),
                      e.horizontal_px, e.euclidean_px, a.eye_arcmin, a.disparity_arcmin);
        out << line;
    }
    const rig::AngularError limit = rig::max_angular_error(rig);
    std::snprintf(line, sizeof line,
                  "max_error_px %.4f (horizontal: the disparity error), max_error_px_2d %.4f\n"
                  "max_error_arcmin %.4f (each eye), max_disparity_error_arcmin %.4f\n",
                  rig.max_error_px, rig.max_error_px_2d, limit.eye_arcmin, limit.disparity_arcmin);
    out << line;
}

void tangents_json(JsonWriter& j, std::string_view key, const rig::Tangents& t) {
    j.begin_object(key);
    j.value("tan_left", t.left).value("tan_right", t.right);
    j.value("tan_down", t.down).value("tan_up", t.up);
    j.end_object();
}

std::string summary_json(const hmd::HmdProfile& profile, const rig::Rig& rig) {
    const rig::RigInputs& in = rig.inputs;
    const rig::MonoCamera& c = rig.mono;
    JsonWriter j;
    j.begin_object();
    j.value("command", "rig").value("hmd", profile.name).value("hmd_source", profile.source);
    j.value("ipd", in.ipd).value("mono_plane", in.mono_plane);
    j.value("near", in.near).value("far", in.far).value("overlap_k", in.overlap_k);
    j.value("grazing_deg", in.grazing_angle * 180.0 / std::numbers::pi);
    j.value("nearest_mono_plane",
            in.nearest_mono_plane > 0.0 ? in.nearest_mono_plane : in.mono_plane);
    j.begin_object("eyes");
    j.value("width", in.eye_width).value("height", in.eye_height);
    tangents_json(j, "left", in.eyes[rig::kLeft]);
    tangents_json(j, "right", in.eyes[rig::kRight]);
    // Canted displays: each eye's yaw, degrees, positive turning it left.
    j.value("left_cant_deg", in.cant[rig::kLeft] * 180.0 / std::numbers::pi);
    j.value("right_cant_deg", in.cant[rig::kRight] * 180.0 / std::numbers::pi);
    j.end_object();
    j.value("mono_skipped", rig.mono_skipped);
    j.begin_object("mono_camera");
    j.value("offset_behind_eyes", c.offset_behind_eyes);
    j.value("tan_left", c.tangents.left).value("tan_right", c.tangents.right);
    j.value("tan_down", c.tangents.down).value("tan_up", c.tangents.up);
    j.value("width", c.width).value("height", c.height);
    j.value("near", c.near).value("far", c.far);
    j.value("viewport_width", c.viewport_width).value("viewport_height", c.viewport_height);
    j.value("allocated_width", c.allocated_width).value("allocated_height", c.allocated_height);
    j.value("uv_scale_x", c.uv_scale.x).value("uv_scale_y", c.uv_scale.y);
    j.value("mono_plane_ndc_depth", c.mono_plane_ndc_depth);
    j.end_object();
    j.value("overlap", rig.overlap);
    j.value("max_error_px", rig.max_error_px).value("max_error_px_2d", rig.max_error_px_2d);
    // The same suprema in visual angle (issue 20): arcminutes compare across headsets.
    const rig::AngularError limit = rig::max_angular_error(rig);
    j.value("max_error_arcmin", limit.eye_arcmin);
    j.value("max_disparity_error_arcmin", limit.disparity_arcmin);
    j.begin_array("error_at_depth");
    if (!rig.mono_skipped) {
        for (double depth : table_depths(in.mono_plane, in.far)) {
            if (std::isinf(depth)) continue;  // JSON has no infinity: max_error_px is the limit
            const rig::PixelError e = rig::error_at_depth(rig, depth);
            const rig::AngularError a = rig::angular_error_at_depth(rig, depth);
            j.begin_object();
            j.value("depth", depth).value("error_px", e.horizontal_px);
            j.value("error_px_2d", e.euclidean_px);
            j.value("error_arcmin", a.eye_arcmin)
                .value("disparity_error_arcmin", a.disparity_arcmin);
            j.end_object();
        }
    }
    j.end_array();
    j.end_object();
    return j.str();
}

// --- Fig. 2 (right): error over depth for several m --------------------------------------------

struct Fig2Series {
    double mono_plane = 0.0;
    std::vector<double> depths;
    std::vector<double> error_px;  // horizontal, as the paper plots
    std::vector<double> error_px_2d;
    double max_error_px = 0.0;  // the supremum, reached at infinite depth
};

std::string fig2_svg(const std::vector<Fig2Series>& series, const hmd::HmdProfile& profile,
                     const rig::RigInputs& in) {
    charts::LineChart chart;
    chart.layout.width = 960.0;
    chart.layout.height = 580.0;
    chart.layout.margins = {80.0, 20.0, 90.0, 70.0};
    chart.layout.legend_width = 220.0;
    chart.text.title = "Largest pixel offset of hybrid vs stereo over depth";
    chart.text.subtitle = profile.name + ": w = " + std::to_string(in.eye_width) +
                          " px, IPD = " + fixed(in.ipd, 6) + " m, k = " + fixed(in.overlap_k, 6);
    chart.text.note =
        "horizontal offset, largest over both eyes' fields (cf. Fink et al. 2019, Fig. 2 right); "
        "monoplane rig --fig2";

    // Depth from the decade at or below the nearest mono plane out to the far plane, where the
    // error reaches its supremum.
    double depth_min = kInfinity;
    for (const Fig2Series& s : series) depth_min = std::min(depth_min, s.mono_plane);
    chart.x_axis.label = "depth in front of the eyes (m, log scale)";
    chart.x_axis.scale = charts::ScaleKind::log10;
    chart.x_axis.min = std::pow(10.0, std::floor(std::log10(depth_min)));
    chart.x_axis.max = in.far;
    chart.y_axis.label = "largest horizontal offset (px)";
    chart.y_axis.include_zero = true;
    chart.y_axis.target_intervals = 6;

    // One line per m; 200 samples each, too dense for markers.
    for (const Fig2Series& s : series) {
        charts::LineSeries line;
        char name[96];
        std::snprintf(name, sizeof name, "m = %g m: max %.2f px", s.mono_plane, s.max_error_px);
        line.name = name;
        line.marker = charts::MarkerShape::none;
        for (std::size_t k = 0; k < s.depths.size(); ++k) {
            line.points.push_back({s.depths[k], s.error_px[k], std::nullopt, ""});
        }
        chart.series.push_back(std::move(line));
    }
    return charts::render_svg(chart);
}

void write_fig2(const RigOptions& o, const hmd::HmdProfile& profile) {
    const std::filesystem::path out = prepare_output_directory("--fig2", o.fig2_dir);
    if (o.fig2_mono_planes.empty()) throw UserError("--mono-planes: give at least one distance");

    std::vector<Fig2Series> series;
    std::optional<rig::RigInputs> shown_inputs;
    for (double m : o.fig2_mono_planes) {
        const rig::Rig rig = build_or_throw(o, profile, m);
        if (rig.mono_skipped) {
            std::cerr << "fig2: m = " << m << " >= far " << o.far
                      << ": nothing beyond the plane, left out\n";
            continue;
        }
        shown_inputs = rig.inputs;
        Fig2Series s;
        s.mono_plane = m;
        s.max_error_px = rig.max_error_px;
        const int samples = o.fig2_samples;
        for (int k = 0; k < samples; ++k) {
            // Log-spaced from m (error 0) to f.
            const double depth = m * std::pow(o.far / m, static_cast<double>(k) / (samples - 1));
            const rig::PixelError e = rig::error_at_depth(rig, depth);
            s.depths.push_back(depth);
            s.error_px.push_back(e.horizontal_px);
            s.error_px_2d.push_back(e.euclidean_px);
        }
        series.push_back(std::move(s));
    }
    if (series.empty()) throw UserError("--mono-planes: every distance is at or beyond --far");

    std::ofstream csv(out / "fig2.csv");
    csv << "mono_plane,depth,error_px,error_px_2d\n";
    csv.precision(10);
    for (const Fig2Series& s : series) {
        for (std::size_t k = 0; k < s.depths.size(); ++k) {
            csv << s.mono_plane << "," << s.depths[k] << "," << s.error_px[k] << ","
                << s.error_px_2d[k] << "\n";
        }
    }
    if (!csv) throw UserError("--fig2 " + o.fig2_dir + ": cannot write fig2.csv");
    charts::write_svg_file(out / "fig2.svg", fig2_svg(series, profile, *shown_inputs))
        .value_or_throw();
    std::cerr << "wrote " << (out / "fig2.csv").string() << " and " << (out / "fig2.svg").string()
              << "\n";
}

void run_rig(const RigOptions& o) {
    if (!o.mono_plane && o.fig2_dir.empty() && !o.error_budget_arcmin) {
        throw UserError(
            "give --mono-plane M for the rig at one distance, --fig2 DIR for the error plot of "
            "Fig. 2, --error-budget-arcmin A for the nearest m within a budget, or several");
    }
    const hmd::HmdProfile profile = hmd::load_hmd_profile(o.hmd).value_or_throw();
    if (o.error_budget_arcmin) {
        const rig::ErrorMeasure measure =
            o.disparity ? rig::ErrorMeasure::kDisparity : rig::ErrorMeasure::kEye;
        // The search ignores m: any valid one builds the inputs.
        const rig::RigInputs inputs = rig_inputs(o, profile, o.far);
        print_error_budget(std::cout, profile, inputs, *o.error_budget_arcmin, measure,
                           o.budget_depth, o.json && !o.mono_plane);
        if (!o.mono_plane && o.fig2_dir.empty()) return;
    }
    if (!o.fig2_dir.empty()) write_fig2(o, profile);
    if (o.mono_plane) {
        const rig::Rig rig = build_or_throw(o, profile, *o.mono_plane);
        if (o.json) {
            std::cout << summary_json(profile, rig) << "\n";
        } else {
            print_summary(std::cout, profile, rig);
        }
    }
}

}  // namespace

void add_rig_command(CLI::App& root, const GlobalOptions& /*global: no GPU here*/) {
    auto options = std::make_shared<RigOptions>();
    CLI::App* cmd = root.add_subcommand(
        "rig",
        "The hybrid camera rig of an HMD at a mono-plane distance (Fink et al. 2019, eq. 1-8) and "
        "its projection error; --fig2 writes the error-over-depth plot");
    cmd->add_option("--hmd", options->hmd,
                    "HMD profile: vive, vive-pro, symmetric-90, symmetric-110 or a TOML file")
        ->capture_default_str();
    cmd->add_option("--ipd", options->ipd,
                    "Interpupillary distance d in metres (default: the profile's)");
    cmd->add_option("--mono-plane", options->mono_plane, "Mono-plane distance m in metres");
    cmd->add_option("--far", options->far, "Far plane f in metres")->capture_default_str();
    cmd->add_option("--near", options->near, "Near plane n in metres")->capture_default_str();
    cmd->add_option("--k", options->overlap_k, "Overlap constant k of eps = k s m (eq. 3)")
        ->capture_default_str();
    cmd->add_option("--grazing-deg", options->grazing_deg,
                    "Grow eps so that surfaces down to this angle to the view rays show no "
                    "cutting line (C's pixel footprint; 0: eps = k s m alone; docs/hybrid.md)")
        ->capture_default_str();
    cmd->add_option("--nearest-mono-plane", options->nearest_mono_plane,
                    "Allocate C's image for this nearest selectable m (Sect. 4.2; default: m)");
    cmd->add_flag("--json", options->json,
                  "Print the rig (or with --error-budget-arcmin alone, the choice) as JSON (keys: "
                  "docs/hybrid.md)");
    cmd->add_option("--error-budget-arcmin", options->error_budget_arcmin,
                    "Print the nearest m whose error in visual angle stays within this many "
                    "arcminutes (each eye's error; --disparity: the disparity error)")
        ->check(CLI::PositiveNumber);
    cmd->add_flag("--disparity", options->disparity,
                  "With --error-budget-arcmin: bound the change of binocular disparity instead");
    cmd->add_option("--budget-depth", options->budget_depth,
                    "With --error-budget-arcmin: the farthest depth in metres the budget must hold "
                    "for (default: infinity, any scene)")
        ->check(CLI::PositiveNumber);
    cmd->add_option("--fig2", options->fig2_dir,
                    "Write fig2.csv and fig2.svg (error over depth per m, cf. the paper's Fig. 2 "
                    "right) to this directory");
    cmd->add_option("--mono-planes", options->fig2_mono_planes,
                    "Mono planes for --fig2, comma-separated (default: the fink2019 protocol's)")
        ->delimiter(',');
    cmd->add_option("--samples", options->fig2_samples, "Depth samples per m for --fig2")
        ->check(CLI::Range(2, 100000))
        ->capture_default_str();
    cmd->callback([options] { run_rig(*options); });
}

}  // namespace monoplane::app
