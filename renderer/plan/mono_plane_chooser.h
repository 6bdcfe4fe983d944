// `--mono-plane auto` (issue 20): the renderer chooses m every frame from what is seen, answering
// papers/000's closing wish ("develop an approach to choose m adaptively, depending on currently
// seen objects"). The policy, in order:
//   (a) The error budget is a floor: the nearest m whose angular error (rig/angular_error.h) at
//       the farthest depth the frame's content can reach stays within error_budget_arcmin
//       (rig/error_budget.h). The depth comes from the chunks' bounds against the eyes' frusta,
//       widened by a margin so that content about to come into view is already counted (the
//       caller computes it: renderer/modes/content_depth.h); the sky is featureless and left out.
//   (b) Gaps: from the last completed frame's depth histogram, the first run of depth bins that
//       (almost) no pixel falls in, within two octaves beyond the floor, and m at its middle: few
//       surfaces then cross the plane, where the unavoidable kink shows (papers/000 Sect. 6.2).
//   (c) No visible jumps: m follows its target only once the target has moved by more than the
//       hysteresis, and then so that the far content's apparent shift (the error's change at the
//       content depth) is at most max_step_arcmin per frame. Only the floor may force a larger
//       move (reported as a jump): correctness before smoothness. TAA's history stays valid
//       under such sub-pixel shifts, as under head motion (docs/hybrid.md).
//   (d) Stereo when hybrid saves nothing: from the completed hybrid frames' pass times, a stereo
//       frame would cost the hybrid frame plus C's forward pass again minus hybrid's own passes
//       (pyramid, occlusion culling, composites). When hybrid's own passes cost more than C's
//       forward pass, or a time budget is given and the estimated stereo frame fits in it, m
//       heads for the far plane (smoothly, as in c) and the frame becomes stereo once the error
//       there is below one step. From stereo, hybrid is tried again every reprobe_frames frames
//       when a time budget is missed or a sizable share of the image lies beyond the floor.
// The floor is never nearer than min_mono_plane. Content that ends before the floor needs no C
// at all: then the frame is stereo at once (no content is shown through the plane, so nothing
// moves).
// Pure and deterministic: the same inputs give the same choices. Vulkan-free.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "common/result.h"
#include "renderer/plan/depth_histogram.h"
#include "renderer/plan/frame_plan.h"
#include "rig/error_budget.h"

namespace monoplane::plan {

struct AutoMonoPlaneParams {
    double error_budget_arcmin = 6.0;
    rig::ErrorMeasure measure = rig::ErrorMeasure::kEye;
    // The frame time (GPU, ms) to stay within: while the estimated stereo frame fits, render
    // stereo. None: hybrid whenever it saves time.
    std::optional<double> time_budget_ms;
    double max_step_arcmin = 0.25;  // largest voluntary shift of the far content per frame
    double hysteresis = 0.15;       // relative change of the target before m follows it
    double gap_octaves = 2.0;       // how far beyond the floor a gap is looked for
    // A bin is part of a gap when it and its neighbours hold at most this share of the pixels.
    double gap_share = 0.002;
    int reprobe_frames = 240;  // stereo frames before hybrid is tried again
    // (d) from measured times; off, the choice depends on the frames' content only (tests, which
    // must not depend on how fast the machine is).
    bool stereo_when_slower = true;
    // m never comes nearer than this (metres): papers/000 studied 1.6 m as its nearest plane,
    // and nearer still the near field's stereo cues, which hybrid flattens, matter most. Content
    // that ends before it is rendered in stereo.
    double min_mono_plane = 1.6;
    bool operator==(const AutoMonoPlaneParams&) const = default;
};

// The completed frame's costs that (d) needs, GPU milliseconds.
struct FrameCost {
    bool hybrid = false;           // C was drawn
    double frame_ms = 0.0;         // the whole frame
    double mono_forward_ms = 0.0;  // C's forward pass
    // Pyramid, occlusion culling, C's SSAO, composites, C's tone mapping.
    double hybrid_only_ms = 0.0;
};

// Adds one completed pass's GPU time to the frame's cost: C's forward pass, or work only hybrid
// does (a pass runs_only_in_hybrid, less the eyes' transparency passes: their blended chunks a
// stereo frame draws in its forward passes). Any other pass adds nothing.
void add_pass_time(FrameCost& cost, PassKind kind, ViewId view, double gpu_ms);

struct MonoPlaneDecision {
    double mono_plane = 0.0;     // this frame's m; far: stereo
    double floor = 0.0;          // (a): the nearest m within the budget for this content
    double target = 0.0;         // where m is heading
    double content_depth = 0.0;  // the farthest depth the budget was held for
    double error_arcmin = 0.0;   // the error measure at mono_plane for that depth
    bool jumped = false;         // the floor moved m by more than one step
    std::string reason;          // "floor", "gap", "moving", "stereo: ...", "hybrid again"
};

class MonoPlaneChooser {
  public:
    explicit MonoPlaneChooser(AutoMonoPlaneParams params);

    // This frame's m for the eyes in `eyes` (tangents, IPD, near, far, cant; its mono_plane is
    // ignored) and the farthest depth the frame's content may reach (+infinity: unknown).
    // Errors: what rig::nearest_mono_plane_within refuses (bad eyes; content_depth <= near).
    // nearest: the nearest m allowed this frame (default: params().min_mono_plane).
    Result<MonoPlaneDecision> next(const rig::RigInputs& eyes, double content_depth,
                                   std::optional<double> nearest = std::nullopt);
    // A completed frame (frames complete one or two after their next()): its depth histogram
    // (none when not measured) and costs.
    void record(const std::optional<DepthHistogram>& histogram, const FrameCost& cost);

    const AutoMonoPlaneParams& params() const { return params_; }

  private:
    // The budget's nearest m for the content (cached), before min_mono_plane.
    Result<double> budget_floor(const rig::RigInputs& eyes, double content_depth);
    double gap_beyond(double floor) const;
    Result<double> error_at(const rig::RigInputs& eyes, double m, double depth) const;
    Result<double> step_towards(const rig::RigInputs& eyes, double target, double depth) const;
    // Why this frame should head for stereo (d), or nothing. May reset the cost averages when
    // it tries hybrid again.
    std::optional<std::string> stereo_reason(double far, double floor);

    AutoMonoPlaneParams params_;
    std::optional<double> current_;  // m of the last frame
    double target_ = 0.0;
    // The floor's cache: recomputed when the content depth or the eyes change.
    std::optional<rig::RigInputs> floor_eyes_;
    double floor_depth_ = 0.0;
    double floor_ = 0.0;
    std::optional<DepthHistogram> histogram_;
    // Exponential averages over hybrid frames of C's forward pass and hybrid's own passes, and
    // over all frames of the estimated stereo frame time.
    std::optional<double> mono_forward_ms_, hybrid_only_ms_, stereo_estimate_ms_;
    int stereo_frames_ = 0;
};

}  // namespace monoplane::plan
