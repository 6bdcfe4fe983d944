// `monoplane bench`: sweeps scenes x modes x variants x mono planes,
// measures GPU time per pass, pipeline statistics and each hybrid configuration's accuracy
// against stereo, and writes bench.json, bench.csv and the figures of app/bench/bench_plots.h.
// Speed is reported as ratios to stereo within one run.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>

#include <unistd.h>

#include "app/bench/bench_plots.h"
#include "app/bench/bench_results.h"
#include "app/commands/auto_mono_plane_options.h"
#include "app/commands/commands.h"
#include "app/commands/frame_summary.h"
#include "app/commands/image_quality_options.h"
#include "app/commands/lod_flags.h"
#include "app/commands/output_directory.h"
#include "app/commands/scene_source.h"
#include "app/commands/validation_report.h"
#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/passes/shared/view_constants.h"
#include "renderer/profile/driver_compiles.h"
#include "renderer/quality/channel_difference.h"
#include "renderer/quality/drift.h"
#include "renderer/quality/ssim.h"
#include "renderer/vk/context.h"
#include "rig/angular_error.h"
#include "rig/pose_path.h"
#include "scenes/generate.h"
#include "study/protocol.h"

namespace monoplane::app {
namespace {

// The ten distances of protocols/fink2019.toml (papers/000 Sect. 6) and the far plane.
constexpr const char* kDefaultMonoPlanes = "1.6,3,5,8,12,16,20,25,31,39.5,far";

struct BenchOptions {
    std::string scenes = "beams,landscape,spheres";
    std::string modes = "stereo,hybrid,hybrid-farfield";
    std::string variants = "no-opt,discard,occlusion-cull";
    std::string mono_planes = kDefaultMonoPlanes;
    std::string protocol;  // takes the mono planes from a protocol (plus far)
    std::string hmd = "vive";
    int width = 0;
    int height = 0;
    std::string detail = "low";
    std::string view = "default";
    std::uint64_t seed = scenes::kDefaultSeed;
    int frames = 10;
    int warmup = 3;
    bool accuracy = true;
    std::string anti_aliasing = "none";
    std::string ssao = "off";
    std::string stereo_pass = "two";
    std::uint32_t vertex_work = 0;
    double grazing_deg = 1.0;  // rig::RigInputs::grazing_angle, degrees
    bool depth_prepass = false;
    bool separate_tonemap = false;  // RendererOptions::separate_tonemap in every run
    AutoMonoPlaneFlags auto_flags;  // the "auto" entry of --mono-planes
    int auto_warmup = 40;           // extra warm-up frames for auto to settle on its m
    int turning_frames = 0;         // pairs of still and turning-head frames per run (0: none)
    LodFlags lod;                   // a sweep: "off,auto"
    std::string out;
};

std::vector<std::string> split_list(const std::string& text) {
    std::vector<std::string> items;
    std::stringstream stream(text);
    std::string item;
    while (std::getline(stream, item, ',')) {
        item.erase(0, item.find_first_not_of(" \t"));
        item.erase(item.find_last_not_of(" \t") + 1);
        if (!item.empty()) items.push_back(item);
    }
    return items;
}

// A mono plane of the sweep: metres, the far plane, or chosen by the renderer every frame.
struct Plane {
    double metres = 0.0;
    bool far = false;
    bool automatic = false;
};

std::vector<Plane> parse_planes(const BenchOptions& o, double far) {
    std::vector<Plane> planes;
    if (!o.protocol.empty()) {
        const study::Protocol protocol = study::load_protocol(o.protocol).value_or_throw();
        for (double m : protocol.mono_planes) planes.push_back({m, false});
        planes.push_back({far, true});
        return planes;
    }
    for (const std::string& item : split_list(o.mono_planes)) {
        if (item == "far") {
            planes.push_back({far, true});
            continue;
        }
        if (item == "auto") {
            planes.push_back({far, false, true});
            continue;
        }
        char* end = nullptr;
        const double m = std::strtod(item.c_str(), &end);
        if (end == item.c_str() || *end != '\0' || !std::isfinite(m) || m <= 0.1) {
            throw UserError("--mono-planes: '" + item +
                            "' is not a distance in metres beyond the near plane (0.1), 'far' "
                            "or 'auto'");
        }
        planes.push_back({std::min(m, far), m >= far});
    }
    if (planes.empty()) throw UserError("--mono-planes: no distance given");
    return planes;
}

std::string plane_text(double metres) {
    std::ostringstream text;
    text << metres;
    return text.str();
}

// One line of progress on stderr, rewritten in place.
class Progress {
  public:
    explicit Progress(int total)
        : total_(total), start_(std::chrono::steady_clock::now()), terminal_(isatty(2) != 0) {}

    void show(int done, const std::string& what) const {
        constexpr int kWidth = 24;
        const int filled = total_ > 0 ? done * kWidth / total_ : kWidth;
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        std::ostringstream line;
        line << "\r[" << std::string(static_cast<std::size_t>(filled), '#')
             << std::string(static_cast<std::size_t>(kWidth - filled), '-') << "] " << done << "/"
             << total_ << " " << what;
        if (done > 0 && done < total_) {
            const double remaining = elapsed / done * (total_ - done);
            line << "  about " << static_cast<int>(remaining / 60) << " min "
                 << static_cast<int>(std::fmod(remaining, 60.0)) << " s left";
        }
        // A terminal gets one line rewritten in place; a log file one line per step.
        if (terminal_) {
            std::cerr << std::left << std::setw(110) << line.str() << std::flush;
        } else {
            std::cerr << line.str().substr(1) << "\n";
        }
    }

