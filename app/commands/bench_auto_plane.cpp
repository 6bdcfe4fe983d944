// Auto runs: one renderer per variant, since the mono-plane chooser keeps state over the frames.
// papers/003's far field has another error model than the rig's: hybrid only.
#include <algorithm>
#include <limits>
#include <vector>

#include "app/commands/bench_measurement.h"
#include "app/commands/bench_scene.h"
#include "rig/angular_error.h"

namespace monoplane::app::bench {
namespace {

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

// The m the renderer chose over the measured frames (median, smallest, largest), the frames it
// drew as stereo, the largest visible error over them and the error at m.
void add_chosen_planes(const AutoRunContext& context, const modes::FrameInputs& inputs,
                       BenchRun& run) {
    std::vector<double> planes = run.frame_mono_planes;
    if (planes.empty()) return;
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
    run.max_error_arcmin =
        eye_error_arcmin(context, inputs, *run.mono_plane, std::numeric_limits<double>::infinity());
}

// An auto run: warm-up frames for the chooser to settle (o.auto_warmup more than fixed runs),
// measured frames against interleaved stereo, the m it chose per frame, the largest visible
// error over them, and the accuracy of one more frame.
BenchRun measure_auto(modes::ModeRenderer& renderer, modes::FrameInputs inputs,
                      plan::MonoCulling variant, const BenchOptions& o,
                      const AutoRunContext& context, modes::ModeRenderer& stereo,
                      const modes::FrameInputs& stereo_inputs) {
    inputs.mono_culling = variant;
    BenchOptions longer = o;
    longer.warmup = o.warmup + o.auto_warmup;
    BenchRun run = measure(renderer, inputs, longer, &stereo, &stereo_inputs);
    run.mode = plan::mode_name(plan::Mode::kHybrid);
    run.variant = plan::mono_culling_name(variant);
    if (variant == plan::MonoCulling::kAuto) {
        run.variant_chosen = plan::mono_culling_name(renderer.last_variant());
    }
    run.mono_plane_auto = true;
    add_chosen_planes(context, inputs, run);
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

}  // namespace

void bench_auto_plane(SweepState& state, const SceneUnderTest& scene, const HybridMode& hybrid,
                      const modes::FrameInputs& inputs) {
    if (hybrid.mode != plan::Mode::kHybrid) {
        state.done += 1;
        return;
    }
    const BenchSetup& setup = state.setup;
    for (plan::MonoCulling variant : hybrid.variants) {
        state.show(scene.name + " hybrid " + plan::mono_culling_name(variant) + " m=auto");
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

}  // namespace monoplane::app::bench
