// What `monoplane bench` sweeps and renders with, from its flags: the scenes, modes, variants,
// levels of detail and mono planes, the headset and image size, the renderers' options. Every
// flag is checked here, before any scene is loaded or device opened.
#pragma once

#include <string>
#include <vector>

#include "app/commands/bench_options.h"
#include "app/commands/scene_source.h"
#include "hmd/profile.h"
#include "renderer/modes/mode_renderer.h"
#include "scenes/scene.h"

namespace monoplane::app::bench {

// A mono plane of the sweep: metres, the far plane, or chosen by the renderer every frame.
struct Plane {
    double metres = 0.0;
    bool far = false;
    bool automatic = false;
};

// The sweep the options ask for, checked before anything is loaded.
struct BenchSweep {
    std::vector<SceneSource> scene_sources;
    std::vector<plan::RenderModeChoice> mode_choices;
    plan::StereoPass hybrid_stereo_pass = plan::StereoPass::kTwoPasses;  // --stereo-pass
    std::vector<plan::MonoCulling> variants;                             // hybrid's
    std::vector<plan::LodOptions> lods;                                  // --lod, in order
    scenes::Detail detail{};
};

// What every run renders with: the headset, the image size, the mono planes and the renderers'
// options.
struct BenchSetup {
    hmd::HmdProfile profile;
    vk::Extent2D extent;
    modes::FrameInputs base;  // every scene's inputs, less its viewpoint
    std::vector<Plane> planes;
    double nearest = 0.0;  // the nearest fixed plane: sizes C's render target once
    plan::AutoMonoPlaneParams auto_params;
    modes::RendererOptions renderer_options;
};

// Throws UserError naming the flag when one is malformed. Any time; reads no file.
BenchSweep parse_sweep(const BenchOptions& o);

// Loads the headset profile (and --protocol's mono planes); throws UserError naming what is wrong.
// After parse_sweep.
BenchSetup prepare_setup(const BenchOptions& o, const BenchSweep& sweep);

// The runs the sweep makes, for the progress line: stereo's once per scene, hybrid's per plane
// and variant, the far field's per plane.
int count_runs(const BenchSweep& sweep, const std::vector<Plane>& planes);

// Two-pass stereo is every scene's reference, measured once before the other modes.
bool is_two_pass_stereo(const plan::RenderModeChoice& m);

// A distance in metres as the progress line and the summary write it ("3", "39.5").
std::string plane_text(double metres);

}  // namespace monoplane::app::bench