  private:
    int total_;
    std::chrono::steady_clock::time_point start_;
    bool terminal_;
};

// The pixels a view's passes cover: an eye's image (its composite and transparency too), both
// eyes' for the single-pass "eyes", C's viewport (eq. 8) for "mono"; 0 for a view it does not
// know.
std::uint64_t view_pixels(const modes::ModeRenderer& renderer, const std::string& view) {
    const vk::Extent2D eye = renderer.eye_extent();
    const std::uint64_t eye_pixels = std::uint64_t{eye.width} * eye.height;
    if (view == "left" || view == "right" || view.ends_with(".composite") ||
        view.ends_with(".transparency")) {
        return eye_pixels;
    }
    if (view == "eyes") return 2 * eye_pixels;
    if (view == "mono" && renderer.last_rig()) {
        const rig::MonoCamera& mono = renderer.last_rig()->mono;
        return static_cast<std::uint64_t>(mono.viewport_width) *
               static_cast<std::uint64_t>(mono.viewport_height);
    }
    return 0;
}

// The turning-head configuration (--turning-frames): after a run's measured frames, the same
// renderer alternates the run's still pose with poses along the "turn" path (yaw back and forth
// at 30 degrees a second, 90 frames a second: every turning pose is new). A turning frame's GPU
// time over the still frame beside it, median over the pairs; the driver's compiles over those
// frames where they can be counted, and their share of the wall time. A driver that keys shader
// variants on view-dependent values compiles on every turning frame and the ratio shows it.
void measure_turning(modes::ModeRenderer& renderer, const modes::FrameInputs& still, int pairs,
                     BenchRun& run) {
    const rig::PosePath turn = *rig::builtin_pose_path("turn");
    constexpr double kFrameRateHz = 90.0;
    std::vector<profile::FrameStats> frames;
    const auto wall_start = std::chrono::steady_clock::now();
    const profile::DriverCompiles before = profile::driver_compiles();
    for (int i = 0; i < 2 * pairs; ++i) {
        modes::FrameInputs inputs = still;
        if (i % 2 == 1) {
            inputs.views.head = rig::pose_along(turn, still.views.head, (i / 2 + 1) / kFrameRateHz);
        }
        renderer.submit_frame(inputs);
        for (profile::FrameStats& s : renderer.take_completed()) frames.push_back(std::move(s));
    }
    for (profile::FrameStats& s : renderer.finish_frames()) frames.push_back(std::move(s));
    const double wall_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
    const profile::DriverCompiles during =
        profile::compiles_between(before, profile::driver_compiles());
    std::vector<double> ratios;
    for (std::size_t i = 1; i < frames.size(); i += 2) {
        if (frames[i - 1].gpu_frame_ms > 0.0) {
            ratios.push_back(frames[i].gpu_frame_ms / frames[i - 1].gpu_frame_ms);
        }
    }
    run.turning_frames = pairs;
    if (!ratios.empty()) run.turning_time_ratio = percentile(ratios, 0.5);
    if (during.measurable) {
        run.turning_driver_compiles = during.modules;
        run.turning_compile_share = wall_s > 0.0 ? during.seconds / wall_s : 0.0;
    }
}

// Warm-up frames (shader compilation, the one-off shadow map, C's allocation), then measured
// frames without read-back. With a reference renderer (stereo), its frames are interleaved with
// the measured ones (in alternating order) and the time ratio is the median of the per-pair
// ratios: a CPU rasterizer on a shared machine drifts by tens of percent over minutes, and only
// frames taken side by side compare.
BenchRun measure(modes::ModeRenderer& renderer, const modes::FrameInputs& inputs,
                 const BenchOptions& o, modes::ModeRenderer* reference = nullptr,
                 const modes::FrameInputs* reference_inputs = nullptr) {
    renderer.set_read_back(false);
    if (reference) reference->set_read_back(false);
    // Frames in flight: nothing waits for the GPU until the end; each renderer's statistics
    // arrive in submission order, so frame i of one pairs with frame i of the other.
    std::vector<profile::FrameStats> measured;
    std::vector<profile::FrameStats> paired;
    const auto take = [](modes::ModeRenderer& r, std::vector<profile::FrameStats>& into,
                         bool finish) {
        for (profile::FrameStats& stats : finish ? r.finish_frames() : r.take_completed()) {
            into.push_back(std::move(stats));
        }
    };
    for (int i = 0; i < o.warmup + o.frames; ++i) {
        if (reference && i % 2 == 0) reference->submit_frame(*reference_inputs);
        renderer.submit_frame(inputs);
        if (reference && i % 2 == 1) reference->submit_frame(*reference_inputs);
        take(renderer, measured, false);
        if (reference) take(*reference, paired, false);
    }
    take(renderer, measured, true);
    if (reference) take(*reference, paired, true);
    std::vector<profile::FrameStats> frames;
    std::vector<double> ratios;
    std::vector<double> reference_ms;
    std::vector<double> frame_mono_planes;
    for (std::size_t i = static_cast<std::size_t>(o.warmup); i < measured.size(); ++i) {
        if (reference && i < paired.size() && paired[i].gpu_frame_ms > 0.0) {
            ratios.push_back(measured[i].gpu_frame_ms / paired[i].gpu_frame_ms);
            reference_ms.push_back(paired[i].gpu_frame_ms);
        }
        if (measured[i].mono_plane) frame_mono_planes.push_back(*measured[i].mono_plane);
        frames.push_back(std::move(measured[i]));
    }
    const FrameSummary summary = summarize(frames);
    BenchRun run;
    run.frames = summary.frames;
    run.frame_ms_median = summary.frame_ms_median;
    run.frame_ms_p90 = summary.frame_ms_p90;
    run.cpu_ms_median = summary.cpu_ms_median;
    run.frame_ms_p10 = summary.frame_ms_p10;
    run.pass_ms_median = summary.pass_ms_median;
    run.pass_ms_p10 = summary.pass_ms_p10;
    run.pass_ms_p90 = summary.pass_ms_p90;
    if (!ratios.empty()) {
        run.time_ratio = percentile(ratios, 0.5);
        run.time_ratio_p25 = percentile(ratios, 0.25);
        run.time_ratio_p75 = percentile(ratios, 0.75);
        run.stereo_frame_ms_median = percentile(reference_ms, 0.5);
    }
    run.plan = renderer.last_plan();
    run.frame_mono_planes = std::move(frame_mono_planes);
    for (const profile::ViewStatistics& v : summary.views) {
        run.fragments += v.fragment_invocations;
        run.view_fragments[v.view] = v.fragment_invocations;
        if (const std::uint64_t pixels = view_pixels(renderer, v.view); pixels > 0) {
            run.view_fragments_per_pixel[v.view] =
                static_cast<double>(v.fragment_invocations) / static_cast<double>(pixels);
        }
        if (v.view.ends_with(".composite")) continue;  // not scene work (transparency is)
        run.primitives += v.clipping_invocations;
        run.vertex_invocations += v.vertex_invocations;
        run.geometry_invocations += v.geometry_invocations;
        run.view_primitives[v.view] = v.clipping_invocations;
        run.view_draws[v.view] = v.draws;
    }
    if (o.turning_frames > 0) measure_turning(renderer, inputs, o.turning_frames, run);
    return run;
}

// The stereo reference's images and depth, for the accuracy of every hybrid configuration.
struct Reference {
    std::array<modes::RgbaImage, 2> images;
    std::array<std::vector<float>, 2> depth;
};

struct Accuracy {
    double ssim = 0.0;
    double mean_abs_difference = 0.0;  // 8-bit levels, mean of both eyes
    double drift_px = 0.0;
    std::size_t drift_patches = 0;
};

// Single-pass stereo against two-pass stereo: the largest channel difference of either eye.
int max_channel_difference(modes::ModeRenderer& renderer, const modes::FrameInputs& inputs,
                           const Reference& reference) {
    renderer.set_read_back(true);
    renderer.render_frame(inputs);
    renderer.set_read_back(false);
    int largest = 0;
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        largest = std::max(largest, quality::max_channel_difference(
                                        quality::rgba_view(reference.images[static_cast<int>(eye)]),
                                        quality::rgba_view(renderer.eye_image(eye)))
                                        .value_or_throw());
    }
    return largest;
}

// beyond_m: where the drift is measured (stereo's pixels beyond it); inputs.mono_plane unless the
// renderer chooses m itself.
Accuracy measure_accuracy(modes::ModeRenderer& renderer, const modes::FrameInputs& inputs,
                          const Reference& reference, std::optional<double> beyond_m = {}) {
    renderer.set_read_back(true);
    renderer.render_frame(inputs);
    renderer.set_read_back(false);
    Accuracy accuracy;
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        const int e = static_cast<int>(eye);
        const quality::ImageView a = quality::rgba_view(reference.images[e]);
        const quality::ImageView b = quality::rgba_view(renderer.eye_image(eye));
        accuracy.ssim += 0.5 * quality::ssim(a, b).value_or_throw().mean;
        accuracy.mean_abs_difference +=
            0.5 * quality::mean_channel_difference(a, b).value_or_throw();
        // Drift where stereo sees beyond the plane (where hybrid can differ at all).
        std::vector<std::uint8_t> beyond(reference.depth[e].size());
        for (std::size_t i = 0; i < beyond.size(); ++i) {
            beyond[i] = reference.depth[e][i] > beyond_m.value_or(inputs.mono_plane) ? 1 : 0;
        }
        const quality::DriftMeasurement drift =
            quality::measure_drift(a, b, beyond).value_or_throw();
        accuracy.drift_px = std::max(accuracy.drift_px, drift.p95_px);
        accuracy.drift_patches += drift.patches;
    }
    return accuracy;
}

