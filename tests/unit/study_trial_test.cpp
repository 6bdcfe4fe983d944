// The 2AFC trial state machine: what becomes visible when, what is logged,
// how times are counted, and that every call in a wrong state is an error.
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "study/trial_runs.h"
#include "study/trial_state_machine.h"

namespace monoplane::study {
namespace {

constexpr std::int64_t kMs = 1'000'000;

ScheduledTrial hybrid_is_label1() {
    ScheduledTrial t;
    t.index = 7;
    t.block = 1;
    t.scene = "beams";
    t.mono_plane = 8.0;
    t.label1_alternative = 1;
    t.label1_mode = RenderMode::Hybrid;
    t.label2_mode = RenderMode::Stereo;
    return t;
}

std::vector<TrialEvent> ok(Result<std::vector<TrialEvent>> result) {
    EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().message);
    return result.ok() ? result.value() : std::vector<TrialEvent>{};
}

void expect_event(const TrialEvent& e, EventKind kind, int label, std::int64_t time_ns,
                  std::int64_t frame) {
    EXPECT_EQ(e.kind, kind) << event_kind_name(e.kind);
    EXPECT_EQ(e.trial_index, 7);
    EXPECT_EQ(e.label, label) << event_kind_name(e.kind);
    EXPECT_EQ(e.time_ns, time_ns) << event_kind_name(e.kind);
    EXPECT_EQ(e.frame, frame) << event_kind_name(e.kind);
}

TEST(TrialEvents, NamesAreStable) {
    EXPECT_EQ(event_kind_name(EventKind::Shown), "shown");
    EXPECT_EQ(event_kind_name(EventKind::Switched), "switched");
    EXPECT_EQ(event_kind_name(EventKind::Confirmed), "confirmed");
    EXPECT_EQ(event_kind_name(EventKind::Refused), "refused");
    EXPECT_EQ(event_kind_name(EventKind::Paused), "paused");
    EXPECT_EQ(event_kind_name(EventKind::Resumed), "resumed");
    EXPECT_EQ(event_kind_name(EventKind::Aborted), "aborted");
}

// Frames every 10 ms: frame f is presented at f * 10 ms. Changes are attributed to the first frame
// after the request; a confirmation is input, logged at its arrival time with no frame.
TEST(Trial, ScriptedSessionHasExactTimesAndFrames) {
    TrialStateMachine m(hybrid_is_label1(), true);
    EXPECT_EQ(m.state(), TrialState::NotStarted);
    EXPECT_EQ(m.visible_label(), 0);
    EXPECT_TRUE(ok(m.start(5 * kMs)).empty());
    EXPECT_EQ(m.state(), TrialState::Viewing);
    EXPECT_EQ(m.label_to_draw(), 1);
    EXPECT_EQ(m.visible_label(), 0);  // requested, not yet on screen

    std::vector<TrialEvent> e = m.frame_presented(1, 10 * kMs);
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Shown, 1, 10 * kMs, 1);
    EXPECT_EQ(m.visible_label(), 1);
    EXPECT_TRUE(m.frame_presented(2, 20 * kMs).empty());  // nothing changed

    EXPECT_TRUE(ok(m.request_switch(1003 * kMs)).empty());
    EXPECT_EQ(m.label_to_draw(), 2);
    EXPECT_EQ(m.visible_label(), 1);
    e = m.frame_presented(101, 1010 * kMs);
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Switched, 2, 1010 * kMs, 101);

    // Two requests within one frame cancel: never seen, so neither logged nor counted.
    ok(m.request_switch(1500 * kMs));
    ok(m.request_switch(1505 * kMs));
    EXPECT_TRUE(m.frame_presented(151, 1510 * kMs).empty());

    ok(m.request_switch(2504 * kMs));
    e = m.frame_presented(251, 2510 * kMs);
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Switched, 1, 2510 * kMs, 251);

    e = ok(m.request_confirm(3000 * kMs));
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Confirmed, 1, 3000 * kMs, -1);
    EXPECT_EQ(m.state(), TrialState::Decided);

    const TrialOutcome& o = m.outcome();
    EXPECT_EQ(o.choice, 1);
    EXPECT_EQ(o.chosen_mode, RenderMode::Hybrid);
    EXPECT_TRUE(o.valid);
    EXPECT_EQ(o.switches, 2);
    EXPECT_EQ(o.time_on_label_ns[0], (1010 - 10 + 3000 - 2510) * kMs);
    EXPECT_EQ(o.time_on_label_ns[1], (2510 - 1010) * kMs);
    EXPECT_EQ(o.decision_time_ns, (3000 - 10) * kMs);
    EXPECT_TRUE(m.frame_presented(301, 3010 * kMs).empty());  // decided: nothing more happens
}

