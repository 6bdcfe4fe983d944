#include "app/commands/bench_options.h"

namespace monoplane::app::bench {
namespace {

// What is swept: scenes, modes, hybrid's variants and the mono planes.
void add_sweep_options(CLI::App& cmd, BenchOptions& options) {
    cmd.add_option("--scenes", options.scenes, "Comma-separated scenes")->capture_default_str();
    cmd.add_option("--modes", options.modes,
                   "Comma-separated modes: stereo, stereo-multiview, stereo-gs, "
                   "stereo-instanced, hybrid, hybrid-farfield")
        ->capture_default_str();
    cmd.add_option("--variants", options.variants,
                   "hybrid's variants (papers/000 Sect. 5.1): no-opt, discard, occlusion-cull, "
                   "and auto (measures them on its frames and uses the fastest)")
        ->capture_default_str();
    cmd.add_option("--mono-planes", options.mono_planes,
                   "Comma-separated distances in metres; 'far' is the far plane, 'auto' the "
                   "renderer's choice every frame within --error-budget-arcmin (hybrid only)")
        ->capture_default_str();
    add_auto_mono_plane_flags(cmd, options.auto_flags);
    cmd.add_option("--auto-warmup", options.auto_warmup,
                   "Extra warm-up frames of an auto run, for its m to settle")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd.add_option("--protocol", options.protocol,
                   "Take the mono planes from this protocol (plus far) instead");
}

// The headset, the image size and what every scene is seen from; how many frames are measured.
void add_view_and_frame_options(CLI::App& cmd, BenchOptions& options) {
    cmd.add_option("--hmd", options.hmd, "HMD profile name or TOML file")->capture_default_str();
    cmd.add_option("--width", options.width, "Per-eye width (default: the profile's)")
        ->check(CLI::Range(16, 16384));
    cmd.add_option("--height", options.height, "Per-eye height (default: the profile's)")
        ->check(CLI::Range(16, 16384));
    cmd.add_option("--detail", options.detail, "test, low, medium, high or ultra")
        ->capture_default_str();
    cmd.add_option("--view", options.view, "Viewpoint of every scene")->capture_default_str();
    cmd.add_option("--seed", options.seed, "Scene seed")->capture_default_str();
    cmd.add_option("--frames", options.frames, "Measured frames per configuration")
        ->check(CLI::Range(1, 100000))
        ->capture_default_str();
    cmd.add_option("--warmup", options.warmup, "Frames before measuring")
        ->check(CLI::Range(0, 100000))
        ->capture_default_str();
    cmd.add_flag("!--no-accuracy", options.accuracy,
                 "Skip SSIM and drift against stereo (times and counts only)");
}

// How every run renders: image quality, the hybrid modes' near passes, extra work and passes.
void add_renderer_options(CLI::App& cmd, BenchOptions& options) {
    cmd.add_option("--anti-aliasing", options.anti_aliasing,
                   "none, taa or msaa2|msaa4|msaa8 for every run (MSAA: stereo modes only)")
        ->capture_default_str();
    cmd.add_option("--ssao", options.ssao, "off, per-eye or stereo for every run")
        ->capture_default_str();
    cmd.add_option("--stereo-pass", options.stereo_pass,
                   "The hybrid modes' near passes: two, multiview, gs or instanced (single-pass "
                   "stereo is measured by --modes stereo-multiview,stereo-gs,stereo-instanced)")
        ->capture_default_str();
    cmd.add_option("--vertex-work", options.vertex_work,
                   "Vertex-heavy configuration (papers/001 Table 1): rounds of synthetic "
                   "per-vertex work in every run (0: none; the images do not change)")
        ->check(CLI::Range(0, 4096))
        ->capture_default_str();
    cmd.add_flag("--depth-prepass", options.depth_prepass,
                 "A depth-only pass before every forward pass, the stereo reference's included "
                 "(each visible pixel shaded once; off by default, docs/benchmarks.md)");
    cmd.add_flag("--separate-tonemap", options.separate_tonemap,
                 "Hybrid modes: tone map each eye in a pass of its own after the composite, as "
                 "before the composite wrote the display image itself (the paired comparison "
                 "of docs/benchmarks.md; each run's plan shows which)");
    cmd.add_option("--grazing-deg", options.grazing_deg,
                   "Overlap for surfaces down to this angle to the view rays (0: eps = k s m)")
        ->capture_default_str();
}

}  // namespace

void add_bench_options(CLI::App& cmd, BenchOptions& options) {
    add_sweep_options(cmd, options);
    add_view_and_frame_options(cmd, options);
    add_renderer_options(cmd, options);
    cmd.add_option("--turning-frames", options.turning_frames,
                   "After each run's frames, this many pairs of a still frame and a frame with "
                   "the head turning (the turn pose path): the time ratio, and the driver's "
                   "shader compiles where they can be counted (turning_* in bench.json)")
        ->capture_default_str()
        ->check(CLI::Range(0, 1000));
    add_lod_flags(cmd, options.lod, true);
    cmd.add_option("--out", options.out, "Output directory")->required();
}

}  // namespace monoplane::app::bench