// The farthest depth either eye of the stereo reference shows (the sky left out): no pixel a
// configuration shows lies beyond it, so the error there bounds every visible pixel's.
double farthest_visible_depth(const Reference& reference) {
    double farthest = 0.0;
    for (const std::vector<float>& depth : reference.depth) {
        for (const float d : depth) {
            if (d < 0.5f * static_cast<float>(MONOPLANE_SKY_LINEAR_DEPTH)) {
                farthest = std::max(farthest, static_cast<double>(d));
            }
        }
    }
    return farthest;
}

struct AutoRunContext {
    const hmd::HmdProfile& profile;
    vk::Extent2D extent;
    double visible_depth = 0.0;
    const Reference& reference;
};

// Each eye's error at `depth` for the profile's rig at m (0 at or beyond the far plane).
double eye_error_arcmin(const AutoRunContext& c, const modes::FrameInputs& inputs, double m,
                        double depth) {
    if (m >= inputs.views.far) return 0.0;
    rig::RigInputs in = hmd::rig_inputs(c.profile, m);
    in.eye_width = static_cast<int>(c.extent.width);
    in.eye_height = static_cast<int>(c.extent.height);
    in.ipd = inputs.views.ipd;
    in.near = inputs.views.near;
    in.far = inputs.views.far;
    return rig::angular_error_at_depth(rig::build_rig(in).value_or_throw(), depth).eye_arcmin;
}

