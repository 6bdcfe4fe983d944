// The protocol's screens in a session (study/session_screens.h): which screen comes before a
// trial, where breaks fall in a schedule, and where a resumed session stood, from hand-made
// event lists.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "study/protocol.h"
#include "study/schedule.h"
#include "study/session_screens.h"

namespace monoplane::study {
namespace {

constexpr std::int64_t kS = 1'000'000'000;

// 2 scenes x 3 distances in the listed order: data trials 1-3 in block 0 (beams), 4-6 in block 1
// (spheres), after one practice trial (index 0, block -1).
Protocol six_trials(int practice = 1) {
    const std::string text = R"(name = "screens"
scenes = ["beams", "spheres"]
mono_planes = [3, 8, 16]
alternatives = ["stereo", "hybrid"]
order = "fixed"
first_scene = "fixed"
practice_trials = )" + std::to_string(practice) +
                             "\n";
    Result<Protocol> protocol = parse_protocol(text, "screens.toml");
    EXPECT_TRUE(protocol.ok()) << (protocol.ok() ? "" : protocol.error().message);
    return protocol.ok() ? std::move(protocol).value() : Protocol{};
}

BreakSettings breaks(int every_trials, bool between_blocks) {
    BreakSettings b;
    b.every_trials = every_trials;
    b.between_blocks = between_blocks;
    return b;
}

TEST(SessionScreens, TheScheduleHasTheBlocksTheTestsAssume) {
    const Schedule schedule = make_schedule(six_trials(), 5, 0);
    ASSERT_EQ(schedule.trials.size(), 7u);
    const int blocks[] = {-1, 0, 0, 0, 1, 1, 1};
    for (int i = 0; i < 7; ++i) {
        EXPECT_EQ(schedule.trials[i].index, i);
        EXPECT_EQ(schedule.trials[i].block, blocks[i]) << i;
        EXPECT_EQ(schedule.trials[i].practice, i == 0) << i;
    }
}

// Breaks by count fall after every N data trials (practice not counted), by block where the
// block changes; both together once per gap; never before the first data trial or after the last.
TEST(SessionScreens, PlannedBreaksByCountAndByBlock) {
    const Schedule schedule = make_schedule(six_trials(), 5, 0);
    StudyDaySettings day;
    EXPECT_TRUE(planned_breaks(day, schedule).empty());
    day.breaks = breaks(2, false);
    EXPECT_EQ(planned_breaks(day, schedule), (std::vector<int>{3, 5}));
    day.breaks = breaks(0, true);
    EXPECT_EQ(planned_breaks(day, schedule), (std::vector<int>{4}));
    day.breaks = breaks(2, true);
    EXPECT_EQ(planned_breaks(day, schedule), (std::vector<int>{3, 4, 5}));
    day.breaks = breaks(3, true);  // after the third data trial the block changes too: one break
    EXPECT_EQ(planned_breaks(day, schedule), (std::vector<int>{4}));
    day.breaks = breaks(1, false);
    EXPECT_EQ(planned_breaks(day, schedule), (std::vector<int>{2, 3, 4, 5, 6}));
    day.breaks = breaks(6, false);  // after the last data trial: none
    EXPECT_TRUE(planned_breaks(day, schedule).empty());
    day.breaks = breaks(0, false);  // neither trigger
    EXPECT_TRUE(planned_breaks(day, schedule).empty());
}

TEST(SessionScreens, InstructionsComeFirstUntilEveryPageIsConfirmed) {
    const Schedule schedule = make_schedule(six_trials(), 5, 0);
    StudyDaySettings day;
    day.instructions = {{"one"}, {"two"}};
    day.ready = ScreenPage{"ready"};
    ScreenProgress progress;
    const ScheduledTrial* practice = &schedule.trials[0];
    EXPECT_EQ(screen_before_trial(day, progress, 0, nullptr, practice), ScreenDue::Instructions);
    progress.instructions_page = 1;
    EXPECT_EQ(screen_before_trial(day, progress, 0, nullptr, practice), ScreenDue::Instructions);
    progress.instructions_page = 2;
    // Before the practice trial no ready screen; before the first data trial, one.
    EXPECT_EQ(screen_before_trial(day, progress, 0, nullptr, practice), ScreenDue::None);
    EXPECT_EQ(screen_before_trial(day, progress, 0, nullptr, &schedule.trials[1]),
              ScreenDue::Ready);
    progress.ready_confirmed = true;
    EXPECT_EQ(screen_before_trial(day, progress, 0, nullptr, &schedule.trials[1]), ScreenDue::None);
    // No screen before "no trial" (the questionnaire and the end screen come then).
    progress.ready_confirmed = false;
    EXPECT_EQ(screen_before_trial(day, progress, 6, &schedule.trials[6], nullptr), ScreenDue::None);
}

TEST(SessionScreens, ABreakIsShownOncePerGap) {
    const Schedule schedule = make_schedule(six_trials(), 5, 0);
    StudyDaySettings day;
    day.breaks = breaks(0, true);
    ScreenProgress progress;
    progress.ready_confirmed = true;
    const ScheduledTrial* last_of_block0 = &schedule.trials[3];
    const ScheduledTrial* first_of_block1 = &schedule.trials[4];
    EXPECT_EQ(screen_before_trial(day, progress, 3, last_of_block0, first_of_block1),
              ScreenDue::Break);
    progress.break_taken = true;
    EXPECT_EQ(screen_before_trial(day, progress, 3, last_of_block0, first_of_block1),
              ScreenDue::None);
}

TrialEvent screen(EventKind kind, std::int64_t time_ns, int page = -1, std::int64_t frame = -1) {
    TrialEvent e;
    e.kind = kind;
    e.trial_index = -1;
    e.time_ns = time_ns;
    e.frame = frame;
    e.page = page;
    return e;
}

TrialEvent trial(EventKind kind, int index, std::int64_t time_ns, int label = 1) {
    TrialEvent e;
    e.kind = kind;
    e.trial_index = index;
    e.label = label;
    e.time_ns = time_ns;
    return e;
}

TEST(SessionScreens, ResumeMidInstructionsRestartsAtTheFirstUnconfirmedPage) {
    EXPECT_EQ(resume_screens({}, 3).progress.instructions_page, 0);
    const std::vector<TrialEvent> events = {
        screen(EventKind::InstructionsShown, 1 * kS, 0, 90),
        screen(EventKind::InstructionsConfirmed, 4 * kS, 0),
        screen(EventKind::InstructionsShown, 4 * kS, 1, 360),
    };
    const ScreenResume r = resume_screens(events, 3);
    EXPECT_EQ(r.progress.instructions_page, 1);
    EXPECT_FALSE(r.progress.ready_confirmed);
    EXPECT_EQ(r.last_trial, -1);
    EXPECT_FALSE(r.break_open);
}

TEST(SessionScreens, ResumeAfterGoingBackKeepsThePagesConfirmed) {
    // Pages 0 and 1 confirmed, page 2 shown, back to page 1: page 2 is the first unconfirmed.
    const std::vector<TrialEvent> events = {
        screen(EventKind::InstructionsShown, 1 * kS, 0, 90),
        screen(EventKind::InstructionsConfirmed, 4 * kS, 0),
        screen(EventKind::InstructionsShown, 4 * kS, 1, 360),
        screen(EventKind::InstructionsConfirmed, 7 * kS, 1),
        screen(EventKind::InstructionsShown, 7 * kS, 2, 630),
        screen(EventKind::InstructionsShown, 8 * kS, 1, 720),
    };
    EXPECT_EQ(resume_screens(events, 3).progress.instructions_page, 2);
}

TEST(SessionScreens, ResumeAfterInstructionsAndReady) {
    std::vector<TrialEvent> events = {
        screen(EventKind::InstructionsShown, 1 * kS, 0, 90),
        screen(EventKind::InstructionsConfirmed, 4 * kS, 0),
    };
    EXPECT_EQ(resume_screens(events, 1).progress.instructions_page, 1);
    events.push_back(trial(EventKind::Shown, 0, 5 * kS));
    events.push_back(trial(EventKind::Confirmed, 0, 6 * kS));
    events.push_back(screen(EventKind::ReadyShown, 6 * kS, -1, 540));
    ScreenResume r = resume_screens(events, 1);
    EXPECT_EQ(r.last_trial, 0);
    EXPECT_FALSE(r.progress.ready_confirmed);
    events.push_back(screen(EventKind::ReadyConfirmed, 7 * kS));
    r = resume_screens(events, 1);
    EXPECT_TRUE(r.progress.ready_confirmed);
    EXPECT_EQ(r.progress.instructions_page, 1);
}

// A headset session logs no event during a break, but its frame log goes on (flushed at least every
// 30 frames): the frames shown since the break started say how long it lasted.
TEST(SessionScreens, ResumeMidBreakCountsTheFramesLoggedDuringIt) {
    const std::vector<TrialEvent> events = {
        trial(EventKind::Confirmed, 3, 50 * kS),
        screen(EventKind::BreakStarted, 51 * kS, -1, 4500),
    };
    std::vector<FrameRecord> frames;
    for (std::int64_t f = 4400; f < 4500 + 270; ++f) {  // 90 Hz: 3 s of break logged
        FrameRecord r;
        r.frame = f;
        r.display_time_ns = 51 * kS + (f - 4500) * kS / 90;
        frames.push_back(r);
    }
    const ScreenResume r = resume_screens(events, 0, frames);
    EXPECT_TRUE(r.break_open);
    EXPECT_EQ(r.break_elapsed_ns, 269 * kS / 90);  // the last logged frame, 4769
    BreakSettings b = breaks(2, false);
    b.min_s = 30;
    EXPECT_EQ(break_remaining_ns(b, r.break_elapsed_ns), 30 * kS - 269 * kS / 90);
    // Frames before the break (the trial's) do not count.
    const ScreenResume none = resume_screens(events, 0, {frames.begin(), frames.begin() + 100});
    EXPECT_EQ(none.break_elapsed_ns, 0);
    // A resumed run that was killed again during the same break logged its frames on with
    // another clock (simxr starts at 10 s): they are not counted, the first run's 3 s are.
    std::vector<FrameRecord> twice = frames;
    for (std::int64_t f = 4770; f < 4770 + 90; ++f) {
        FrameRecord r;
        r.frame = f;
        r.display_time_ns = 10 * kS + (f - 4770) * kS / 90;
        twice.push_back(r);
    }
    EXPECT_EQ(resume_screens(events, 0, twice).break_elapsed_ns, 269 * kS / 90);
    // A real runtime's clock runs on through the downtime: a jump of minutes is another run too.
    for (FrameRecord& r : twice)
        if (r.frame >= 4770) r.display_time_ns += 200 * kS;
    EXPECT_EQ(resume_screens(events, 0, twice).break_elapsed_ns, 269 * kS / 90);
}

// Since runs share one time axis (session_runs.h), a break shown in three runs, each killed
// during it, is one break (its start logged in each run): it lasted from its first start to the
// latest time logged, every run's frames included.
TEST(SessionScreens, ABreakOverSeveralRunsOnOneAxisCountsEveryRun) {
    const std::int64_t period = kS / 90;
    std::vector<TrialEvent> events = {
        trial(EventKind::Confirmed, 3, 50 * kS),
        screen(EventKind::BreakStarted, 50 * kS, -1, 4500),
    };
    std::vector<FrameRecord> frames;
    std::int64_t t = 50 * kS;
    std::int64_t f = 4500;
    for (int run = 0; run < 3; ++run) {
        if (run > 0) {
            // The run starts 1 ns after the last time stored, shows the break again one period
            // later, and logs 2 s of its frames.
            events.push_back(screen(EventKind::RunStarted, t + 1));
            t += 1 + period;
            events.push_back(screen(EventKind::BreakStarted, t, -1, ++f));
        }
        for (int i = 0; i < 180; ++i) {
            FrameRecord r;
            r.frame = ++f;
            r.display_time_ns = (t += period);
            frames.push_back(r);
        }
    }
    const ScreenResume r = resume_screens(events, 0, frames);
    EXPECT_TRUE(r.break_open);
    EXPECT_FALSE(r.break_ended);
    EXPECT_EQ(r.break_elapsed_ns, t - 50 * kS);
    EXPECT_EQ(r.break_elapsed_ns, 540 * period + 2 * (1 + period));
    // Its end closes it.
    events.push_back(screen(EventKind::BreakEnded, t + kS));
    EXPECT_TRUE(resume_screens(events, 0, frames).progress.break_taken);
}

TEST(SessionScreens, ResumeMidBreakTellsHowLongItLasted) {
    std::vector<TrialEvent> events = {
        trial(EventKind::Shown, 3, 40 * kS),
        trial(EventKind::Confirmed, 3, 50 * kS),
        screen(EventKind::BreakStarted, 50 * kS + 11'111'111, -1, 4500),
    };
    ScreenResume r = resume_screens(events, 0);
    EXPECT_EQ(r.last_trial, 3);
    EXPECT_TRUE(r.break_open);
    EXPECT_FALSE(r.break_ended);
    EXPECT_FALSE(r.progress.break_taken);
    EXPECT_EQ(r.break_elapsed_ns, 0);  // nothing logged after its start
    // Something logged 12 s into the break (here a pause with no trial): the break lasted that.
    TrialEvent later = screen(EventKind::Paused, 62 * kS + 11'111'111);
    events.push_back(later);
    r = resume_screens(events, 0);
    EXPECT_TRUE(r.break_open);
    EXPECT_EQ(r.break_elapsed_ns, 12 * kS);
    BreakSettings b = breaks(2, false);
    b.min_s = 30;
    EXPECT_EQ(break_remaining_ns(b, r.break_elapsed_ns), 18 * kS);
    EXPECT_EQ(break_remaining_ns(b, 0), 30 * kS);
    EXPECT_EQ(break_remaining_ns(b, 45 * kS), 0);
    EXPECT_EQ(break_remaining_ns(b, -5 * kS), 30 * kS);  // another run's clock: never longer
    b.min_s = 2.5;
    EXPECT_EQ(break_remaining_ns(b, kS), 1'500'000'000);

    events.push_back(screen(EventKind::BreakEnded, 70 * kS));
    r = resume_screens(events, 0);
    EXPECT_FALSE(r.break_open);
    EXPECT_TRUE(r.break_ended);
    EXPECT_TRUE(r.progress.break_taken);
    // The next trial's events close the gap: its break is behind it.
    events.push_back(trial(EventKind::Shown, 4, 71 * kS));
    r = resume_screens(events, 0);
    EXPECT_EQ(r.last_trial, 4);
    EXPECT_FALSE(r.break_open);
    EXPECT_FALSE(r.break_ended);
}

}  // namespace
}  // namespace monoplane::study