TEST(Trial, ConfirmationIsRefusedUntilBothWereSeen) {
    TrialStateMachine m(hybrid_is_label1(), true);
    ok(m.start(0));
    m.frame_presented(1, 10 * kMs);

    Result<std::vector<TrialEvent>> refused = m.request_confirm(500 * kMs);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("both labels"), std::string::npos)
        << refused.error().message;
    ASSERT_TRUE(m.last_refusal().has_value());
    expect_event(*m.last_refusal(), EventKind::Refused, 1, 500 * kMs, -1);
    EXPECT_EQ(m.state(), TrialState::Viewing);

    // A switch requested but not yet shown does not count as seen.
    ok(m.request_switch(600 * kMs));
    EXPECT_FALSE(m.last_refusal().has_value());
    EXPECT_FALSE(m.request_confirm(601 * kMs).ok());
    m.frame_presented(61, 610 * kMs);
    std::vector<TrialEvent> e = ok(m.request_confirm(900 * kMs));
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Confirmed, 2, 900 * kMs, -1);
    EXPECT_EQ(m.outcome().choice, 2);
    EXPECT_EQ(m.outcome().chosen_mode, RenderMode::Stereo);
    EXPECT_TRUE(m.outcome().valid);
    EXPECT_EQ(m.outcome().switches, 1);
    EXPECT_EQ(m.outcome().decision_time_ns, 890 * kMs);
}

TEST(Trial, ConfirmAppliesToTheVisibleLabelNotAPendingSwitch) {
    TrialStateMachine m(hybrid_is_label1(), true);
    ok(m.start(0));
    m.frame_presented(1, 10 * kMs);
    ok(m.request_switch(100 * kMs));
    m.frame_presented(11, 110 * kMs);
    ok(m.request_switch(200 * kMs));  // back to 1, but the confirm arrives before the frame
    ok(m.request_confirm(205 * kMs));
    EXPECT_EQ(m.outcome().choice, 2);
    EXPECT_EQ(m.outcome().switches, 1);
    EXPECT_EQ(m.label_to_draw(), 2);
}

TEST(Trial, PausesAreExcludedFromAllTimes) {
    TrialStateMachine m(hybrid_is_label1(), true);
    ok(m.start(0));
    m.frame_presented(1, 100 * kMs);
    std::vector<TrialEvent> e = ok(m.pause(400 * kMs));  // 300 ms on label 1
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Paused, 0, 400 * kMs, -1);
    EXPECT_EQ(m.state(), TrialState::Paused);
    EXPECT_TRUE(m.frame_presented(50, 5000 * kMs).empty());
    EXPECT_FALSE(m.request_switch(5000 * kMs).ok());
    EXPECT_FALSE(m.request_confirm(5000 * kMs).ok());
    EXPECT_FALSE(m.pause(5000 * kMs).ok());

    e = ok(m.resume(10400 * kMs));  // a 10 s pause
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Resumed, 0, 10400 * kMs, -1);
    ok(m.request_switch(10600 * kMs));  // 200 ms more on label 1
    // A switch requested just before a pause shows after it.
    ok(m.pause(10605 * kMs));
    EXPECT_TRUE(m.frame_presented(1061, 10610 * kMs).empty());
    ok(m.resume(11605 * kMs));                 // a 1 s pause
    e = m.frame_presented(1162, 11620 * kMs);  // 15 ms more on label 1
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Switched, 2, 11620 * kMs, 1162);
    ok(m.request_confirm(12020 * kMs));  // 400 ms on label 2

    const TrialOutcome& o = m.outcome();
    EXPECT_EQ(o.time_on_label_ns[0], (300 + 200 + 5 + 15) * kMs);
    EXPECT_EQ(o.time_on_label_ns[1], 400 * kMs);
    EXPECT_EQ(o.decision_time_ns, (12020 - 100 - 10000 - 1000) * kMs);
    EXPECT_EQ(o.decision_time_ns, o.time_on_label_ns[0] + o.time_on_label_ns[1]);
}

