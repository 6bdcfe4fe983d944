// The frame and head log of a headset session (DESIGN.md section 7): one row per displayed frame
// through StudyStore's frame queue, so rows become durable with the next committed event (and at
// least every kFlushFrames frames). A frame's GPU time arrives when its renderer's frame in
// flight completes, frames later; it is matched to the frame by submission order.
#pragma once

#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <vector>

#include "app/headset/frame_times.h"
#include "app/headset/openxr_headset.h"
#include "renderer/profile/frame_stats.h"
#include "renderer/rig/pose.h"
#include "study/live_session.h"
#include "study/study_store.h"

namespace monoplane::modes {
class ModeRenderer;
}  // namespace monoplane::modes

namespace monoplane::app {

// What a frame showed, as the log names it: label1 | label2 | paused | neutral | questionnaire |
// finished.
std::string shown_name(const study::LiveScreen& screen);

class HeadsetFrameLog {
  public:
    static constexpr int kFlushFrames = 30;

    HeadsetFrameLog(study::StudyStore& store, std::int64_t session_id);

    // A displayed frame. renderer: the one that drew its scene (its GPU time follows), or null.
    // head: the head relative to the seat (SeatAnchor), none while tracking is lost.
    void displayed(const headset::HeadsetFrame& frame, const study::LiveScreen& screen,
                   const std::optional<rig::Pose>& head, double cpu_ms,
                   const modes::ModeRenderer* renderer);
    // The statistics a renderer's completed frames returned, oldest first.
    void completed(const modes::ModeRenderer* renderer,
                   const std::vector<profile::FrameStats>& stats);
    // Writes what is queued.
    void flush();

  private:
    study::StudyStore& store_;
    std::int64_t session_id_;
    std::optional<std::int64_t> previous_display_ns_;
    int since_flush_ = 0;
    std::map<const modes::ModeRenderer*, std::deque<std::int64_t>>
        awaiting_gpu_;  // per renderer, in order
};

}  // namespace monoplane::app
