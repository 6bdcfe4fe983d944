#include "app/commands/bench_scene.h"

#include <algorithm>
#include <optional>
#include <sstream>
#include <utility>

#include "app/commands/bench_measurement.h"
#include "common/result.h"
#include "rig/angular_error.h"

namespace monoplane::app::bench {
namespace {

// Stereo's own timed run (when --modes asks for two-pass stereo). With level of detail, the run
// interleaves with full-detail stereo frames: its time ratio to them is level of detail's gain,
// and its images' SSIM and mean difference against full detail are its error.
void measure_stereo(SweepState& state, const SceneUnderTest& scene,
                    modes::ModeRenderer& full_detail) {
    const std::vector<plan::RenderModeChoice>& mode_list = state.sweep.mode_choices;
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
                              const plan::RenderModeChoice& choice,
                              const modes::FrameInputs& inputs) {
    modes::RendererOptions options = state.renderer_options();
    options.stereo_pass = choice.stereo_pass;
    const std::string name = plan::render_mode_name(choice);
    state.show(scene.name + " " + name);
    modes::ModeRenderer renderer(state.ctx, scene.resources, choice.mode, state.setup.extent,
                                 options);
    BenchRun run = measure(renderer, inputs, state.options, &scene.stereo, &scene.stereo_inputs);
    run.scene = scene.name;
    run.mode = name;
    run.stereo_pass = plan::stereo_pass_name(options.stereo_pass);
    if (state.options.accuracy) {
        run.max_channel_difference = max_channel_difference(renderer, inputs, scene.same_lod);
    }
    state.add(std::move(run));
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
    const plan::Mode mode = hybrid.mode;
    modes::ModeRenderer& renderer = hybrid.renderer;
    inputs.mono_plane = plane.metres;
    std::optional<Accuracy> accuracy;
    for (plan::MonoCulling variant : hybrid.variants) {
        inputs.mono_culling = variant;
        std::ostringstream what;
        what << scene.name << " " << plan::mode_name(mode)
             << (mode == plan::Mode::kHybrid ? " " + plan::mono_culling_name(variant) : "")
             << " m=" << (plane.far ? std::string("far") : plane_text(plane.metres));
        state.show(what.str());
        BenchRun run =
            measure(renderer, inputs, state.options, &scene.stereo, &scene.stereo_inputs);
        run.scene = scene.name;
        run.mode = plan::mode_name(mode);
        run.stereo_pass = hybrid.pass_name;
        if (mode == plan::Mode::kHybrid) {
            run.variant = plan::mono_culling_name(variant);
            // auto: the variant its measurement settled on by the last frame.
            if (variant == plan::MonoCulling::kAuto) {
                run.variant_chosen = plan::mono_culling_name(renderer.last_variant());
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
void bench_hybrid_mode(SweepState& state, const SceneUnderTest& scene, plan::Mode mode,
                       modes::FrameInputs& inputs) {
    const BenchSetup& setup = state.setup;
    modes::RendererOptions options = state.renderer_options();
    options.stereo_pass = state.sweep.hybrid_stereo_pass;
    modes::ModeRenderer renderer(state.ctx, scene.resources, mode, setup.extent, options,
                                 setup.nearest);
    const HybridMode hybrid{mode, renderer, options, plan::stereo_pass_name(options.stereo_pass),
                            mode == plan::Mode::kHybrid ? state.sweep.variants
                                                        : std::vector{plan::MonoCulling::kNoOpt}};
    for (const Plane& plane : setup.planes) {
        if (plane.automatic) {
            bench_auto_plane(state, scene, hybrid, inputs);
        } else {
            bench_fixed_plane(state, scene, hybrid, plane, inputs);
        }
    }
}

}  // namespace

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
    full_options.stereo_pass = plan::StereoPass::kTwoPasses;
    full_options.lod.enabled = false;
    modes::ModeRenderer full_detail(state.ctx, resources, plan::Mode::kStereo, setup.extent,
                                    full_options);
    const modes::FrameInputs stereo_inputs = inputs;
    const Reference reference = read_reference(full_detail, stereo_inputs);

    for (const plan::LodOptions& lod : state.sweep.lods) {
        state.lod = lod;
        modes::RendererOptions stereo_options = state.renderer_options();
        stereo_options.read_back_depth = true;
        stereo_options.stereo_pass = plan::StereoPass::kTwoPasses;
        std::optional<modes::ModeRenderer> at_lod;
        if (lod.enabled) {
            at_lod.emplace(state.ctx, resources, plan::Mode::kStereo, setup.extent, stereo_options);
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
        for (const plan::RenderModeChoice& choice : state.sweep.mode_choices) {
            if (is_two_pass_stereo(choice)) continue;
            if (choice.mode == plan::Mode::kStereo) {
                bench_single_pass_stereo(state, under_test, choice, inputs);
            } else {
                bench_hybrid_mode(state, under_test, choice.mode, inputs);
            }
        }
    }
}

}  // namespace monoplane::app::bench