TEST(Trial, APauseBeforeTheFirstFrameIsNotPartOfTheDecision) {
    TrialStateMachine m(hybrid_is_label1(), false);
    ok(m.start(0));
    ok(m.pause(1 * kMs));
    EXPECT_TRUE(m.frame_presented(1, 10 * kMs).empty());
    ok(m.resume(2000 * kMs));
    std::vector<TrialEvent> e = m.frame_presented(201, 2010 * kMs);
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Shown, 1, 2010 * kMs, 201);
    ok(m.request_confirm(2510 * kMs));
    EXPECT_EQ(m.outcome().decision_time_ns, 500 * kMs);
    EXPECT_EQ(m.outcome().time_on_label_ns[0], 500 * kMs);
}

TEST(Trial, WithoutTheRequirementAnUnseenAlternativeMakesTheDecisionInvalid) {
    TrialStateMachine m(hybrid_is_label1(), false);
    ok(m.start(0));
    m.frame_presented(1, 10 * kMs);
    std::vector<TrialEvent> e = ok(m.request_confirm(2010 * kMs));
    ASSERT_EQ(e.size(), 1u);
    expect_event(e[0], EventKind::Confirmed, 1, 2010 * kMs, -1);
    EXPECT_FALSE(m.last_refusal().has_value());
    const TrialOutcome& o = m.outcome();
    EXPECT_EQ(o.choice, 1);
    EXPECT_EQ(o.chosen_mode, RenderMode::Hybrid);
    EXPECT_FALSE(o.valid);
    EXPECT_EQ(o.switches, 0);
    EXPECT_EQ(o.time_on_label_ns[0], 2000 * kMs);
    EXPECT_EQ(o.time_on_label_ns[1], 0);
    EXPECT_EQ(o.decision_time_ns, 2000 * kMs);
}

TEST(Trial, AbortLeavesTheTrialUndecided) {
    for (bool paused : {false, true}) {
        TrialStateMachine m(hybrid_is_label1(), true);
        ok(m.start(0));
        m.frame_presented(1, 10 * kMs);
        if (paused) ok(m.pause(510 * kMs));
        std::vector<TrialEvent> e = ok(m.abort(1010 * kMs));
        ASSERT_EQ(e.size(), 1u);
        expect_event(e[0], EventKind::Aborted, 0, 1010 * kMs, -1);
        EXPECT_EQ(m.state(), TrialState::Aborted);
        EXPECT_EQ(m.outcome().choice, 0);
        EXPECT_FALSE(m.outcome().valid);
        EXPECT_EQ(m.outcome().time_on_label_ns[0], (paused ? 500 : 1000) * kMs);
        EXPECT_TRUE(m.frame_presented(200, 2000 * kMs).empty());
        EXPECT_FALSE(m.request_switch(2000 * kMs).ok());
        EXPECT_FALSE(m.request_confirm(2000 * kMs).ok());
        EXPECT_FALSE(m.resume(2000 * kMs).ok());
        EXPECT_FALSE(m.abort(2000 * kMs).ok());
        EXPECT_FALSE(m.start(2000 * kMs).ok());
    }
    TrialStateMachine before_start(hybrid_is_label1(), true);
    EXPECT_TRUE(before_start.abort(0).ok());
}