// An auto run: warm-up frames for the chooser to settle (o.auto_warmup more than fixed runs),
// measured frames against interleaved stereo, the m it chose per frame, the largest visible
// error over them, and the accuracy of one more frame.
BenchRun measure_auto(modes::ModeRenderer& renderer, modes::FrameInputs inputs,
                      modes::MonoCulling variant, const BenchOptions& o,
                      const AutoRunContext& context, modes::ModeRenderer& stereo,
                      const modes::FrameInputs& stereo_inputs) {
    inputs.mono_culling = variant;
    BenchOptions longer = o;
    longer.warmup = o.warmup + o.auto_warmup;
    BenchRun run = measure(renderer, inputs, longer, &stereo, &stereo_inputs);
    run.mode = modes::mode_name(modes::Mode::kHybrid);
    run.variant = modes::mono_culling_name(variant);
    if (variant == modes::MonoCulling::kAuto) {
        run.variant_chosen = modes::mono_culling_name(renderer.last_variant());
    }
    run.mono_plane_auto = true;
    std::vector<double> planes = run.frame_mono_planes;
    if (!planes.empty()) {
        std::sort(planes.begin(), planes.end());
        run.mono_plane = planes[planes.size() / 2];
        run.mono_plane_min = planes.front();
        run.mono_plane_max = planes.back();
        double worst = 0.0;
        for (const double m : run.frame_mono_planes) {
            worst = std::max(worst, eye_error_arcmin(context, inputs, m, context.visible_depth));
            if (m >= inputs.views.far) ++run.stereo_frames;
        }
        run.visible_error_arcmin = worst;
        run.max_error_arcmin = eye_error_arcmin(context, inputs, *run.mono_plane,
                                                std::numeric_limits<double>::infinity());
    }
    if (renderer.last_rig()) run.max_error_px = renderer.last_rig()->max_error_px;
    if (o.accuracy) {
        const Accuracy accuracy = measure_accuracy(renderer, inputs, context.reference,
                                                   run.mono_plane.value_or(inputs.views.far));
        run.ssim_vs_stereo = accuracy.ssim;
        run.drift_px = accuracy.drift_px;
        run.drift_patches = accuracy.drift_patches;
    }
    return run;
}

// The sweep the options ask for, checked before anything is loaded.
struct BenchSweep {
    std::vector<SceneSource> scene_sources;
    std::vector<modes::RenderModeChoice> mode_choices;
    modes::StereoPass hybrid_stereo_pass = modes::StereoPass::kTwoPasses;  // --stereo-pass
    std::vector<modes::MonoCulling> variants;                              // hybrid's
    std::vector<modes::LodOptions> lods;                                   // --lod, in order
    scenes::Detail detail{};
};

BenchSweep parse_sweep(const BenchOptions& o) {
    BenchSweep sweep;
    for (const std::string& name : split_list(o.scenes)) {
        Result<SceneSource> source = parse_scene_source(name);
        if (!source) throw UserError("--scenes: '" + name + "': " + source.error().message);
        sweep.scene_sources.push_back(std::move(source).value());
    }
    for (const std::string& name : split_list(o.modes)) {
        const auto mode = modes::parse_render_mode(name);
        if (!mode) {
            throw UserError("--modes: '" + name +
                            "' is not stereo, stereo-multiview, stereo-gs, stereo-instanced, "
                            "hybrid or hybrid-farfield");
        }
        sweep.mode_choices.push_back(*mode);
    }
    sweep.hybrid_stereo_pass = parse_stereo_pass_flag(o.stereo_pass);
    for (const std::string& name : split_list(o.variants)) {
        const auto variant = modes::parse_mono_culling(name);
        if (!variant) {
            throw UserError("--variants: '" + name +
                            "' is not no-opt, discard, occlusion-cull or auto");
        }
        sweep.variants.push_back(*variant);
    }
    sweep.lods = parse_lod_list(o.lod);
    const auto detail = scenes::parse_detail(o.detail);
    if (!detail) throw UserError("--detail " + o.detail + ": use test, low, medium, high or ultra");
    sweep.detail = *detail;
    if ((o.width > 0) != (o.height > 0)) throw UserError("--width and --height go together");
    if (sweep.scene_sources.empty() || sweep.mode_choices.empty())
        throw UserError("nothing to measure");
    return sweep;
}

// Two-pass stereo is every scene's reference, measured once before the other modes.
bool is_two_pass_stereo(const modes::RenderModeChoice& m) {
    return m.mode == modes::Mode::kStereo && m.stereo_pass == modes::StereoPass::kTwoPasses;
}

// What every run renders with: the headset, the image size, the mono planes and the renderers'
// options.
struct BenchSetup {
    hmd::HmdProfile profile;
    vk::Extent2D extent;
    modes::FrameInputs base;  // every scene's inputs, less its viewpoint
    std::vector<Plane> planes;
    double nearest = 0.0;  // the nearest fixed plane: sizes C's render target once
    modes::AutoMonoPlaneParams auto_params;
    modes::RendererOptions renderer_options;
};

