// `monoplane rig`: the triple-frustum rig of an HMD profile at one mono-plane distance (DESIGN.md
// sections 3 and 8), as a readable summary or JSON, and with --fig2 the projection error over
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
#include "app/commands/json_writer.h"
#include "hmd/profile.h"
#include "renderer/rig/rig.h"

namespace monoplane::app {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The mono-plane distances of the fink2019 protocol (DESIGN.md section 7).
const std::vector<double> kFink2019MonoPlanes = {1.6, 3, 5, 8, 12, 16, 20, 25, 31, 39.5};

struct RigOptions {
    std::string hmd = "vive";
    std::optional<double> ipd;
    std::optional<double> mono_plane;
    double near = 0.1;
    double far = 1000.0;
    double overlap_k = 2.0;
    double nearest_mono_plane = 0.0;
    bool json = false;
    std::string fig2_dir;
    std::vector<double> fig2_mono_planes = kFink2019MonoPlanes;
    int fig2_samples = 200;
};

rig::RigInputs rig_inputs(const RigOptions& o, const hmd::HmdProfile& profile, double m) {
    rig::RigInputs in = hmd::rig_inputs(profile, m);
    in.ipd = o.ipd.value_or(profile.ipd);
    in.near = o.near;
    in.far = o.far;
    in.overlap_k = o.overlap_k;
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
    std::snprintf(line, sizeof line,
                  "  overlap eps   %.6f m (k s m): C starts at %.6f m in front of the eyes\n",
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
    std::snprintf(line, sizeof line, "  %-14s %14s %14s\n", "depth (m)", "horizontal px", "2d px");
    out << line;
    for (double depth : table_depths(in.mono_plane, in.far)) {
        const rig::PixelError e = rig::error_at_depth(rig, depth);
        const std::string label = std::isinf(depth) ? "infinity" : fixed(depth, 6);
        std::snprintf(line, sizeof line, "  %-14s %14.4f %14.4f\n", label.c_str(), e.horizontal_px,
                      e.euclidean_px);
        out << line;
    }
    std::snprintf(line, sizeof line,
                  "max_error_px %.4f (horizontal: the disparity error), max_error_px_2d %.4f\n",
                  rig.max_error_px, rig.max_error_px_2d);
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
    j.value("nearest_mono_plane",
            in.nearest_mono_plane > 0.0 ? in.nearest_mono_plane : in.mono_plane);
    j.begin_object("eyes");
    j.value("width", in.eye_width).value("height", in.eye_height);
    tangents_json(j, "left", in.eyes[rig::kLeft]);
    tangents_json(j, "right", in.eyes[rig::kRight]);
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
    j.begin_array("error_at_depth");
    if (!rig.mono_skipped) {
        for (double depth : table_depths(in.mono_plane, in.far)) {
            if (std::isinf(depth)) continue;  // JSON has no infinity: max_error_px is the limit
            const rig::PixelError e = rig::error_at_depth(rig, depth);
            j.begin_object();
            j.value("depth", depth).value("error_px", e.horizontal_px);
            j.value("error_px_2d", e.euclidean_px);
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

std::string xml_escaped(std::string_view text) {
    std::string out;
    for (char ch : text) {
        switch (ch) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += ch;
        }
    }
    return out;
}

// A round step (1, 2 or 5 times a power of ten) giving about `ticks` intervals up to `top`.
double nice_step(double top, int ticks) {
    const double raw = top / ticks;
    const double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double factor : {1.0, 2.0, 5.0}) {
        if (factor * decade >= raw) return factor * decade;
    }
    return 10.0 * decade;
}

std::string tick_label(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::string fig2_svg(const std::vector<Fig2Series>& series, const hmd::HmdProfile& profile,
                     const rig::RigInputs& in) {
    // Tableau 10: distinguishable and colour-blind-tolerable for up to ten lines.
    static const char* const kColors[] = {"#4e79a7", "#f28e2b", "#e15759", "#76b7b2", "#59a14f",
                                          "#edc948", "#b07aa1", "#ff9da7", "#9c755f", "#bab0ac"};
    constexpr double kWidth = 960.0;
    constexpr double kHeight = 580.0;
    constexpr double kLeft = 80.0;
    constexpr double kRight = 720.0;
    constexpr double kTop = 90.0;
    constexpr double kBottom = 510.0;

    double depth_min = kInfinity;
    double error_max = 0.0;
    for (const Fig2Series& s : series) {
        depth_min = std::min(depth_min, s.mono_plane);
        for (double e : s.error_px) error_max = std::max(error_max, e);
    }
    const double log_min = std::floor(std::log10(depth_min));
    const double log_max = std::log10(in.far);
    const double y_step = nice_step(std::max(error_max, 1e-9), 6);
    const double y_top = std::ceil(std::max(error_max, 1e-9) / y_step) * y_step;
    auto x_of = [&](double depth) {
        return kLeft + (std::log10(depth) - log_min) / (log_max - log_min) * (kRight - kLeft);
    };
    auto y_of = [&](double px) { return kBottom - px / y_top * (kBottom - kTop); };

    std::ostringstream svg;
    svg.precision(6);
    svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\""
        << kHeight << "\" viewBox=\"0 0 " << kWidth << " " << kHeight
        << "\" font-family=\"Helvetica, Arial, sans-serif\" font-size=\"13\">\n";
    svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    svg << "<text x=\"" << kWidth / 2 << "\" y=\"28\" text-anchor=\"middle\" font-size=\"17\" "
        << "font-weight=\"bold\">Largest pixel offset of hybrid vs stereo over depth</text>\n";
    svg << "<text x=\"" << kWidth / 2 << "\" y=\"50\" text-anchor=\"middle\">"
        << xml_escaped(profile.name) << ": w = " << in.eye_width << " px, IPD = " << in.ipd
        << " m, k = " << in.overlap_k << "</text>\n";
    svg << "<text x=\"" << kWidth / 2 << "\" y=\"70\" text-anchor=\"middle\" fill=\"#555\" "
        << "font-size=\"12\">horizontal offset, largest over both eyes' fields "
        << "(cf. Fink et al. 2019, Fig. 2 right); monoplane rig --fig2</text>\n";

    // Grid and ticks: decades labelled, 2..9 as light lines; pixel steps.
    svg << "<g stroke=\"#e5e5e5\" stroke-width=\"1\">\n";
    for (int decade = static_cast<int>(log_min); decade <= static_cast<int>(log_max); ++decade) {
        for (int k = 1; k <= 9; ++k) {
            const double depth = k * std::pow(10.0, decade);
            if (depth < std::pow(10.0, log_min) || std::log10(depth) > log_max + 1e-12) continue;
            const double x = x_of(depth);
            svg << "<line x1=\"" << x << "\" y1=\"" << kTop << "\" x2=\"" << x << "\" y2=\""
                << kBottom << "\"" << (k == 1 ? " stroke=\"#c8c8c8\"" : "") << "/>\n";
        }
    }
    for (double px = y_step; px <= y_top + 1e-9; px += y_step) {
        svg << "<line x1=\"" << kLeft << "\" y1=\"" << y_of(px) << "\" x2=\"" << kRight
            << "\" y2=\"" << y_of(px) << "\"/>\n";
    }
    svg << "</g>\n";
    svg << "<g text-anchor=\"middle\">\n";
    for (int decade = static_cast<int>(log_min); decade <= static_cast<int>(log_max); ++decade) {
        const double depth = std::pow(10.0, decade);
        svg << "<line x1=\"" << x_of(depth) << "\" y1=\"" << kBottom << "\" x2=\"" << x_of(depth)
            << "\" y2=\"" << kBottom + 6 << "\" stroke=\"black\"/>\n";
        svg << "<text x=\"" << x_of(depth) << "\" y=\"" << kBottom + 22 << "\">"
            << tick_label(depth) << "</text>\n";
    }
    svg << "</g>\n<g text-anchor=\"end\">\n";
    for (double px = 0.0; px <= y_top + 1e-9; px += y_step) {
        svg << "<line x1=\"" << kLeft - 6 << "\" y1=\"" << y_of(px) << "\" x2=\"" << kLeft
            << "\" y2=\"" << y_of(px) << "\" stroke=\"black\"/>\n";
        svg << "<text x=\"" << kLeft - 10 << "\" y=\"" << y_of(px) + 4 << "\">" << tick_label(px)
            << "</text>\n";
    }
    svg << "</g>\n";
    svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << kRight - kLeft
        << "\" height=\"" << kBottom - kTop << "\" fill=\"none\" stroke=\"black\"/>\n";
    svg << "<text x=\"" << (kLeft + kRight) / 2 << "\" y=\"" << kBottom + 48
        << "\" text-anchor=\"middle\">depth in front of the eyes (m, log scale)</text>\n";
    svg << "<text transform=\"translate(" << kLeft - 52 << " " << (kTop + kBottom) / 2
        << ") rotate(-90)\" text-anchor=\"middle\">largest horizontal offset (px)</text>\n";

    // One line per m, and a legend on the right.
    for (std::size_t i = 0; i < series.size(); ++i) {
        const Fig2Series& s = series[i];
        const char* color = kColors[i % std::size(kColors)];
        svg << "<polyline fill=\"none\" stroke=\"" << color
            << "\" stroke-width=\"2\" stroke-linejoin=\"round\" points=\"";
        for (std::size_t k = 0; k < s.depths.size(); ++k) {
            svg << (k ? " " : "") << x_of(s.depths[k]) << "," << y_of(s.error_px[k]);
        }
        svg << "\"/>\n";
        const double legend_y = kTop + 12 + 22.0 * static_cast<double>(i);
        svg << "<line x1=\"" << kRight + 20 << "\" y1=\"" << legend_y << "\" x2=\"" << kRight + 48
            << "\" y2=\"" << legend_y << "\" stroke=\"" << color << "\" stroke-width=\"3\"/>\n";
        char label[96];
        std::snprintf(label, sizeof label, "m = %g m: max %.2f px", s.mono_plane, s.max_error_px);
        svg << "<text x=\"" << kRight + 54 << "\" y=\"" << legend_y + 4 << "\">" << label
            << "</text>\n";
    }
    svg << "</svg>\n";
    return svg.str();
}

void write_fig2(const RigOptions& o, const hmd::HmdProfile& profile) {
    // Validate the output path before any work, so nothing is computed and then lost.
    const std::filesystem::path out(o.fig2_dir);
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec || !std::filesystem::is_directory(out)) {
        throw UserError("--fig2 " + o.fig2_dir + ": cannot create the directory (" + ec.message() +
                        ")");
    }
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
    std::ofstream(out / "fig2.svg") << fig2_svg(series, profile, *shown_inputs);
    if (!csv) throw UserError("--fig2 " + o.fig2_dir + ": cannot write fig2.csv");
    std::cerr << "wrote " << (out / "fig2.csv").string() << " and " << (out / "fig2.svg").string()
              << "\n";
}

void run_rig(const RigOptions& o) {
    if (!o.mono_plane && o.fig2_dir.empty()) {
        throw UserError(
            "give --mono-plane M for the rig at one distance, --fig2 DIR for the error plot of "
            "Fig. 2, or both");
    }
    const hmd::HmdProfile profile = hmd::load_hmd_profile(o.hmd).value_or_throw();
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
    CLI::Option* mono_plane =
        cmd->add_option("--mono-plane", options->mono_plane, "Mono-plane distance m in metres");
    cmd->add_option("--far", options->far, "Far plane f in metres")->capture_default_str();
    cmd->add_option("--near", options->near, "Near plane n in metres")->capture_default_str();
    cmd->add_option("--k", options->overlap_k, "Overlap constant k of eps = k s m (eq. 3)")
        ->capture_default_str();
    cmd->add_option("--nearest-mono-plane", options->nearest_mono_plane,
                    "Allocate C's image for this nearest selectable m (Sect. 4.2; default: m)");
    cmd->add_flag("--json", options->json, "Print the rig as JSON (keys: DESIGN.md section 8)")
        ->needs(mono_plane);
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