TEST(Trial, CallsInTheWrongStateAreErrors) {
    TrialStateMachine m(hybrid_is_label1(), true);
    // Not started: only start and abort are allowed; frames change nothing.
    EXPECT_TRUE(m.frame_presented(0, 0).empty());
    for (auto call : {&TrialStateMachine::request_switch, &TrialStateMachine::request_confirm,
                      &TrialStateMachine::pause, &TrialStateMachine::resume}) {
        const Result<std::vector<TrialEvent>> r = (m.*call)(0);
        ASSERT_FALSE(r.ok());
        EXPECT_NE(r.error().message.find("trial 7"), std::string::npos) << r.error().message;
        EXPECT_NE(r.error().message.find("not started"), std::string::npos) << r.error().message;
    }
    EXPECT_EQ(m.state(), TrialState::NotStarted);

    ok(m.start(0));
    EXPECT_FALSE(m.start(1).ok());
    EXPECT_FALSE(m.resume(1).ok());
    // Started, nothing visible yet: neither a switch (label 1 is always shown first) nor a
    // confirmation.
    EXPECT_FALSE(m.request_switch(1).ok());
    EXPECT_FALSE(m.request_confirm(1).ok());
    EXPECT_EQ(m.label_to_draw(), 1);

    m.frame_presented(1, 10 * kMs);
    ok(m.request_switch(20 * kMs));
    m.frame_presented(3, 30 * kMs);
    ok(m.request_confirm(40 * kMs));
    for (auto call : {&TrialStateMachine::start, &TrialStateMachine::request_switch,
                      &TrialStateMachine::request_confirm, &TrialStateMachine::pause,
                      &TrialStateMachine::resume, &TrialStateMachine::abort}) {
        const Result<std::vector<TrialEvent>> r = (m.*call)(50 * kMs);
        ASSERT_FALSE(r.ok());
        EXPECT_NE(r.error().message.find("decided"), std::string::npos) << r.error().message;
    }
    EXPECT_EQ(m.outcome().choice, 2);
    EXPECT_EQ(m.state(), TrialState::Decided);
}

// --- A trial across runs (study/trial_runs.h) -------------------------------------------------

TrialEvent logged(EventKind kind, int label, std::int64_t time_ns, std::int64_t frame = -1) {
    TrialEvent e;
    e.kind = kind;
    e.trial_index = is_trial_event(kind) ? 7 : -1;
    e.label = label;
    e.time_ns = time_ns;
    e.frame = frame;
    return e;
}

FrameRecord frame_of_trial(std::int64_t frame, std::int64_t time_ns) {
    FrameRecord f;
    f.frame = frame;
    f.trial_index = 7;
    f.shown = "label1";
    f.display_time_ns = time_ns;
    return f;
}

// Replayed from its events, a trial decided in one run gives the outcome the machine recorded:
// the same rules in both places.
TEST(TrialRuns, ReplayingOneRunGivesTheMachinesOutcome) {
    TrialStateMachine m(hybrid_is_label1(), true);
    std::vector<TrialEvent> events;
    const auto keep = [&](const std::vector<TrialEvent>& e) {
        events.insert(events.end(), e.begin(), e.end());
    };
    keep(ok(m.start(0)));
    keep(m.frame_presented(1, 10 * kMs));
    keep(ok(m.request_switch(40 * kMs)));
    keep(m.frame_presented(5, 50 * kMs));
    keep(ok(m.pause(70 * kMs)));
    keep(ok(m.resume(170 * kMs)));
    keep(ok(m.request_switch(200 * kMs)));
    keep(m.frame_presented(21, 210 * kMs));
    keep(ok(m.request_confirm(260 * kMs)));
    const std::map<int, TrialRuns> runs = trial_runs(events);
    ASSERT_EQ(runs.size(), 1u);
    const TrialRuns& r = runs.at(7);
    const TrialOutcome& o = m.outcome();
    EXPECT_EQ(r.runs, 1);
    EXPECT_EQ(o.runs, 1);
    EXPECT_EQ(r.switches, o.switches);
    EXPECT_EQ(r.time_on_label_ns[0], o.time_on_label_ns[0]);
    EXPECT_EQ(r.time_on_label_ns[1], o.time_on_label_ns[1]);
    EXPECT_EQ(r.viewing_ns, o.decision_time_ns);
    EXPECT_EQ(o.decision_time_ns, 150 * kMs);  // 10 to 260 ms, less the 100 ms pause
}

