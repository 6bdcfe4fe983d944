// The trial's rules as TrialStateMachine applies them, replayed on stored events: a label's time
// runs from the frame that showed it to the next change, pauses are left out, and the viewing
// time runs from the first visibility to the decision. Here a run may also end without one.
#include "study/trial_runs.h"

#include <algorithm>
#include <limits>
#include <optional>

namespace monoplane::study {
namespace {

constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max();

// Durations never go negative, even if a record's clocks disagree by a little.
std::int64_t elapsed(std::int64_t from, std::int64_t to) {
    return std::max<std::int64_t>(0, to - from);
}

// One trial in one run, from its `shown` event on.
struct Segment {
    int visible = 0;
    std::int64_t visible_since_ns = 0;
    std::int64_t first_visible_ns = 0;
    std::int64_t first_frame = 0;
    std::optional<std::int64_t> paused_at_ns;  // while paused
    std::int64_t paused_total_ns = 0;
    std::int64_t last_ns = 0;              // the latest time the run recorded of the trial
    std::optional<std::int64_t> ended_ns;  // confirmed or aborted: viewing ended there
    int switches = 0;
    std::int64_t on_label_ns[2] = {0, 0};

    void close_dwell(std::int64_t time_ns) {
        if (paused_at_ns) return;  // the pause closed it
        on_label_ns[visible - 1] += elapsed(visible_since_ns, time_ns);
        visible_since_ns = time_ns;
    }

    void apply(const TrialEvent& e) {
        last_ns = std::max(last_ns, e.time_ns);
        if (ended_ns) return;
        switch (e.kind) {
            case EventKind::Switched:
                close_dwell(e.time_ns);
                visible = e.label;
                ++switches;
                break;
            case EventKind::Paused:
                close_dwell(e.time_ns);
                paused_at_ns = e.time_ns;
                break;
            case EventKind::Resumed:
                if (paused_at_ns) paused_total_ns += elapsed(*paused_at_ns, e.time_ns);
                paused_at_ns.reset();
                visible_since_ns = e.time_ns;
                break;
            case EventKind::Confirmed:
            case EventKind::Aborted:
                close_dwell(e.time_ns);
                ended_ns = paused_at_ns.value_or(e.time_ns);
                break;
            default:
                break;
        }
    }

    // The run is over: its record of the trial ends at `last_ns` unless the trial ended before.
    void finish(TrialRuns& runs) {
        const std::int64_t end = ended_ns.value_or(paused_at_ns.value_or(last_ns));
        close_dwell(end);
        ++runs.runs;
        runs.switches += switches;
        runs.time_on_label_ns[0] += on_label_ns[0];
        runs.time_on_label_ns[1] += on_label_ns[1];
        runs.viewing_ns += elapsed(first_visible_ns, end) - paused_total_ns;
    }
};

// The frame log's latest time of `trial` in the run that starts at its `shown` frame `from`:
// frames of the trial up to its next `shown` (a later run) and before `until` (the next run's
// start on the session's axis).
std::int64_t last_frame_ns(const std::vector<const FrameRecord*>& frames,
                           const std::vector<std::int64_t>& shown_frames, std::int64_t from,
                           std::int64_t until) {
    const auto next = std::upper_bound(shown_frames.begin(), shown_frames.end(), from);
    const std::int64_t to = next == shown_frames.end() ? kNever : *next;
    std::int64_t last = std::numeric_limits<std::int64_t>::min();
    for (const FrameRecord* f : frames)
        if (f->frame >= from && f->frame < to && f->display_time_ns < until)
            last = std::max(last, f->display_time_ns);
    return last;
}

class Replay {
  public:
    explicit Replay(const std::vector<FrameRecord>& frames) {
        for (const FrameRecord& f : frames)
            if (f.trial_index) frames_[*f.trial_index].push_back(&f);
    }

    void note_shown_frames(const std::vector<TrialEvent>& events) {
        for (const TrialEvent& e : events)
            if (e.kind == EventKind::Shown) shown_frames_[e.trial_index].push_back(e.frame);
        for (auto& [trial, list] : shown_frames_) std::ranges::sort(list);
    }

    void apply(const TrialEvent& e) {
        if (e.kind == EventKind::RunStarted) {
            // Every trial's run is over: the next run shows a trial again from label 1.
            for (auto& [trial, segment] : open_) finish(trial, segment, e.time_ns);
            open_.clear();
            return;
        }
        if (!is_trial_event(e.kind)) return;
        auto open = open_.find(e.trial_index);
        if (e.kind == EventKind::Shown) {
            // A second `shown` in a file without run_started events: an earlier resume.
            if (open != open_.end()) finish(e.trial_index, open->second, kNever);
            Segment& s = open_[e.trial_index];
            s = Segment{};
            s.visible = e.label;
            s.visible_since_ns = s.first_visible_ns = s.last_ns = e.time_ns;
            s.first_frame = e.frame;
            return;
        }
        // Before its label shows, a trial's run has nothing to count.
        if (open != open_.end()) open->second.apply(e);
    }

    std::map<int, TrialRuns> finish_all() {
        for (auto& [trial, segment] : open_) finish(trial, segment, kNever);
        open_.clear();
        return std::move(runs_);
    }

  private:
    void finish(int trial, Segment& segment, std::int64_t until_ns) {
        if (segment.first_frame >= 0)
            segment.last_ns = std::max(
                segment.last_ns,
                last_frame_ns(frames_[trial], shown_frames_[trial], segment.first_frame, until_ns));
        segment.finish(runs_[trial]);
    }

    std::map<int, std::vector<const FrameRecord*>> frames_;
    std::map<int, std::vector<std::int64_t>> shown_frames_;
    std::map<int, Segment> open_;
    std::map<int, TrialRuns> runs_;
};

}  // namespace

std::map<int, TrialRuns> trial_runs(const std::vector<TrialEvent>& events,
                                    const std::vector<FrameRecord>& frames) {
    Replay replay(frames);
    replay.note_shown_frames(events);
    for (const TrialEvent& e : events) replay.apply(e);
    return replay.finish_all();
}

}  // namespace monoplane::study
