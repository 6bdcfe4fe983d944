// One session engine (issue 17 item 1): `study run --headset none` (run_session, into the
// database) and `simulate` (run_simulated_session, into memory) decide every trial alike, because
// both are LiveSession with the observer at its controls; the in-memory log refuses what the
// database refuses.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "study/observer.h"
#include "study/observer_input.h"
#include "study/protocol.h"
#include "study/schedule.h"
#include "study/session_log.h"
#include "study/session_runner.h"
#include "study/session_screens.h"
#include "study/study_store.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kProtocol = R"(name = "engine"
scenes = ["beams", "spheres"]
mono_planes = [1.6, 8, 31]
alternatives = ["stereo", "hybrid"]
practice_trials = 1
[questionnaire]
items = ["I noticed differences"]
)";

TEST(SessionEngine, DatabaseAndMemoryRunsDecideEveryTrialAlike) {
    const Protocol protocol = parse_protocol(kProtocol, "engine.toml").value_or_throw();
    constexpr std::uint64_t kSeed = 77;
    const Schedule schedule = make_schedule(protocol, kSeed, 0);
    RunOptions options;
    // A stimulus that grows with m, so the default observer's choices vary over the trials.
    options.trial_error_px = [](const ScheduledTrial& t) { return 40.0 / t.mono_plane; };

    std::string pattern = (fs::path(::testing::TempDir()) / "engine_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    auto store = StudyStore::open(fs::path(pattern) / "engine.sqlite").value_or_throw();
    SessionInfo info;
    info.participant_code = "E1";
    info.protocol_name = protocol.name;
    info.protocol_text = protocol.text;
    info.protocol_hash = protocol.text_hash;
    info.hmd = "vive";
    info.runtime = "none";
    info.device = "none";
    info.observer = "default";
    const std::int64_t id = store->begin_session(info, schedule).value_or_throw();
    auto stored_observer = make_observer("default", kSeed).value_or_throw();
    ASSERT_EQ(*run_session(*store, id, protocol, *stored_observer, options),
              SessionStatus::Completed);

    MemorySessionLog memory;
    auto memory_observer = make_observer("default", kSeed).value_or_throw();
    ASSERT_TRUE(run_simulated_session(memory, protocol, schedule, *memory_observer, options).ok());
    EXPECT_EQ(memory.status(), SessionStatus::Completed);

    const std::vector<TrialRecord> stored = store->trials(id).value_or_throw();
    ASSERT_EQ(stored.size(), schedule.trials.size());
    ASSERT_EQ(memory.outcomes().size(), schedule.trials.size());
    int chose_label2 = 0;
    for (const TrialRecord& record : stored) {
        ASSERT_TRUE(record.decided) << record.trial.index;
        const TrialOutcome& m = memory.outcomes().at(record.trial.index);
        EXPECT_EQ(m.choice, record.outcome.choice) << record.trial.index;
        EXPECT_EQ(m.chosen_mode, record.outcome.chosen_mode) << record.trial.index;
        EXPECT_EQ(m.valid, record.outcome.valid) << record.trial.index;
        EXPECT_EQ(m.switches, record.outcome.switches) << record.trial.index;
        chose_label2 += m.choice == 2;
    }
    // Not a degenerate observer: both labels are chosen somewhere.
    EXPECT_GT(chose_label2, 0);
    EXPECT_LT(chose_label2, static_cast<int>(stored.size()));
    EXPECT_EQ(memory.events().size(), store->events(id).value_or_throw().size());
    EXPECT_EQ(memory.answers().size(), 1u);
    fs::remove_all(pattern);
}

// FNV-1a over the lines, each ended by a newline: a compact fingerprint of a whole session.
std::uint64_t fingerprint(const std::vector<std::string>& lines) {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::string& line : lines) {
        for (unsigned char c : line + "\n") h = (h ^ c) * 1099511628211ull;
    }
    return h;
}