// An interrupted run's record of the trial ends at its last event or logged frame before the
// next run started (a frame of a later run does not count); a run paused at the interruption
// ends at the pause; an aborted one at the abort.
TEST(TrialRuns, ARunCutShortEndsWithItsLastRecord) {
    const std::vector<TrialEvent> events = {
        logged(EventKind::RunStarted, 0, 0),
        logged(EventKind::Shown, 1, 100 * kMs, 10),
        logged(EventKind::Switched, 2, 300 * kMs, 30),
        logged(EventKind::Switched, 1, 500 * kMs, 50),
        logged(EventKind::RunStarted, 0, 2000 * kMs),
        logged(EventKind::Shown, 1, 2100 * kMs, 200),
        logged(EventKind::Paused, 0, 2200 * kMs),
        logged(EventKind::RunStarted, 0, 2500 * kMs),
        logged(EventKind::Shown, 1, 2600 * kMs, 300),
        logged(EventKind::Switched, 2, 2650 * kMs, 305),
        logged(EventKind::Aborted, 0, 2700 * kMs),
    };
    // Headless (no frame log): run 1 ends at its last switch, 500 ms.
    TrialRuns r = trial_runs(events).at(7);
    EXPECT_EQ(r.runs, 3);
    EXPECT_EQ(r.switches, 3);
    EXPECT_EQ(r.time_on_label_ns[0], (200 + 100 + 50) * kMs);
    EXPECT_EQ(r.time_on_label_ns[1], (200 + 50) * kMs);
    EXPECT_EQ(r.viewing_ns, (400 + 100 + 100) * kMs);
    // With a frame log: run 1's frames of the trial reach 900 ms; the frame at 2300 ms belongs
    // to run 2 (after its start) and the paused run 2 ends at its pause anyway.
    const std::vector<FrameRecord> frames = {frame_of_trial(60, 600 * kMs),
                                             frame_of_trial(90, 900 * kMs),
                                             frame_of_trial(220, 2300 * kMs)};
    r = trial_runs(events, frames).at(7);
    EXPECT_EQ(r.time_on_label_ns[0], (200 + 400 + 100 + 50) * kMs);
    EXPECT_EQ(r.viewing_ns, (800 + 100 + 100) * kMs);
    EXPECT_EQ(r.time_on_label_ns[0] + r.time_on_label_ns[1], r.viewing_ns);
}

// Files from before runs were recorded have no run_started: the trial's second `shown` (logged
// once per run) starts its next run.
TEST(TrialRuns, WithoutRunStartedASecondShownIsTheNextRun) {
    const std::vector<TrialEvent> events = {
        logged(EventKind::Shown, 1, 100 * kMs, 10),
        logged(EventKind::Switched, 2, 200 * kMs, 20),
        logged(EventKind::Shown, 1, 5000 * kMs, 500),
        logged(EventKind::Confirmed, 1, 5100 * kMs),
    };
    const TrialRuns r = trial_runs(events).at(7);
    EXPECT_EQ(r.runs, 2);
    EXPECT_EQ(r.switches, 1);
    EXPECT_EQ(r.time_on_label_ns[0], 200 * kMs);
    EXPECT_EQ(r.time_on_label_ns[1], 0);
    EXPECT_EQ(r.viewing_ns, 200 * kMs);
    EXPECT_TRUE(trial_runs({logged(EventKind::Paused, 0, 5)}).empty());  // never shown
}

// What earlier runs showed counts into the outcome of the run that decides; whether both labels
// were seen is that run's own.
TEST(TrialRuns, EarlierRunsCountIntoTheDecidingRunsOutcome) {
    TrialRuns earlier;
    earlier.runs = 2;
    earlier.switches = 6;
    earlier.time_on_label_ns[0] = 3000 * kMs;
    earlier.time_on_label_ns[1] = 2000 * kMs;
    earlier.viewing_ns = 5000 * kMs;
    TrialStateMachine m(hybrid_is_label1(), true, earlier);
    EXPECT_EQ(m.outcome().switches, 6);
    ok(m.start(0));
    m.frame_presented(1, 10 * kMs);
    EXPECT_FALSE(m.request_confirm(20 * kMs).ok());  // label 2 not seen in this run
    ok(m.request_switch(30 * kMs));
    m.frame_presented(4, 40 * kMs);
    ok(m.request_switch(50 * kMs));
    m.frame_presented(6, 60 * kMs);
    ok(m.request_confirm(100 * kMs));
    const TrialOutcome& o = m.outcome();
    EXPECT_EQ(o.runs, 3);
    EXPECT_EQ(o.switches, 8);
    EXPECT_EQ(o.time_on_label_ns[0], (3000 + 30 + 40) * kMs);
    EXPECT_EQ(o.time_on_label_ns[1], (2000 + 20) * kMs);
    EXPECT_EQ(o.decision_time_ns, (5000 + 90) * kMs);
    EXPECT_TRUE(o.valid);
}
}  // namespace
}  // namespace monoplane::study
