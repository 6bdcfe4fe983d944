// The results of `monoplane bench` (docs/benchmarks.md): one run per scene x mode x variant x
// mono plane, and their CSV and JSON forms. Plain data; the sweep is in bench_command.cpp.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/commands/device_memory_json.h"
#include "renderer/plan/frame_plan.h"

namespace monoplane::app {

struct BenchRun {
    std::string scene;
    // stereo, stereo-multiview, stereo-gs, stereo-instanced, hybrid, hybrid-farfield
    std::string mode;
    // How the eyes' forward passes were drawn: two, multiview, gs or instanced (for the
    // single-pass stereo modes, their form; for the hybrid modes, their near passes').
    std::string stereo_pass = "two";
    std::string variant;  // hybrid: no-opt, discard, occlusion-cull, auto; otherwise empty
    // Level of detail: "auto" or "off" (--lod), and auto's budget in pixels.
    std::string lod = "auto";
    double lod_error_px = 0.5;
    std::string variant_chosen;  // auto: the variant in use at the last frame; otherwise empty
    std::optional<double> mono_plane;  // none for stereo; auto: the median of its frames
    bool mono_plane_is_far = false;    // m = f: C skipped, hybrid records stereo's passes
    // `--mono-planes auto` (issue 20): the renderer chose m every frame; the smallest and largest
    // it chose over the measured frames, and how many frames it drew as stereo.
    bool mono_plane_auto = false;
    std::optional<double> mono_plane_min;
    std::optional<double> mono_plane_max;
    int stereo_frames = 0;
    std::vector<double> frame_mono_planes;  // each measured frame's m (not written out)
    int frames = 0;
    double frame_ms_median = 0.0;
    double frame_ms_p10 = 0.0;
    double frame_ms_p90 = 0.0;
    double cpu_ms_median = 0.0;
    std::map<std::string, double> pass_ms_median;
    std::map<std::string, double> pass_ms_p10;
    std::map<std::string, double> pass_ms_p90;
    // Pipeline statistics of the scene views (left, right, mono): clipping input primitives
    // and fragment invocations, and the chunks each view drew.
    std::map<std::string, std::uint64_t> view_primitives;
    std::map<std::string, std::uint64_t> view_draws;
    std::map<std::string, std::uint64_t> view_fragments;  // every view, composites included
    // Fragment-shader invocations per pixel of each view (its drawn area: an eye's image, C's
    // viewport of eq. 8, both eyes' for single-pass "eyes"); llvmpipe counts every covered
    // pixel of every 2x2 quad, whether or not the depth test then rejects it.
    std::map<std::string, double> view_fragments_per_pixel;
    std::uint64_t primitives = 0;
    std::uint64_t fragments = 0;  // all views, composites included
    // Vertex and geometry shader invocations of the scene views (papers/001: single-pass stereo
    // shades each vertex once for both eyes).
    std::uint64_t vertex_invocations = 0;
    std::uint64_t geometry_invocations = 0;
    // Accuracy against stereo (hybrid modes below far).
    // Against two-pass stereo at full detail (--lod off), so level of detail's error counts too.
    std::optional<double> ssim_vs_stereo;  // mean of both eyes, Gaussian SSIM
    // The mean absolute difference of the colour channels, 8-bit levels, mean of both eyes.
    std::optional<double> mean_abs_difference;
    std::optional<double> max_error_px;  // analytic supremum (rig)
    // The same in visual angle (rig/angular_error.h): each eye's supremum at infinity, and at the
    // farthest depth the stereo reference shows (the error any visible pixel can have; auto: the
    // largest over its frames).
    std::optional<double> max_error_arcmin;
    std::optional<double> visible_error_arcmin;
    std::optional<double> drift_px;  // measured: 95th percentile of patch displacements
    std::size_t drift_patches = 0;
    // Single-pass stereo: the largest channel difference (8-bit levels) of either eye's image
    // from two-pass stereo's; 0 or 1 where they draw the same images.
    std::optional<int> max_channel_difference;
    // Ratios to stereo in the same run (same scene and resolution): time as the median of
    // per-frame ratios to stereo frames rendered in between (bench_command.cpp), primitives to
    // the scene's stereo run.
    std::optional<double> time_ratio;
    std::optional<double> stereo_frame_ms_median;  // of the interleaved stereo frames
    // Quartiles of the per-pair time ratios: how much a ratio varies frame to frame.
    std::optional<double> time_ratio_p25;
    std::optional<double> time_ratio_p75;
    // Level of detail's gain: with --lod off,auto, an auto run's median frame time over the
    // matching off run's (two-pass stereo's: the median of per-frame ratios to full-detail
    // stereo frames rendered in between, as time_ratio).
    std::optional<double> time_ratio_vs_lod_off;
    std::optional<double> primitive_ratio;
    std::optional<double> vertex_invocation_ratio;  // to the scene's stereo run
    // The turning-head configuration (--turning-frames): the median ratio of a frame's GPU time
    // with the head turning (every pose new) to the still frame beside it, and over those
    // frames the shader modules the driver compiled and the share of the wall time it spent
    // compiling (none where the driver's compiles cannot be counted). A ratio near 1 and no
    // compiles: the renderer's cost does not depend on where the head looks.
    int turning_frames = 0;
    std::optional<double> turning_time_ratio;
    std::optional<std::uint64_t> turning_driver_compiles;
    std::optional<double> turning_compile_share;
    // Auto runs: whether no fixed-m run of the same scene, mode and variant is both faster
    // (median time ratio) and more accurate (visible error), and which are (issue 20's target).
    std::optional<bool> on_fixed_m_frontier;
    std::vector<std::string> dominated_by;  // "m=8", ...
    // Of those, the ones faster beyond the frame-to-frame spread: the fixed run's upper quartile
    // of per-pair ratios below auto's lower quartile. On a busy CPU rasterizer the medians of
    // runs of a few frames differ by noise; this says which dominations survive it.
    std::vector<std::string> dominated_beyond_spread_by;
    // The plan of the last measured frame (renderer/plan/frame_plan.h).
    plan::FramePlan plan;
    // The device memory the process held after the run's frames: the scene's resources, the
    // run's renderer and, where one renders beside it, the stereo reference's.
    DeviceMemoryFigures device_memory;
};

struct BenchReport {
    std::string device;
    std::string hmd;
    int width = 0;
    int height = 0;
    std::string detail;
    std::string view;
    std::string anti_aliasing = "none";  // of every run, the stereo reference included
    std::string ssao = "off";
    std::uint32_t vertex_work = 0;  // the vertex-heavy configuration's rounds (0: none)
    bool depth_prepass = false;     // RendererOptions::depth_prepass in every run
    std::uint64_t seed = 0;
    int warmup = 0;
    int frames = 0;
    std::vector<BenchRun> runs;
};

// Fills time_ratio, primitive_ratio and vertex_invocation_ratio from the stereo run of each
// run's scene and level of detail, and time_ratio_vs_lod_off where the bench left it empty.
void add_ratios_to_stereo(BenchReport& report);

// Fills on_fixed_m_frontier, dominated_by and dominated_beyond_spread_by of every auto run from the
// fixed-m runs of its scene, mode and variant (after add_ratios_to_stereo).
void mark_auto_frontier(BenchReport& report);

std::string bench_json(const BenchReport& report);
std::string bench_csv(const BenchReport& report);

}  // namespace monoplane::app