BenchSetup prepare_setup(const BenchOptions& o, const BenchSweep& sweep) {
    BenchSetup setup;
    setup.profile = hmd::load_hmd_profile(o.hmd).value_or_throw();
    const hmd::HmdProfile& profile = setup.profile;
    setup.extent =
        vk::Extent2D(static_cast<std::uint32_t>(o.width > 0 ? o.width : profile.width),
                     static_cast<std::uint32_t>(o.height > 0 ? o.height : profile.height));
    modes::FrameInputs& base = setup.base;
    base.views.ipd = profile.ipd;
    base.views.left = profile.left;
    base.views.right = profile.right;
    base.views.cant = hmd::cant_radians(profile);
    base.grazing_angle = o.grazing_deg * std::numbers::pi / 180.0;
    setup.planes = parse_planes(o, base.views.far);
    setup.nearest = base.views.far;
    for (const Plane& p : setup.planes) {
        if (!p.automatic) setup.nearest = std::min(setup.nearest, p.metres);
    }
    setup.auto_params = auto_mono_plane_params(o.auto_flags);

    modes::RendererOptions& renderer_options = setup.renderer_options;
    apply_image_quality_flags(o.anti_aliasing, o.ssao, renderer_options);
    renderer_options.vertex_work = o.vertex_work;
    renderer_options.depth_prepass = o.depth_prepass;
    renderer_options.separate_tonemap = o.separate_tonemap;
    if (modes::msaa_samples(renderer_options.anti_aliasing) != vk::SampleCountFlagBits::e1 &&
        std::any_of(
            sweep.mode_choices.begin(), sweep.mode_choices.end(),
            [](const modes::RenderModeChoice& m) { return m.mode != modes::Mode::kStereo; })) {
        throw UserError(
            "--anti-aliasing " + o.anti_aliasing +
            " works in stereo mode only (docs/hybrid.md, \"MSAA: stereo only, and why\"): add "
            "--modes stereo, or use taa");
    }
    return setup;
}

// The runs the sweep makes, for the progress line: stereo's once per scene, hybrid's per plane
// and variant, the far field's per plane.
int count_runs(const BenchSweep& sweep, const std::vector<Plane>& planes) {
    int total = 0;
    for (const modes::RenderModeChoice& choice : sweep.mode_choices) {
        if (choice.mode == modes::Mode::kStereo) total += 1;
        if (choice.mode == modes::Mode::kHybrid)
            total += static_cast<int>(planes.size() * sweep.variants.size());
        if (choice.mode == modes::Mode::kHybridFarfield) total += static_cast<int>(planes.size());
    }
    return total * static_cast<int>(sweep.scene_sources.size() * sweep.lods.size());
}

// bench.json's header: the configuration every run shares.
BenchReport empty_report(const BenchOptions& o, const std::string& device,
                         const BenchSetup& setup) {
    BenchReport report;
    report.device = device;
    report.hmd = setup.profile.name;
    report.width = static_cast<int>(setup.extent.width);
    report.height = static_cast<int>(setup.extent.height);
    report.detail = o.detail;
    report.view = o.view;
    report.seed = o.seed;
    report.anti_aliasing = o.anti_aliasing;
    report.ssao = o.ssao;
    report.vertex_work = o.vertex_work;
    report.depth_prepass = o.depth_prepass;
    report.warmup = o.warmup;
    report.frames = o.frames;
    return report;
}

// The sweep under way: what it renders with, the report its runs go into, and its progress.
struct SweepState {
    const BenchOptions& options;
    const BenchSweep& sweep;
    const BenchSetup& setup;
    const vk_core::Context& ctx;
    BenchReport& report;
    Progress progress;
    int done = 0;
    modes::LodOptions lod{};  // of the runs under way

    void show(const std::string& what) const {
        progress.show(done, what + (sweep.lods.size() > 1 ? " lod " + lod_name() : ""));
    }
    std::string lod_name() const { return modes::lod_mode_name(lod.enabled); }
    // The renderers' options at the level of detail under way.
    modes::RendererOptions renderer_options() const {
        modes::RendererOptions options = setup.renderer_options;
        options.lod = lod;
        return options;
    }
    void add(BenchRun run) {
        run.lod = lod_name();
        run.lod_error_px = lod.error_px;
        report.runs.push_back(std::move(run));
        ++done;
    }
};

// A scene under measurement at one level of detail: the scene's GPU resources (uploaded and
// simplified once for every renderer), the stereo renderer at this level of detail whose frames
// interleave with every other run's (for the time ratios), two-pass stereo at full detail (the
// accuracy reference: its images and depth), and same_lod: the stereo images at this level of
// detail, which single-pass stereo must equal.
struct SceneUnderTest {
    const scenes::Scene& scene;
    std::string name;
    std::shared_ptr<modes::SceneResources> resources;
    modes::ModeRenderer& stereo;
    const modes::FrameInputs& stereo_inputs;
    const Reference& reference;
    Reference same_lod;
    double visible_depth = 0.0;  // farthest_visible_depth(reference)
};

// One frame's images and linear depth, read back.
Reference read_reference(modes::ModeRenderer& stereo, const modes::FrameInputs& inputs) {
    Reference reference;
    stereo.set_read_back(true);
    stereo.render_frame(inputs);
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        reference.images[static_cast<int>(eye)] = stereo.eye_image(eye);
        reference.depth[static_cast<int>(eye)] = stereo.eye_linear_depth(eye);
    }
    stereo.set_read_back(false);
    return reference;
}

// Stereo's own timed run (when --modes asks for two-pass stereo). With level of detail, the run
// interleaves with full-detail stereo frames: its time ratio to them is level of detail's gain,
// and its images' SSIM and mean difference against full detail are its error.
void measure_stereo(SweepState& state, const SceneUnderTest& scene,
                    modes::ModeRenderer& full_detail) {
    const std::vector<modes::RenderModeChoice>& mode_list = state.sweep.mode_choices;
    if (!std::any_of(mode_list.begin(), mode_list.end(), is_two_pass_stereo)) return;
    state.show(scene.name + " stereo");
    const bool lod = state.lod.enabled;
    BenchRun run = measure(scene.stereo, scene.stereo_inputs, state.options,
                           lod ? &full_detail : nullptr, lod ? &scene.stereo_inputs : nullptr);
    run.scene = scene.name;
    run.mode = "stereo";
    if (lod) {
        run.time_ratio_vs_lod_off = run.time_ratio;
        run.time_ratio.reset();  // stereo is its level of detail's reference: 1
        run.stereo_frame_ms_median.reset();
        run.time_ratio_p25.reset();
        run.time_ratio_p75.reset();
        if (state.options.accuracy) {
            const Accuracy accuracy =
                measure_accuracy(scene.stereo, scene.stereo_inputs, scene.reference);
            run.ssim_vs_stereo = accuracy.ssim;
            run.mean_abs_difference = accuracy.mean_abs_difference;
        }
    }
    state.add(std::move(run));
}

