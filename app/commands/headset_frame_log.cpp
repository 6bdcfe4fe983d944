#include "app/commands/headset_frame_log.h"

namespace monoplane::app {

std::string shown_name(const study::LiveScreen& screen) {
    switch (screen.kind) {
        case study::ScreenKind::Trial:
            if (screen.paused) return "paused";
            return screen.label == 1 ? "label1" : "label2";
        case study::ScreenKind::Neutral:
            return "neutral";
        case study::ScreenKind::Questionnaire:
            return "questionnaire";
        case study::ScreenKind::Finished:
        case study::ScreenKind::Aborted:
            return "finished";
    }
    return "neutral";
}

HeadsetFrameLog::HeadsetFrameLog(study::StudyStore& store, std::int64_t session_id)
    : store_(store), session_id_(session_id) {}

void HeadsetFrameLog::displayed(const headset::HeadsetFrame& frame, const study::LiveScreen& screen,
                                const std::optional<rig::Pose>& head, double cpu_ms,
                                const modes::ModeRenderer* renderer) {
    study::FrameRecord row;
    row.frame = frame.index;
    if (screen.kind == study::ScreenKind::Trial && screen.trial) {
        row.trial_index = screen.trial->index;
    }
    row.shown = shown_name(screen);
    row.display_time_ns = frame.display_time_ns;
    row.cpu_ms = cpu_ms;
    row.missed =
        previous_display_ns_ &&
        headset::missed_slot(*previous_display_ns_, frame.display_time_ns, frame.display_period_ns);
    previous_display_ns_ = frame.display_time_ns;
    if (head) {
        const rig::Pose& p = *head;
        row.head =
            std::array<double, 7>{p.position.x,    p.position.y,    p.position.z,   p.orientation.w,
                                  p.orientation.x, p.orientation.y, p.orientation.z};
    }
    store_.queue_frame(session_id_, row);
    if (renderer) awaiting_gpu_[renderer].push_back(frame.index);
    if (++since_flush_ >= kFlushFrames) flush();
}

void HeadsetFrameLog::completed(const modes::ModeRenderer* renderer,
                                const std::vector<profile::FrameStats>& stats) {
    std::deque<std::int64_t>& frames = awaiting_gpu_[renderer];
    for (const profile::FrameStats& s : stats) {
        if (frames.empty()) break;  // not a logged frame (none is submitted unlogged)
        store_.queue_frame_gpu_ms(session_id_, frames.front(), s.gpu_frame_ms, s.mono_plane);
        frames.pop_front();
    }
}

void HeadsetFrameLog::flush() {
    store_.flush_frames().value_or_throw();
    since_flush_ = 0;
}

}  // namespace monoplane::app
