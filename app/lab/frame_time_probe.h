// An estimate of a session's frame time on this device before the session starts (`monoplane
// lab`'s session settings, docs/lab.md "Session settings"): a short probe render of the
// protocol's conditions with the renderers a headset session builds
// (app/commands/study_renderers.h: the protocol's [render] table, the preset's detail, eyes of
// the recommended size times the preset's scale), timed with the renderer's GPU timestamps.
//
// What is rendered: every scene of the protocol in each of its two alternatives at its nearest
// mono plane (hybrid's most expensive m: the most content drawn per eye), seen from the scene's
// seat with the HMD profile's frusta, IPD and cant; the reference alternative (the protocol's
// first, usually the dearer) of every scene before the other. Condition by condition, one
// warm-up frame (pipelines, the scene's shadow map, TAA's first frame) and one measured frame;
// then more rounds of one measured frame per condition up to frames_per_condition, all only while
// the budget lasts.
//
// How long it takes: setup (generating the scenes at the preset's detail, uploading them, building
// the renderers: about 1.7 s for fink2019's three scenes on llvmpipe on 2 cores), then frames for
// budget_s, counted from the end of setup, plus the frame in flight when it runs out. At least the
// first condition gets its warm-up and one measured frame whatever the budget, so a device that
// needs seconds per frame takes two such frames (the verdict is then clear anyway). On llvmpipe the
// default 2 s cover the first two or three conditions at the cheapest preset (complete false, the
// estimate from those measured); on a GPU, whose frames take milliseconds, every condition should
// complete within it (not measured on one yet). The caller's progress callback runs before each
// frame and may cancel there; a frame in flight is not interrupted.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "app/lab/performance_preset.h"
#include "common/result.h"
#include "hmd/profile.h"
#include "renderer/vk/context.h"
#include "study/protocol.h"

namespace monoplane::lab {

struct FrameTimeProbeRequest {
    study::Protocol protocol;  // as study::load_protocol gives it (glTF scenes are loaded here)
    PerformancePreset preset;  // presets_for(protocol): detail and resolution scale
    hmd::HmdProfile hmd;       // the eyes' frusta, IPD and cant: the session's --hmd profile
    // The runtime's recommended eye size (the launcher's headset report), or the profile's
    // width and height where no runtime reported one; scaled by the preset (scaled_eye_size).
    int recommended_width = 0;
    int recommended_height = 0;
    double budget_s = 2.0;  // from the end of setup: no frame starts later (the minimum aside)
    int frames_per_condition = 3;  // measured frames per condition, after its warm-up frame
};

// One condition's measured frames.
struct ProbeCondition {
    std::string scene;        // as the protocol names it
    std::string alternative;  // the render mode, as the protocol names it
    double mono_plane = 0.0;  // metres: the protocol's nearest
    int frames = 0;           // measured frames (0: the budget ran out before its turn)
    double frame_ms = 0.0;    // their median: GPU time of both eyes (or CPU recording, if longer)
    // Fragment-shader invocations of its first measured frame over all views (pipeline
    // statistics): deterministic for a device, detail and eye size, unlike any time.
    std::uint64_t fragments = 0;
};

struct FrameTimeEstimate {
    // What the session's frames will cost, both eyes: the median of the slowest condition
    // measured (a trial of that condition must keep the rate too). Positive and finite.
    double frame_ms = 0.0;
    std::string slowest;  // "beams / stereo at 1.6 m"
    int eye_width = 0, eye_height = 0;
    std::vector<ProbeCondition> conditions;  // every condition, measured or not
    bool complete = false;                   // every condition got frames_per_condition frames
    double elapsed_s = 0.0;  // the whole probe, setup included (wall clock, for the report only)
    std::string device;      // the Vulkan device it ran on
};

// Before the setup and before each frame: how far the probe is. The callback runs on the probing
// thread (the launcher's worker) and returns false to cancel.
struct ProbeProgress {
    int frames_done = 0;
    int frames_planned = 0;  // warm-ups and measured frames of every condition
    std::string condition;   // the condition of the next frame
    double elapsed_s = 0.0;
};
using ProbeCallback = std::function<bool(const ProbeProgress&)>;

// Renders the probe on `ctx` and returns the estimate. Refuses (one message each): a preset whose
// detail the renderer does not know, a protocol scene file that cannot be loaded, a condition the
// renderer refuses (e.g. hybrid-farfield with a canted HMD profile), recommended sizes not
// positive, frames_per_condition below 1, a device error; "the frame-time probe was cancelled"
// when the callback returned false. May be called from any one thread at a time per context,
// never while a session renders on the same device (each would slow the other, and the estimate
// would be of neither); blocks until done (see above for how long), holding no lock.
Result<FrameTimeEstimate> probe_frame_time(const vk_core::Context& ctx,
                                           const FrameTimeProbeRequest& request,
                                           const ProbeCallback& progress = {});

// The same on a device of its own, chosen as a session chooses without a headset
// (options.device_selector; the OpenXR runtime may pick another GPU where there are several).
// With options.validation, any validation message refuses the estimate, quoting the first ones.
// Creating the device adds about 0.1 to 0.5 s.
Result<FrameTimeEstimate> probe_frame_time(const vk_core::ContextOptions& options,
                                           const FrameTimeProbeRequest& request,
                                           const ProbeCallback& progress = {});

}  // namespace monoplane::lab
