#include "study/session_screens.h"

#include <algorithm>
#include <cmath>
#include <set>

namespace monoplane::study {

namespace {

bool break_due(const BreakSettings& breaks, int data_decided, const ScheduledTrial& previous,
               const ScheduledTrial& next) {
    if (breaks.every_trials > 0 && data_decided > 0 && data_decided % breaks.every_trials == 0) {
        return true;
    }
    return breaks.between_blocks && next.block != previous.block;
}

}  // namespace

ScreenDue screen_before_trial(const StudyDaySettings& day, const ScreenProgress& progress,
                              int data_decided, const ScheduledTrial* previous,
                              const ScheduledTrial* next) {
    if (progress.instructions_page < static_cast<int>(day.instructions.size())) {
        return ScreenDue::Instructions;
    }
    // Screens before a trial only: after the last one comes the questionnaire, then the end.
    if (next == nullptr || next->practice) return ScreenDue::None;
    if (day.ready && !progress.ready_confirmed && data_decided == 0) return ScreenDue::Ready;
    if (previous == nullptr || progress.break_taken || !day.breaks) return ScreenDue::None;
    return break_due(*day.breaks, data_decided, *previous, *next) ? ScreenDue::Break
                                                                  : ScreenDue::None;
}

std::vector<int> planned_breaks(const StudyDaySettings& day, const Schedule& schedule) {
    ScreenProgress progress;
    progress.instructions_page = static_cast<int>(day.instructions.size());
    progress.ready_confirmed = true;
    std::vector<int> breaks;
    const ScheduledTrial* previous = nullptr;
    int data_decided = 0;
    for (const ScheduledTrial& trial : schedule.trials) {
        if (trial.practice) continue;
        if (screen_before_trial(day, progress, data_decided, previous, &trial) ==
            ScreenDue::Break) {
            breaks.push_back(trial.index);
        }
        previous = &trial;
        ++data_decided;
    }
    return breaks;
}

namespace {

// How long the frame log shows a break lasted: the frames from break_started's on, in order, up
// to the first whose time goes back or jumps by more than a second. Runs since schema 8 share one
// time axis (session_runs.h), so a resumed run's frames continue the break's time and count;
// a run before it had a clock of another origin, and its share is not counted: the break is
// never cut short.
std::int64_t frames_elapsed(const std::vector<FrameRecord>& frames, std::int64_t first_frame,
                            std::int64_t started_ns) {
    constexpr std::int64_t kRunGapNs = 1'000'000'000;
    std::vector<const FrameRecord*> run;
    for (const FrameRecord& f : frames)
        if (f.frame >= first_frame) run.push_back(&f);
    std::ranges::sort(run, {}, &FrameRecord::frame);
    std::int64_t previous_ns = started_ns;
    for (const FrameRecord* f : run) {
        if (f->display_time_ns < previous_ns || f->display_time_ns - previous_ns > kRunGapNs) break;
        previous_ns = f->display_time_ns;
    }
    return previous_ns - started_ns;
}

}  // namespace

ScreenResume resume_screens(const std::vector<TrialEvent>& events, int instruction_pages,
                            const std::vector<FrameRecord>& frames) {
    ScreenResume resume;
    std::set<int> confirmed_pages;
    std::int64_t break_started_ns = 0;
    std::int64_t break_started_frame = -1;
    for (const TrialEvent& e : events) {
        if (resume.break_open) {
            resume.break_elapsed_ns =
                std::max(resume.break_elapsed_ns, e.time_ns - break_started_ns);
        }
        if (!is_screen_event(e.kind) && e.trial_index >= 0) {
            // A trial event closes the gap the last break belonged to.
            resume.last_trial = e.trial_index;
            resume.break_open = false;
            resume.break_ended = false;
            continue;
        }
        switch (e.kind) {
            case EventKind::InstructionsConfirmed:
                confirmed_pages.insert(e.page);
                break;
            case EventKind::ReadyConfirmed:
                resume.progress.ready_confirmed = true;
                break;
            case EventKind::BreakStarted:
                // A start while the break is open is the same break, shown again after a resume:
                // its time counts from the first start.
                if (resume.break_open) break;
                resume.break_open = true;
                resume.break_ended = false;
                resume.break_elapsed_ns = 0;
                break_started_ns = e.time_ns;
                break_started_frame = e.frame;
                break;
            case EventKind::BreakEnded:
                resume.break_open = false;
                resume.break_ended = true;
                break;
            default:
                break;
        }
    }
    if (resume.break_open && break_started_frame >= 0) {
        resume.break_elapsed_ns = std::max(
            resume.break_elapsed_ns, frames_elapsed(frames, break_started_frame, break_started_ns));
    }
    // The last page confirmed means the instructions were read (a page before it may have been
    // left by going back); otherwise they restart at the first page not confirmed.
    int page = 0;
    if (instruction_pages > 0 && confirmed_pages.contains(instruction_pages - 1)) {
        page = instruction_pages;
    } else {
        while (page < instruction_pages && confirmed_pages.contains(page)) ++page;
    }
    resume.progress.instructions_page = page;
    resume.progress.break_taken = resume.break_ended;
    return resume;
}

std::int64_t break_remaining_ns(const BreakSettings& breaks, std::int64_t elapsed_ns) {
    const auto min_ns = static_cast<std::int64_t>(std::llround(breaks.min_s * 1e9));
    return std::clamp<std::int64_t>(min_ns - elapsed_ns, 0, min_ns);
}

}  // namespace monoplane::study