// Single-pass stereo: the same images as stereo in one pass (papers/001).
void bench_single_pass_stereo(SweepState& state, const SceneUnderTest& scene,
                              const modes::RenderModeChoice& choice,
                              const modes::FrameInputs& inputs) {
    modes::RendererOptions options = state.renderer_options();
    options.stereo_pass = choice.stereo_pass;
    const std::string name = modes::render_mode_name(choice);
    state.show(scene.name + " " + name);
    modes::ModeRenderer renderer(state.ctx, scene.resources, choice.mode, state.setup.extent,
                                 options);
    BenchRun run = measure(renderer, inputs, state.options, &scene.stereo, &scene.stereo_inputs);
    run.scene = scene.name;
    run.mode = name;
    run.stereo_pass = modes::stereo_pass_name(options.stereo_pass);
    if (state.options.accuracy) {
        run.max_channel_difference = max_channel_difference(renderer, inputs, scene.same_lod);
    }
    state.add(std::move(run));
}

// A hybrid mode under measurement: its renderer for the fixed planes, the options it was made
// with and the variants it is measured with.
struct HybridMode {
    modes::Mode mode;
    modes::ModeRenderer& renderer;
    const modes::RendererOptions& options;
    std::string pass_name;  // of options.stereo_pass
    std::vector<modes::MonoCulling> variants;
};

// m chosen by the renderer every frame: one renderer per variant, since the chooser keeps state
// over the frames. papers/003's far field has another error model than the rig's: hybrid only.
void bench_auto_plane(SweepState& state, const SceneUnderTest& scene, const HybridMode& hybrid,
                      const modes::FrameInputs& inputs) {
    if (hybrid.mode != modes::Mode::kHybrid) {
        state.done += 1;
        return;
    }
    const BenchSetup& setup = state.setup;
    for (modes::MonoCulling variant : hybrid.variants) {
        state.show(scene.name + " hybrid " + modes::mono_culling_name(variant) + " m=auto");
        modes::RendererOptions auto_options = hybrid.options;
        auto_options.auto_mono_plane = setup.auto_params;
        modes::ModeRenderer automatic(state.ctx, scene.resources, hybrid.mode, setup.extent,
                                      auto_options, setup.nearest);
        AutoRunContext context{setup.profile, setup.extent, scene.visible_depth, scene.reference};
        BenchRun run = measure_auto(automatic, inputs, variant, state.options, context,
                                    scene.stereo, scene.stereo_inputs);
        run.scene = scene.name;
        run.stereo_pass = hybrid.pass_name;
        state.add(std::move(run));
    }
}

// The rig's largest error, in pixels and arcminutes, and the error at the farthest visible depth.
void add_rig_errors(const modes::ModeRenderer& renderer, double visible_depth, BenchRun& run) {
    if (!renderer.last_rig()) return;
    const rig::Rig& rig = *renderer.last_rig();
    run.max_error_px = rig.max_error_px;
    run.max_error_arcmin = rig::max_angular_error(rig).eye_arcmin;
    run.visible_error_arcmin = rig::angular_error_at_depth(rig, visible_depth).eye_arcmin;
}

// One fixed m, each variant in turn on the mode's renderer. The variants draw identical images
// (tests/gpu/culling_test.cpp): the accuracy is measured once per mono plane.
void bench_fixed_plane(SweepState& state, const SceneUnderTest& scene, const HybridMode& hybrid,
                       const Plane& plane, modes::FrameInputs& inputs) {
    const modes::Mode mode = hybrid.mode;
    modes::ModeRenderer& renderer = hybrid.renderer;
    inputs.mono_plane = plane.metres;
    std::optional<Accuracy> accuracy;
    for (modes::MonoCulling variant : hybrid.variants) {
        inputs.mono_culling = variant;
        std::ostringstream what;
        what << scene.name << " " << modes::mode_name(mode)
             << (mode == modes::Mode::kHybrid ? " " + modes::mono_culling_name(variant) : "")
             << " m=" << (plane.far ? std::string("far") : plane_text(plane.metres));
        state.show(what.str());
        BenchRun run =
            measure(renderer, inputs, state.options, &scene.stereo, &scene.stereo_inputs);
        run.scene = scene.name;
        run.mode = modes::mode_name(mode);
        run.stereo_pass = hybrid.pass_name;
        if (mode == modes::Mode::kHybrid) {
            run.variant = modes::mono_culling_name(variant);
            // auto: the variant its measurement settled on by the last frame.
            if (variant == modes::MonoCulling::kAuto) {
                run.variant_chosen = modes::mono_culling_name(renderer.last_variant());
            }
        }
        run.mono_plane = plane.metres;
        run.mono_plane_is_far = plane.far;
        add_rig_errors(renderer, scene.visible_depth, run);
        if (state.options.accuracy && !accuracy) {
            accuracy = measure_accuracy(renderer, inputs, scene.reference);
        }
        if (accuracy) {
            run.ssim_vs_stereo = accuracy->ssim;
            run.mean_abs_difference = accuracy->mean_abs_difference;
            run.drift_px = accuracy->drift_px;
            run.drift_patches = accuracy->drift_patches;
        }
        state.add(std::move(run));
    }
}