// A protocol without screens runs exactly as before they existed: every committed line of a
// seeded simulated session (events with their times and frames, outcomes, answers, the status)
// is what the engine wrote before (fingerprint and count recorded from that engine). The run's
// start, a line since runs are recorded, comes first and is left out.
TEST(SessionEngine, AProtocolWithoutScreensRunsAsBefore) {
    const Protocol protocol = parse_protocol(kProtocol, "engine.toml").value_or_throw();
    ASSERT_FALSE(protocol.day.has_screens());
    std::vector<std::string> lines;
    RunOptions options;
    options.trial_error_px = [](const ScheduledTrial& t) { return 40.0 / t.mono_plane; };
    options.on_committed = [&lines](const std::string& line) { lines.push_back(line); };
    MemorySessionLog memory;
    auto observer = make_observer("default", 77).value_or_throw();
    ASSERT_TRUE(
        run_simulated_session(memory, protocol, make_schedule(protocol, 77, 0), *observer, options)
            .ok());
    ASSERT_FALSE(lines.empty());
    EXPECT_EQ(lines.front(), "run 1 started t 0 frame 0");
    lines.erase(lines.begin());
    ASSERT_EQ(lines.size(), 69u);
    EXPECT_EQ(fingerprint(lines), 8958072370625582265ull);
    EXPECT_EQ(lines.front(), "trial 0 shown label 1 t 1033333323 frame 93");
    EXPECT_EQ(lines.back(), "session completed");
}

// The engine's protocol with every screen: two instruction pages, the ready screen, breaks every
// two data trials and between the scene blocks (5 s), and the end screen.
Protocol day_protocol() {
    Protocol protocol = parse_protocol(kProtocol, "engine.toml").value_or_throw();
    protocol.day.instructions = {
        {"You will see two versions of each scene."},
        {"Press SWITCH to see the other version, CONFIRM to choose the one shown."}};
    protocol.day.ready = ScreenPage{"Practice is over. Press CONFIRM to begin."};
    BreakSettings breaks;
    breaks.every_trials = 2;
    breaks.between_blocks = true;
    breaks.min_s = 5.0;
    protocol.day.breaks = breaks;
    protocol.day.end = ScreenPage{"Thank you."};
    return protocol;
}

// The session as a list of steps: each screen event ("ready_shown", "instructions_shown 1"),
// and each trial once ("trial 3"); a run's start is none.
std::vector<std::string> steps(const std::vector<TrialEvent>& events) {
    std::vector<std::string> out;
    int trial = -1;
    for (const TrialEvent& e : events) {
        if (is_session_event(e.kind)) continue;
        if (is_screen_event(e.kind)) {
            out.push_back(std::string(event_kind_name(e.kind)) +
                          (e.page >= 0 ? " " + std::to_string(e.page) : ""));
            trial = -1;
        } else if (e.trial_index != trial) {
            trial = e.trial_index;
            out.push_back("trial " + std::to_string(trial));
        }
    }
    return out;
}

std::int64_t time_of(const std::vector<TrialEvent>& events, std::size_t from, EventKind kind) {
    for (std::size_t i = from; i < events.size(); ++i) {
        if (events[i].kind == kind) return events[i].time_ns;
    }
    ADD_FAILURE() << "no " << event_kind_name(kind) << " after event " << from;
    return 0;
}

std::unique_ptr<StudyStore> open_store(const std::string& name, std::string& dir) {
    dir = (fs::path(::testing::TempDir()) / (name + "_XXXXXX")).string();
    EXPECT_NE(::mkdtemp(dir.data()), nullptr);
    return StudyStore::open(fs::path(dir) / "engine.sqlite").value_or_throw();
}

std::int64_t begin_stored(StudyStore& store, const Protocol& protocol, const Schedule& schedule) {
    SessionInfo info;
    info.participant_code = "D1";
    info.protocol_name = protocol.name;
    info.protocol_text = protocol.text;
    info.protocol_hash = protocol.text_hash;
    info.hmd = "vive";
    info.runtime = "none";
    info.device = "none";
    info.observer = "default";
    return store.begin_session(info, schedule).value_or_throw();
}

