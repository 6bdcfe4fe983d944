// A row of the frame and head log (docs/data.md, table frames).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace monoplane::study {

// The eye tracker's sample for a frame's display time (XR_EXT_eye_gaze_interaction): whether
// it was valid (the runtime located the gaze, tracked), and the gaze direction, a unit vector in
// the head's space (-z ahead, as the head pose's frame), meaningful only when valid.
struct GazeRecord {
    bool valid = false;
    std::array<double, 3> direction{0.0, 0.0, -1.0};
};

// Where a frame's gaze ray met the scene, and hybrid's error there (docs/gaze.md): derived as the
// frame is logged, for every frame of a trial's scene with a valid gaze sample, whichever
// alternative the frame showed.
struct GazePointRecord {
    // The larger over both eyes of the angle between where stereo and where hybrid (at
    // mono_plane_m) show the point, arcmin: 0 for a point nearer than the plane.
    double error_arcmin = 0.0;
    // The point's depth: metres in front of the eyes' plane (along the head's -z). None: the
    // ray met no surface (the sky), the point lies infinitely far.
    std::optional<double> depth_m = std::nullopt;
    // The m the error is for: the trial's mono plane (the one its hybrid alternative shows).
    double mono_plane_m = 0.0;
    bool beyond_mono_plane() const { return !depth_m || *depth_m > mono_plane_m; }
};

// One displayed frame of a headset session: the frame and head log.
struct FrameRecord {
    std::int64_t frame = 0;          // the runtime's frame index (HeadsetFrame::index)
    std::optional<int> trial_index;  // none outside a trial
    // label1 | label2 | neutral | paused | questionnaire | finished | instructions | ready |
    // break | end
    std::string shown;
    std::int64_t display_time_ns = 0;  // the runtime's predicted display time
    double cpu_ms = 0.0;               // host time of the frame, xrWaitFrame to xrEndFrame
    std::optional<double> gpu_ms;      // the renderer's timestamps; none without a scene
    // The display slot before this frame went without a new frame (the runtime showed the
    // previous one again): predicted display times more than 1.5 periods apart.
    bool missed = false;
    // The head relative to the participant's seat (the first tracked pose, turned about the
    // vertical to look along the scene's view; a trial's views are the scene's viewpoint moved
    // by it): x, y, z in metres, then the orientation quaternion w, x, y, z; none while tracking
    // was lost.
    std::optional<std::array<double, 7>> head;
    // Hybrid modes: the frame's mono plane in metres (with hybrid-auto, the renderer's choice that
    // frame; the far plane when it drew the frame as stereo); none for stereo modes and screens
    // without a scene. Known when the frame completes, like gpu_ms.
    std::optional<double> mono_plane;
    // Since the previous logged frame (the first: since the renderers were built): pipelines
    // monoplane created, and shader modules the driver compiled (none where it cannot be
    // counted; profile::driver_compiles). Both 0 after warm-up; none in sessions before these
    // were logged.
    std::optional<std::int64_t> pipelines_created;
    std::optional<std::int64_t> driver_compiles;
    // [gaze] record on a runtime that tracks the eyes: the frame's gaze sample; none where gaze
    // was not recorded (not asked, no eye tracker, sessions before gaze was logged).
    std::optional<GazeRecord> gaze;
    // The gaze point and hybrid's error there; none where it was not derived (no valid sample,
    // no scene shown, a trial without a fixed mono plane, sessions before it was derived).
    std::optional<GazePointRecord> gaze_point;
};

}  // namespace monoplane::study