// A hybrid mode at every mono plane of the sweep; hybrid with each variant, the far field with
// frustum culling only. inputs keeps the last plane and variant measured.
void bench_hybrid_mode(SweepState& state, const SceneUnderTest& scene, modes::Mode mode,
                       modes::FrameInputs& inputs) {
    const BenchSetup& setup = state.setup;
    modes::RendererOptions options = state.renderer_options();
    options.stereo_pass = state.sweep.hybrid_stereo_pass;
    modes::ModeRenderer renderer(state.ctx, scene.resources, mode, setup.extent, options,
                                 setup.nearest);
    const HybridMode hybrid{mode, renderer, options, modes::stereo_pass_name(options.stereo_pass),
                            mode == modes::Mode::kHybrid ? state.sweep.variants
                                                         : std::vector{modes::MonoCulling::kNoOpt}};
    for (const Plane& plane : setup.planes) {
        if (plane.automatic) {
            bench_auto_plane(state, scene, hybrid, inputs);
        } else {
            bench_fixed_plane(state, scene, hybrid, plane, inputs);
        }
    }
}

// Every mode of the sweep in one scene, against the scene's stereo reference.
void bench_scene(SweepState& state, const SceneSource& source) {
    const BenchOptions& o = state.options;
    const BenchSetup& setup = state.setup;
    state.show((source.builtin ? "generating " : "loading ") + source.label);
    const scenes::Scene scene = load_scene(source, state.sweep.detail, o.seed).value_or_throw();
    const std::string scene_name = source.builtin ? source.label : scene.name;
    const scenes::Viewpoint* viewpoint = scene.find_viewpoint(o.view);
    if (!viewpoint) throw UserError("--view " + o.view + ": " + scene_name + " has no such view");
    modes::FrameInputs inputs = setup.base;
    inputs.views.head = viewpoint->head;
    auto resources =
        std::make_shared<modes::SceneResources>(state.ctx, scene, setup.renderer_options.shadow);

    modes::RendererOptions full_options = setup.renderer_options;
    full_options.read_back_depth = true;
    full_options.stereo_pass = modes::StereoPass::kTwoPasses;
    full_options.lod.enabled = false;
    modes::ModeRenderer full_detail(state.ctx, resources, modes::Mode::kStereo, setup.extent,
                                    full_options);
    const modes::FrameInputs stereo_inputs = inputs;
    const Reference reference = read_reference(full_detail, stereo_inputs);

    for (const modes::LodOptions& lod : state.sweep.lods) {
        state.lod = lod;
        modes::RendererOptions stereo_options = state.renderer_options();
        stereo_options.read_back_depth = true;
        stereo_options.stereo_pass = modes::StereoPass::kTwoPasses;
        std::optional<modes::ModeRenderer> at_lod;
        if (lod.enabled) {
            at_lod.emplace(state.ctx, resources, modes::Mode::kStereo, setup.extent,
                           stereo_options);
        }
        modes::ModeRenderer& stereo = at_lod ? *at_lod : full_detail;
        SceneUnderTest under_test{scene,
                                  scene_name,
                                  resources,
                                  stereo,
                                  stereo_inputs,
                                  reference,
                                  lod.enabled ? read_reference(stereo, stereo_inputs) : reference};
        under_test.visible_depth = farthest_visible_depth(reference);
        measure_stereo(state, under_test, full_detail);
        for (const modes::RenderModeChoice& choice : state.sweep.mode_choices) {
            if (is_two_pass_stereo(choice)) continue;
            if (choice.mode == modes::Mode::kStereo) {
                bench_single_pass_stereo(state, under_test, choice, inputs);
            } else {
                bench_hybrid_mode(state, under_test, choice.mode, inputs);
            }
        }
    }
}

// One line per run compared with stereo on stderr: its time and count ratios, accuracy and
// error, and for auto runs whether a fixed m beat them.
void print_run_summary(const BenchRun& run) {
    std::cerr << "  " << std::left << std::setw(10) << run.scene << std::setw(16) << run.mode
              << std::setw(15) << run.variant << " m " << std::setw(6)
              << (!run.mono_plane         ? std::string("-")
                  : run.mono_plane_auto   ? "auto~" + plane_text(*run.mono_plane)
                  : run.mono_plane_is_far ? std::string("far")
                                          : plane_text(*run.mono_plane))
              << " time " << std::fixed << std::setprecision(2) << *run.time_ratio
              << "x  primitives " << run.primitive_ratio.value_or(0.0) << "x  vertices "
              << run.vertex_invocation_ratio.value_or(0.0) << "x";
    if (run.max_channel_difference)
        std::cerr << "  max difference " << *run.max_channel_difference << "/255";
    if (run.ssim_vs_stereo) std::cerr << "  SSIM " << std::setprecision(4) << *run.ssim_vs_stereo;
    if (run.visible_error_arcmin)
        std::cerr << "  error " << std::setprecision(2) << *run.visible_error_arcmin << "'";
    if (run.on_fixed_m_frontier) {
        std::cerr << (*run.on_fixed_m_frontier ? "  on the fixed-m frontier"
                                               : "  dominated by a fixed m");
        if (!run.dominated_by.empty()) {
            std::cerr << " (" << run.dominated_beyond_spread_by.size() << " of "
                      << run.dominated_by.size() << " beyond the frame-to-frame spread)";
        }
    }
    std::cerr << std::defaultfloat << "\n";
}

