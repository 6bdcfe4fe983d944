// One session engine (issue 17 item 1): `study run --headset none` (run_session, into the
// database) and `simulate` (run_simulated_session, into memory) decide every trial alike, because
// both are LiveSession with the observer at its controls; the in-memory log refuses what the
// database refuses.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "study/observer.h"
#include "study/protocol.h"
#include "study/schedule.h"
#include "study/session_log.h"
#include "study/session_runner.h"
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

TEST(SessionEngine, TheMemoryLogRefusesASecondDecision) {
    MemorySessionLog log;
    TrialOutcome outcome;
    outcome.choice = 1;
    ASSERT_TRUE(log.record_outcome(1, 3, outcome).ok());
    const Result<bool> again = log.record_outcome(1, 3, outcome);
    ASSERT_FALSE(again.ok());
    EXPECT_NE(again.error().message.find("never overwritten"), std::string::npos);
}

}  // namespace
}  // namespace monoplane::study