// Headless, the observer steps through every screen on the virtual clock: it reads each page
// for ObserverInput::reading_ns, waits out each break's countdown, confirms the ready screen;
// the end screen completes the session. The database and memory runs log the same events.
TEST(SessionEngine, HeadlessSessionsStepThroughTheScreens) {
    const Protocol protocol = day_protocol();
    constexpr std::uint64_t kSeed = 77;
    const Schedule schedule = make_schedule(protocol, kSeed, 0);
    ASSERT_EQ(planned_breaks(protocol.day, schedule), (std::vector<int>{3, 4, 5}));
    RunOptions options;
    options.trial_error_px = [](const ScheduledTrial& t) { return 40.0 / t.mono_plane; };

    MemorySessionLog memory;
    auto observer = make_observer("default", kSeed).value_or_throw();
    ASSERT_TRUE(run_simulated_session(memory, protocol, schedule, *observer, options).ok());
    EXPECT_EQ(memory.status(), SessionStatus::Completed);
    EXPECT_EQ(memory.outcomes().size(), 7u);
    EXPECT_EQ(memory.answers().size(), 1u);
    const std::vector<TrialEvent>& e = memory.events();
    const std::vector<std::string> expected = {"instructions_shown 0",
                                               "instructions_confirmed 0",
                                               "instructions_shown 1",
                                               "instructions_confirmed 1",
                                               "trial 0",
                                               "ready_shown",
                                               "ready_confirmed",
                                               "trial 1",
                                               "trial 2",
                                               "break_started",
                                               "break_ended",
                                               "trial 3",
                                               "break_started",
                                               "break_ended",
                                               "trial 4",
                                               "break_started",
                                               "break_ended",
                                               "trial 5",
                                               "trial 6",
                                               "end_shown"};
    EXPECT_EQ(steps(e), expected);

    const std::int64_t period =
        static_cast<std::int64_t>(std::llround(1e9 / options.frame_rate_hz));
    for (std::size_t i = 0; i < e.size(); ++i) {
        if (e[i].frame >= 0) {
            EXPECT_EQ(e[i].time_ns, e[i].frame * period) << i;
        }
        if (e[i].kind == EventKind::InstructionsShown) {
            const std::int64_t least =
                ObserverInput::reading_ns(protocol.day.instructions[e[i].page].text);
            EXPECT_GE(time_of(e, i, EventKind::InstructionsConfirmed) - e[i].time_ns, least);
            EXPECT_LE(time_of(e, i, EventKind::InstructionsConfirmed) - e[i].time_ns,
                      least + 2 * period);
        }
        if (e[i].kind == EventKind::ReadyShown) {
            const std::int64_t least = ObserverInput::reading_ns(protocol.day.ready->text);
            EXPECT_GE(time_of(e, i, EventKind::ReadyConfirmed) - e[i].time_ns, least);
            EXPECT_LE(time_of(e, i, EventKind::ReadyConfirmed) - e[i].time_ns, least + 2 * period);
        }
        if (e[i].kind == EventKind::BreakStarted) {
            EXPECT_GE(time_of(e, i, EventKind::BreakEnded) - e[i].time_ns, 5'000'000'000);
            EXPECT_LE(time_of(e, i, EventKind::BreakEnded) - e[i].time_ns,
                      5'000'000'000 + 2 * period);
        }
    }
    // 2 s plus 40 ms a character: the first page's 40 characters take 3.6 s.
    EXPECT_EQ(ObserverInput::reading_ns(protocol.day.instructions[0].text), 3'600'000'000);

    std::string dir;
    auto store = open_store("screens", dir);
    const std::int64_t id = begin_stored(*store, protocol, schedule);
    auto stored_observer = make_observer("default", kSeed).value_or_throw();
    ASSERT_EQ(*run_session(*store, id, protocol, *stored_observer, options),
              SessionStatus::Completed);
    const std::vector<TrialEvent> stored = store->events(id).value_or_throw();
    ASSERT_EQ(stored.size(), e.size());
    for (std::size_t i = 0; i < e.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(stored[i].kind, e[i].kind);
        EXPECT_EQ(stored[i].trial_index, e[i].trial_index);
        EXPECT_EQ(stored[i].label, e[i].label);
        EXPECT_EQ(stored[i].time_ns, e[i].time_ns);
        EXPECT_EQ(stored[i].frame, e[i].frame);
        EXPECT_EQ(stored[i].page, e[i].page);
    }
    store.reset();
    fs::remove_all(dir);
}

struct Killed {};

// Killed as the first break starts (the process dies after the write), the session resumes in
// that break: for all of its 5 s, since nothing was logged after its start, its start logged
// again when the resumed run shows it; the instructions read and the ready screen confirmed are
// not shown again. The resumed run's times go on 1 ns after the last one stored.
TEST(SessionEngine, AHeadlessSessionKilledInABreakResumesInIt) {
    const Protocol protocol = day_protocol();
    const Schedule schedule = make_schedule(protocol, 5, 0);
    std::string dir;
    auto store = open_store("killed", dir);
    const std::int64_t id = begin_stored(*store, protocol, schedule);
    RunOptions options;
    options.on_committed = [](const std::string& line) {
        if (line.starts_with("screen break_started")) throw Killed{};
    };
    {
        auto observer = make_observer("default", 5).value_or_throw();
        EXPECT_THROW((void)run_session(*store, id, protocol, *observer, options), Killed);
    }
    const std::size_t before = store->events(id).value_or_throw().size();
    options.on_committed = nullptr;
    auto observer = make_observer("default", 5).value_or_throw();
    ASSERT_EQ(*run_session(*store, id, protocol, *observer, options), SessionStatus::Completed);
    const std::vector<TrialEvent> e = store->events(id).value_or_throw();
    const std::vector<std::string> expected = {"instructions_shown 0",
                                               "instructions_confirmed 0",
                                               "instructions_shown 1",
                                               "instructions_confirmed 1",
                                               "trial 0",
                                               "ready_shown",
                                               "ready_confirmed",
                                               "trial 1",
                                               "trial 2",
                                               "break_started",
                                               "break_started",
                                               "break_ended",
                                               "trial 3",
                                               "break_started",
                                               "break_ended",
                                               "trial 4",
                                               "break_started",
                                               "break_ended",
                                               "trial 5",
                                               "trial 6",
                                               "end_shown"};
    EXPECT_EQ(steps(e), expected);
    // The resumed run starts 1 ns after the break's start, shows the break again with its first
    // frame (one period later) and ends it at least 5 s after that.
    ASSERT_GT(e.size(), before + 2);
    EXPECT_EQ(e[before - 1].kind, EventKind::BreakStarted);
    EXPECT_EQ(e[before].kind, EventKind::RunStarted);
    EXPECT_EQ(e[before].time_ns, e[before - 1].time_ns + 1);
    EXPECT_EQ(e[before + 1].kind, EventKind::BreakStarted);
    EXPECT_EQ(e[before + 1].time_ns, e[before].time_ns + 11'111'111);
    EXPECT_GT(e[before + 1].frame, e[before - 1].frame);
    EXPECT_EQ(e[before + 2].kind, EventKind::BreakEnded);
    EXPECT_GE(e[before + 2].time_ns - e[before + 1].time_ns, 5'000'000'000);
    EXPECT_LE(e[before + 2].time_ns - e[before + 1].time_ns, 5'000'000'000 + 3 * 11'111'111);
    for (const TrialRecord& r : store->trials(id).value_or_throw()) {
        EXPECT_TRUE(r.decided) << r.trial.index;
    }
    store.reset();
    fs::remove_all(dir);
}

TEST(SessionEngine, TheMemoryLogRefusesASecondDecision) {
    MemorySessionLog log;
    TrialOutcome outcome;
    outcome.choice = 1;
    ASSERT_TRUE(log.record_outcome(1, 3, outcome).ok());
    const Result<void> again = log.record_outcome(1, 3, outcome);
    ASSERT_FALSE(again.ok());
    EXPECT_NE(again.error().message.find("never overwritten"), std::string::npos);
}

}  // namespace
}  // namespace monoplane::study
