#include "app/commands/headset_frame_log.h"

#include <sstream>

#include "common/resident_memory.h"
#include "renderer/vk/pipeline.h"

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
        case study::ScreenKind::Instructions:
            return "instructions";
        case study::ScreenKind::Ready:
            return "ready";
        case study::ScreenKind::Break:
            return "break";
        case study::ScreenKind::End:
            return "end";
    }
    return "neutral";
}

HeadsetFrameLog::HeadsetFrameLog(study::StudyStore& store, std::int64_t session_id)
    : store_(store),
      session_id_(session_id),
      pipelines_seen_(vk_core::pipelines_created()),
      compiles_seen_(profile::driver_compiles()) {}

void HeadsetFrameLog::displayed(const headset::HeadsetFrame& frame, const study::LiveScreen& screen,
                                const std::optional<rig::Pose>& head, double cpu_ms,
                                const modes::ModeRenderer* renderer,
                                const std::optional<study::GazePointRecord>& gaze_point) {
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
    if (frame.gaze) {
        const glm::dvec3& d = frame.gaze->direction;
        row.gaze = study::GazeRecord{frame.gaze->valid, {d.x, d.y, d.z}};
    }
    row.gaze_point = gaze_point;
    count_builds(row);
    store_.queue_frame(session_id_, row);
    if (renderer) awaiting_gpu_[renderer].push_back(frame.index);
    if (++since_flush_ >= kFlushFrames) flush();
}

void HeadsetFrameLog::count_builds(study::FrameRecord& row) {
    const std::uint64_t pipelines = vk_core::pipelines_created();
    const profile::DriverCompiles compiles = profile::driver_compiles();
    const profile::DriverCompiles since = profile::compiles_between(compiles_seen_, compiles);
    row.pipelines_created = static_cast<std::int64_t>(pipelines - pipelines_seen_);
    if (since.measurable) row.driver_compiles = static_cast<std::int64_t>(since.modules);
    if (frames_ > 0) late_pipelines_ += *row.pipelines_created;
    const auto screen = std::make_pair(row.trial_index, row.shown);
    screen_frames_ = previous_screen_ == screen ? screen_frames_ + 1 : 1;
    const bool scene = row.shown == "label1" || row.shown == "label2";
    const bool steady = scene && screen_frames_ > kSettlingFrames;
    if (steady) ++steady_frames_;
    if (steady && since.modules > 0) {
        steady_compiles_ += static_cast<std::int64_t>(since.modules);
        ++steady_compile_frames_;
        steady_compile_seconds_ += since.seconds;
    }
    previous_screen_ = screen;
    pipelines_seen_ = pipelines;
    compiles_seen_ = compiles;
    ++frames_;
    if (frames_ == kMemoryWarmupFrames) resident_after_warmup_ = resident_bytes();
}

std::string HeadsetFrameLog::build_summary() const {
    std::ostringstream out;
    out << "builds while frames ran: " << late_pipelines_
        << " pipelines created after the first frame; ";
    if (!compiles_seen_.measurable) {
        out << "the driver's shader compiles cannot be counted on this device\n";
    } else {
        out << steady_compiles_ << " driver shader compiles in " << steady_compile_frames_ << " of "
            << steady_frames_ << " frames of a trial's scene that showed what the "
            << kSettlingFrames << " frames before showed";
        if (steady_compiles_ > 0) {
            out.precision(3);
            out << " (" << steady_compile_seconds_
                << " s): the driver compiled shader variants while a screen was showing, and "
                   "those frames stalled";
        }
        out << "\n";
    }
    // Whatever the device lets us count: the memory is the process's own.
    const std::optional<std::uint64_t> now = resident_bytes();
    if (resident_after_warmup_ && now) {
        const double mib = 1024.0 * 1024.0;
        out.precision(1);
        out << std::fixed
            << "resident memory: " << static_cast<double>(*resident_after_warmup_) / mib
            << " MiB after " << kMemoryWarmupFrames << " frames, "
            << static_cast<double>(*now) / mib << " MiB after " << frames_ << " (" << std::showpos
            << (static_cast<double>(*now) - static_cast<double>(*resident_after_warmup_)) / mib
            << std::noshowpos << " MiB)\n";
    }
    return out.str();
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
