// The frame and head log of a headset session: one row per displayed frame
// through StudyStore's frame queue, so rows become durable with the next committed event (and at
// least every kFlushFrames frames). A frame's GPU time arrives when its renderer's frame in
// flight completes, frames later; it is matched to the frame by submission order.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/headset/frame_times.h"
#include "app/headset/openxr_headset.h"
#include "renderer/profile/driver_compiles.h"
#include "renderer/profile/frame_stats.h"
#include "rig/pose.h"
#include "study/live_session.h"
#include "study/study_store.h"

namespace monoplane::modes {
class ModeRenderer;
}  // namespace monoplane::modes

namespace monoplane::app {

// What a frame showed, as the log names it: label1 | label2 | paused | neutral | questionnaire |
// finished, or one of the protocol's pages: instructions | ready | break | end.
std::string shown_name(const study::LiveScreen& screen);

class HeadsetFrameLog {
  public:
    static constexpr int kFlushFrames = 30;

    HeadsetFrameLog(study::StudyStore& store, std::int64_t session_id);

    // A displayed frame. renderer: the one that drew its scene (its GPU time follows), or null.
    // head: the head relative to the seat (SeatAnchor), none while tracking is lost.
    // gaze_point: where the frame's gaze rested in its scene (gaze_point.h), if found.
    void displayed(const headset::HeadsetFrame& frame, const study::LiveScreen& screen,
                   const std::optional<rig::Pose>& head, double cpu_ms,
                   const modes::ModeRenderer* renderer,
                   const std::optional<study::GazePointRecord>& gaze_point = std::nullopt);
    // The statistics a renderer's completed frames returned, oldest first.
    void completed(const modes::ModeRenderer* renderer,
                   const std::vector<profile::FrameStats>& stats);
    // Writes what is queued.
    void flush();
    // What frames made the renderer build, for the end of the session: pipelines created after
    // the first logged frame, and the driver's compiles in steady frames (a frame of a trial's
    // scene that shows what the kSettlingFrames frames before it showed: a screen's first frame
    // may compile what it is the first to draw, and the driver compiles its work while it runs,
    // which a renderer with two frames in flight may log up to three frames later: seen on
    // simxr, the first scene frame's compile landing in the third frame's wait). Steady compiles
    // stall what the participant sees while the head turns. (Screens without a scene, such as the
    // questionnaire, change what they draw as the participant answers.)
    static constexpr int kSettlingFrames = 3;
    // The summary also gives resident memory after this many frames and at its end: a session
    // must not grow however long it runs.
    static constexpr std::int64_t kMemoryWarmupFrames = 300;
    std::string build_summary() const;

  private:
    // Fills the row's pipelines_created and driver_compiles, and the session's totals.
    void count_builds(study::FrameRecord& row);

    study::StudyStore& store_;
    std::int64_t session_id_;
    std::optional<std::int64_t> previous_display_ns_;
    std::uint64_t pipelines_seen_;
    profile::DriverCompiles compiles_seen_;
    std::optional<std::pair<std::optional<int>, std::string>> previous_screen_;
    std::int64_t frames_ = 0;
    std::int64_t late_pipelines_ = 0;  // after the first frame
    int screen_frames_ = 0;            // frames the current screen has shown, this one included
    std::int64_t steady_frames_ = 0;
    std::int64_t steady_compiles_ = 0;
    std::int64_t steady_compile_frames_ = 0;
    double steady_compile_seconds_ = 0.0;
    std::optional<std::uint64_t> resident_after_warmup_;
    int since_flush_ = 0;
    std::map<const modes::ModeRenderer*, std::deque<std::int64_t>>
        awaiting_gpu_;  // per renderer, in order
};

}  // namespace monoplane::app