// bench.json, bench.csv and the figures, then the summary on stderr.
void write_results(const BenchReport& report, const std::filesystem::path& out) {
    std::ofstream(out / "bench.json") << bench_json(report) << "\n";
    std::ofstream(out / "bench.csv") << bench_csv(report);
    const auto plots = write_bench_plots(report, out).value_or_throw();
    std::cerr << "wrote " << (out / "bench.json").string() << ", bench.csv and " << plots.size()
              << " figures\n";
    for (const BenchRun& run : report.runs) {
        if (!run.time_ratio || run.mode == "stereo") continue;
        print_run_summary(run);
    }
}

void run_bench(const BenchOptions& o, const GlobalOptions& global) {
    const BenchSweep sweep = parse_sweep(o);
    const std::filesystem::path out = prepare_output_directory("--out", o.out);
    const BenchSetup setup = prepare_setup(o, sweep);
    auto ctx = vk_core::Context::create(global.context_options()).value_or_throw();
    std::cerr << "device: " << ctx->device_info().name << "\n";

    BenchReport report = empty_report(o, ctx->device_info().name, setup);
    SweepState state{o, sweep, setup, *ctx, report, Progress(count_runs(sweep, setup.planes))};
    for (const SceneSource& source : sweep.scene_sources) bench_scene(state, source);
    state.show("done");
    if (isatty(2)) std::cerr << "\n";

    add_ratios_to_stereo(report);
    mark_auto_frontier(report);
    write_results(report, out);
    fail_on_validation_messages(*ctx, global);
}

}  // namespace

void add_bench_command(CLI::App& root, const GlobalOptions& global) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* cmd = root.add_subcommand(
        "bench", "Measure time, primitives and accuracy over scenes x modes x mono planes");
    cmd->add_option("--scenes", options->scenes, "Comma-separated scenes")->capture_default_str();
    cmd->add_option("--modes", options->modes,
                    "Comma-separated modes: stereo, stereo-multiview, stereo-gs, "
                    "stereo-instanced, hybrid, hybrid-farfield")
        ->capture_default_str();
    cmd->add_option("--variants", options->variants,
                    "hybrid's variants (papers/000 Sect. 5.1): no-opt, discard, occlusion-cull, "
                    "and auto (measures them on its frames and uses the fastest)")
        ->capture_default_str();
    cmd->add_option("--mono-planes", options->mono_planes,
                    "Comma-separated distances in metres; 'far' is the far plane, 'auto' the "
                    "renderer's choice every frame within --error-budget-arcmin (hybrid only)")
        ->capture_default_str();
    add_auto_mono_plane_flags(*cmd, options->auto_flags);
    cmd->add_option("--auto-warmup", options->auto_warmup,
                    "Extra warm-up frames of an auto run, for its m to settle")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd->add_option("--protocol", options->protocol,
                    "Take the mono planes from this protocol (plus far) instead");
    cmd->add_option("--hmd", options->hmd, "HMD profile name or TOML file")->capture_default_str();
    cmd->add_option("--width", options->width, "Per-eye width (default: the profile's)")
        ->check(CLI::Range(16, 16384));
    cmd->add_option("--height", options->height, "Per-eye height (default: the profile's)")
        ->check(CLI::Range(16, 16384));
    cmd->add_option("--detail", options->detail, "test, low, medium, high or ultra")
        ->capture_default_str();
    cmd->add_option("--view", options->view, "Viewpoint of every scene")->capture_default_str();
    cmd->add_option("--seed", options->seed, "Scene seed")->capture_default_str();
    cmd->add_option("--frames", options->frames, "Measured frames per configuration")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    cmd->add_option("--warmup", options->warmup, "Frames before measuring")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd->add_flag("!--no-accuracy", options->accuracy,
                  "Skip SSIM and drift against stereo (times and counts only)");
    cmd->add_option("--anti-aliasing", options->anti_aliasing,
                    "none, taa or msaa2|msaa4|msaa8 for every run (MSAA: stereo modes only)")
        ->capture_default_str();
    cmd->add_option("--ssao", options->ssao, "off, per-eye or stereo for every run")
        ->capture_default_str();
    cmd->add_option("--stereo-pass", options->stereo_pass,
                    "The hybrid modes' near passes: two, multiview, gs or instanced (single-pass "
                    "stereo is measured by --modes stereo-multiview,stereo-gs,stereo-instanced)")
        ->capture_default_str();
    cmd->add_option("--vertex-work", options->vertex_work,
                    "Vertex-heavy configuration (papers/001 Table 1): rounds of synthetic "
                    "per-vertex work in every run (0: none; the images do not change)")
        ->check(CLI::Range(0, 4096))
        ->capture_default_str();
    cmd->add_flag("--depth-prepass", options->depth_prepass,
                  "A depth-only pass before every forward pass, the stereo reference's included "
                  "(each visible pixel shaded once; off by default, docs/benchmarks.md)");
    cmd->add_flag("--separate-tonemap", options->separate_tonemap,
                  "Hybrid modes: tone map each eye in a pass of its own after the composite, as "
                  "before the composite wrote the display image itself (the paired comparison "
                  "of docs/benchmarks.md; each run's plan shows which)");
    cmd->add_option("--grazing-deg", options->grazing_deg,
                    "Overlap for surfaces down to this angle to the view rays (0: eps = k s m)")
        ->capture_default_str();
    cmd->add_option("--turning-frames", options->turning_frames,
                    "After each run's frames, this many pairs of a still frame and a frame with "
                    "the head turning (the turn pose path): the time ratio, and the driver's "
                    "shader compiles where they can be counted (turning_* in bench.json)")
        ->capture_default_str()
        ->check(CLI::Range(0, 1000));
    add_lod_flags(*cmd, options->lod, true);
    cmd->add_option("--out", options->out, "Output directory")->required();
    cmd->callback([options, &global] { run_bench(*options, global); });
}

}  // namespace monoplane::app
