// `monoplane bench`'s sweep under way: the state every run shares, and the runs of one scene (its
// stereo reference, the single-pass stereo modes, the hybrid modes at every mono plane).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "app/bench/bench_results.h"
#include "app/commands/bench_accuracy.h"
#include "app/commands/bench_options.h"
#include "app/commands/bench_progress.h"
#include "app/commands/bench_sweep.h"
#include "renderer/modes/mode_renderer.h"
#include "renderer/vk/context.h"

namespace monoplane::app::bench {

// The sweep under way: what it renders with, the report its runs go into, and its progress.
struct SweepState {
    const BenchOptions& options;
    const BenchSweep& sweep;
    const BenchSetup& setup;
    const vk_core::Context& ctx;
    BenchReport& report;
    Progress progress;
    int done = 0;
    plan::LodOptions lod{};  // of the runs under way

    void show(const std::string& what) const {
        progress.show(done, what + (sweep.lods.size() > 1 ? " lod " + lod_name() : ""));
    }
    std::string lod_name() const { return plan::lod_mode_name(lod.enabled); }
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

// A hybrid mode under measurement: its renderer for the fixed planes, the options it was made
// with and the variants it is measured with.
struct HybridMode {
    plan::Mode mode;
    modes::ModeRenderer& renderer;
    const modes::RendererOptions& options;
    std::string pass_name;  // of options.stereo_pass
    std::vector<plan::MonoCulling> variants;
};

// Every mode of the sweep in one scene, against the scene's stereo reference; each run goes into
// state.report. Throws UserError when the scene cannot be loaded or lacks --view.
void bench_scene(SweepState& state, const SceneSource& source);

// m chosen by the renderer every frame (the "auto" entry of --mono-planes), each variant of the
// hybrid mode in turn; a step of the progress only for another mode. Within bench_scene.
void bench_auto_plane(SweepState& state, const SceneUnderTest& scene, const HybridMode& hybrid,
                      const modes::FrameInputs& inputs);

}  // namespace monoplane::app::bench
