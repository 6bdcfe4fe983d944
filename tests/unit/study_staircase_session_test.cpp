// Staircase sessions (issue 21): the session engine chooses each adaptive trial's m as it starts
// and stores it first; a session killed at any point and resumed continues every staircase
// exactly where it was (its state replayed from the stored decisions), so it ends with the same
// mono planes and decisions as an uninterrupted run; the database and memory runs agree; the
// store keeps the slots as plans and refuses what does not fit them; a version-4 database
// migrates.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "study/export.h"
#include "study/live_session.h"
#include "study/observer.h"
#include "study/observer_input.h"
#include "study/protocol.h"
#include "study/schedule.h"
#include "study/session_runner.h"
#include "study/staircase_estimates.h"
#include "study/store_schema.h"
#include "study/study_store.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

// QUEST+ that stops a scene once the posterior SD of log10 T is 0.3 or less (after 3 trials),
// so slots are skipped too; 8 slots per scene.
constexpr std::string_view kQuest = R"(name = "quest"
scenes = ["beams", "spheres"]
mono_planes = [1.6, 3, 5, 8, 12, 20, 39.5]
alternatives = ["stereo", "hybrid"]
practice_trials = 1
procedure = "staircase"
[staircase]
rule = "quest+"
trials_per_scene = 8
min_trials_per_scene = 3
stop_sd_log10 = 0.3
threshold_steps = 12
slopes = [2, 4]
lapses = [0, 0.04]
)";

// The up-down rule: m anywhere between the ends, stored and replayed as exact doubles.
constexpr std::string_view kUpDown = R"(name = "updown"
scenes = ["beams", "spheres"]
mono_planes = [1.6, 39.5]
alternatives = ["hybrid", "stereo"]
practice_trials = 0
procedure = "staircase"
[staircase]
rule = "weighted-up-down"
trials_per_scene = 10
step_log10 = 0.15
start_m = 10
[questionnaire]
items = ["I noticed differences"]
)";

constexpr std::string_view kObserver = "psychometric:threshold=6,slope=3,lapse=0.02";
constexpr std::uint64_t kSeed = 4242;

// In memory where the system has a tmpfs: the kills here are simulated in the process, so what
// is tested is the replay, not the disk, and a tmpfs spares the hundreds of fsyncs of the
// store's durable writes (seconds on a busy disk).
fs::path temporary_root() {
    std::error_code error;
    if (fs::is_directory("/dev/shm", error) && ::access("/dev/shm", W_OK) == 0) return "/dev/shm";
    return ::testing::TempDir();
}

struct TempDir {
    fs::path path;
    TempDir() {
        std::string pattern = (temporary_root() / "staircase_XXXXXX").string();
        EXPECT_NE(::mkdtemp(pattern.data()), nullptr);
        path = pattern;
    }
    ~TempDir() { fs::remove_all(path); }
};

SessionInfo session_info(const Protocol& protocol) {
    SessionInfo info;
    info.participant_code = "S1";
    info.protocol_name = protocol.name;
    info.protocol_text = protocol.text;
    info.protocol_hash = protocol.text_hash;
    info.hmd = "vive";
    info.runtime = "none";
    info.device = "none";
    info.observer = std::string(kObserver);
    return info;
}

// The decisions as the export sees them: trial index, m, choice.
struct Decision {
    int index;
    double m;
    int choice;
    bool operator==(const Decision&) const = default;
};

std::vector<Decision> decisions(const StudyStore& store, std::int64_t id) {
    std::vector<Decision> out;
    for (const TrialRecord& r : store.trials(id).value_or_throw()) {
        out.push_back({r.trial.index, r.trial.mono_plane, r.decided ? r.outcome.choice : 0});
    }
    return out;
}

struct Killed {};

// The virtual display of session_runner.cpp, with a kill: `kill_after` sees every committed
// line and throws Killed after the write that should be the last, as a SIGKILL right after it.
void drive(StudyStore& store, std::int64_t id, const Protocol& protocol,
           const std::function<bool(const std::string&)>& kill_after) {
    LiveOptions options;
    options.neutral_ns = 100'000'000;
    options.on_committed = [&kill_after](const std::string& line) {
        if (kill_after(line)) throw Killed{};
    };
    auto session = LiveSession::open(store, id, protocol, options).value_or_throw();
    auto observer = make_observer(kObserver, kSeed).value_or_throw();
    ObserverInput input(*observer, protocol, [](const ScheduledTrial&) { return 0.0; });
    const std::int64_t period = 11'111'111;
    for (std::int64_t frame = 1; !session->finished(); ++frame) {
        ASSERT_LT(frame, 10'000'000) << "the session does not end";
        const std::int64_t now = frame * period;
        for (LiveInput request : input.poll(session->screen(), session->progress(), now)) {
            const Result<std::string> done = session->request(request, now);
            ASSERT_TRUE(done.ok()) << done.error().message;
        }
        const Result<void> shown = session->frame_presented(frame, now);
        ASSERT_TRUE(shown.ok()) << shown.error().message;
    }
}

std::int64_t begin(StudyStore& store, const Protocol& protocol) {
    return store.begin_session(session_info(protocol), make_schedule(protocol, kSeed, 0))
        .value_or_throw();
}

// Kills the session after the next write of the kind wanted, cycling through the points where a
// staircase's state matters: the m just chosen (not shown yet), the trial shown, its decision.
void expect_resumed_runs_match_an_uninterrupted_one(std::string_view text) {
    const Protocol protocol = parse_protocol(text, "s.toml").value_or_throw();
    TempDir dir;
    auto whole = StudyStore::open(dir.path / "whole.sqlite").value_or_throw();
    const std::int64_t whole_id = begin(*whole, protocol);
    drive(*whole, whole_id, protocol, [](const std::string&) { return false; });
    const std::vector<Decision> expected = decisions(*whole, whole_id);

    const fs::path file = dir.path / "killed.sqlite";
    std::int64_t id = begin(*StudyStore::open(file).value_or_throw(), protocol);
    const std::vector<std::string> kill_points = {" stimulus m ", " shown ", " outcome "};
    int kills = 0;
    for (bool finished = false; !finished; ++kills) {
        ASSERT_LT(kills, 200);
        auto store = StudyStore::open(file).value_or_throw();  // a new process
        const std::string& wanted = kill_points[static_cast<std::size_t>(kills) % 3];
        try {
            drive(*store, id, protocol, [&wanted](const std::string& line) {
                return line.find(wanted) != std::string::npos;
            });
            finished = true;
        } catch (const Killed&) {
        }
    }
    auto store = StudyStore::open(file).value_or_throw();
    EXPECT_EQ(store->session(id)->status, SessionStatus::Completed);
    EXPECT_EQ(decisions(*store, id), expected);
    // Every staircase was killed at each point at least once.
    EXPECT_GE(kills, static_cast<int>(expected.size()));
}

TEST(StaircaseSession, QuestPlusKilledAtEveryTrialResumesAsIfUninterrupted) {
    expect_resumed_runs_match_an_uninterrupted_one(kQuest);
}

TEST(StaircaseSession, UpDownKilledAtEveryTrialResumesAsIfUninterrupted) {
    expect_resumed_runs_match_an_uninterrupted_one(kUpDown);
}

TEST(StaircaseSession, ChoosesEachTrialsMonoPlaneFromTheAnswersBefore) {
    const Protocol protocol = parse_protocol(kQuest, "s.toml").value_or_throw();
    TempDir dir;
    auto store = StudyStore::open(dir.path / "s.sqlite").value_or_throw();
    const std::int64_t id = begin(*store, protocol);
    // Before the first trial: the practice trial and the slots, none with an m yet.
    const int per_scene_slots = protocol.staircase.trials_per_scene;
    const std::size_t slots = 2 * static_cast<std::size_t>(per_scene_slots);
    const Schedule stored = store->load_schedule(id).value_or_throw();
    ASSERT_EQ(stored.trials.size(), 1 + slots);
    EXPECT_EQ(store->trials(id)->size(), 1u);
    for (std::size_t i = 1; i <= slots; ++i) {
        EXPECT_TRUE(stored.trials[i].adaptive && std::isnan(stored.trials[i].mono_plane)) << i;
    }
    EXPECT_EQ(store->session(id)->procedure, Procedure::Staircase);
    EXPECT_EQ(*store->first_undecided_trial(id), 0);
    drive(*store, id, protocol, [](const std::string&) { return false; });

    // Replaying the decisions through fresh staircases gives every trial's m.
    Staircases replay(protocol);
    int shown = 0;
    std::map<std::string, int> per_scene;
    for (const TrialRecord& r : store->trials(id).value_or_throw()) {
        ASSERT_TRUE(r.decided);
        if (!r.trial.adaptive) continue;
        EXPECT_FALSE(replay.finished(r.trial.scene)) << r.trial.index;
        EXPECT_EQ(r.trial.mono_plane, replay.next_mono_plane(r.trial.scene)) << r.trial.index;
        replay.record(r.trial, r.outcome);
        ++shown;
        ++per_scene[r.trial.scene];
    }
    // Each staircase stopped: by the width rule (not before 3 trials) or after its slots; at
    // least one by the width rule, so slots were skipped.
    for (const auto& [scene, n] : per_scene) {
        EXPECT_TRUE(replay.finished(scene)) << scene;
        EXPECT_GE(n, 3) << scene;
        if (n < per_scene_slots) {
            EXPECT_LE(*replay.estimate(scene).sd_log10, 0.3) << scene;
        }
    }
    EXPECT_LT(shown, static_cast<int>(slots));
    EXPECT_EQ(store->load_schedule(id)->trials.size(), 1 + slots);  // skipped slots stay plans

    // The same engine into memory decides alike.
    MemorySessionLog memory;
    auto observer = make_observer(kObserver, kSeed).value_or_throw();
    RunOptions options;
    options.neutral_ns = 100'000'000;
    ASSERT_TRUE(run_simulated_session(memory, protocol, make_schedule(protocol, kSeed, 0),
                                      *observer, options)
                    .ok());
    ASSERT_EQ(memory.adaptive_trials().size(), static_cast<std::size_t>(shown));
    for (const TrialRecord& r : store->trials(id).value_or_throw()) {
        if (!r.trial.adaptive) continue;
        EXPECT_EQ(memory.adaptive_trials().at(r.trial.index).mono_plane, r.trial.mono_plane);
        EXPECT_EQ(memory.outcomes().at(r.trial.index).choice, r.outcome.choice);
    }
}

// The export's staircase columns and the end-of-session summary replay the stored decisions: after
// each adaptive trial, its scene's estimate equals that of staircases fed the same decisions here;
// practice trials have none; the final estimate per scene is the last trial's.
TEST(StaircaseSession, ExportedEstimatesAreTheStaircasesAfterEachDecision) {
    const Protocol protocol = parse_protocol(kQuest, "s.toml").value_or_throw();
    TempDir dir;
    auto store = StudyStore::open(dir.path / "s.sqlite").value_or_throw();
    const std::int64_t id = begin(*store, protocol);
    drive(*store, id, protocol, [](const std::string&) { return false; });
    const SessionInfo info = store->session(id).value_or_throw();
    const std::vector<TrialRecord> trials = store->trials(id).value_or_throw();
    const auto estimates = replay_staircase_estimates(info, trials).value_or_throw();
    const auto finals = final_staircase_estimates(info, trials).value_or_throw();
    const ExportData exported = collect_export(*store).value_or_throw();
    const auto& exported_estimates = exported.staircase_estimates.at(id);

    Staircases replay(protocol);
    std::map<std::string, ThresholdEstimate> last;
    for (const TrialRecord& r : trials) {
        if (!r.trial.adaptive) {
            EXPECT_FALSE(estimates.contains(r.trial.index)) << r.trial.index;
            continue;
        }
        replay.record(r.trial, r.outcome);
        const ThresholdEstimate expected = replay.estimate(r.trial.scene);
        last[r.trial.scene] = expected;
        ASSERT_TRUE(estimates.contains(r.trial.index)) << r.trial.index;
        EXPECT_EQ(estimates.at(r.trial.index).threshold_m, expected.threshold_m);
        EXPECT_EQ(estimates.at(r.trial.index).lower_m, expected.lower_m);
        EXPECT_EQ(estimates.at(r.trial.index).upper_m, expected.upper_m);
        EXPECT_EQ(exported_estimates.at(r.trial.index).threshold_m, expected.threshold_m);
    }
    ASSERT_EQ(finals.size(), 2u);
    for (const auto& [scene, estimate] : last) {
        EXPECT_EQ(finals.at(scene).threshold_m, estimate.threshold_m) << scene;
        EXPECT_EQ(finals.at(scene).trials, estimate.trials) << scene;
        ASSERT_TRUE(estimate.lower_m && estimate.upper_m) << scene;
        EXPECT_LT(*estimate.lower_m, estimate.threshold_m) << scene;
        EXPECT_GT(*estimate.upper_m, estimate.threshold_m) << scene;
    }

    // A stored protocol text that is no longer a staircase's is named.
    SessionInfo changed = info;
    changed.protocol_text =
        "name = \"x\"\nscenes = [\"beams\"]\nmono_planes = [3]\n"
        "alternatives = [\"stereo\", \"hybrid\"]\n";
    const auto refused = replay_staircase_estimates(changed, trials);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("not a staircase protocol"), std::string::npos)
        << refused.error().message;
}

TEST(StaircaseSession, StoreRefusesAStimulusThatDoesNotFitThePlan) {
    const Protocol protocol = parse_protocol(kQuest, "s.toml").value_or_throw();
    TempDir dir;
    auto store = StudyStore::open(dir.path / "s.sqlite").value_or_throw();
    const std::int64_t id = begin(*store, protocol);
    ScheduledTrial slot = store->load_schedule(id)->trials[3];
    const auto refused = [&](const ScheduledTrial& t, std::string_view why) {
        const Result<void> r = store->record_stimulus(id, t);
        ASSERT_FALSE(r.ok()) << why;
        EXPECT_NE(r.error().message.find(why), std::string::npos) << r.error().message;
    };
    refused(slot, "not a positive distance");  // m not chosen (NaN)
    slot.mono_plane = -2.0;
    refused(slot, "not a positive distance");
    refused(store->load_schedule(id)->trials[0], "not a staircase's trial");  // practice
    slot.mono_plane = 8.0;
    ASSERT_TRUE(store->record_stimulus(id, slot).ok());
    slot.mono_plane = 12.0;
    refused(slot, "has its mono plane already");
    ScheduledTrial unplanned = slot;
    unplanned.index = 99;
    refused(unplanned, "is not a staircase's planned trial");
    // The started slot is a trial with its m; the others still plans.
    EXPECT_EQ(store->trials(id)->size(), 2u);
    EXPECT_EQ(store->load_schedule(id)->trials[3].mono_plane, 8.0);
    EXPECT_TRUE(std::isnan(store->load_schedule(id)->trials[4].mono_plane));
}

// A version-4 database (made here from the first four migrations, with a session as that
// release wrote it) migrates: its session is a constant one and resumes as before.
TEST(StaircaseSession, AVersion4DatabaseMigrates) {
    TempDir dir;
    const fs::path file = dir.path / "v4.sqlite";
    {
        sqlite3* raw = nullptr;
        ASSERT_EQ(sqlite3_open(file.c_str(), &raw), SQLITE_OK);
        std::string sql;
        for (int v = 0; v < 4; ++v)
            sql += std::string(store_migrations()[static_cast<std::size_t>(v)]);
        sql += "PRAGMA application_id = " + std::to_string(kStoreApplicationId) + ";";
        sql += "PRAGMA user_version = 4;";
        sql += R"sql(
INSERT INTO participants VALUES (1, 'P01', 0, '2027-01-01T10:00:00Z');
INSERT INTO sessions (id, participant_id, protocol_name, protocol_hash, protocol_text, seed,
    block_order, software_version, hmd, runtime, device, observer, started_utc, status)
    VALUES (1, 1, 'demo', '0000000000000002', 'name = "demo"', '12', 'beams',
            'monoplane 0.1.0', 'vive', 'none', 'none', 'default', '2027-01-01T10:00:01Z',
            'running');
INSERT INTO trials (session_id, trial_index, practice, block, scene, mono_plane,
    label1_alternative, label1_mode, label2_mode, decided, choice, chosen_mode, valid,
    switches, time_label1_ns, time_label2_ns, decision_time_ns)
    VALUES (1, 0, 0, 0, 'beams', 8.0, 0, 'stereo', 'hybrid', 1, 2, 'hybrid', 1, 1, 5, 6, 11),
           (1, 1, 0, 0, 'beams', 3.0, 1, 'hybrid', 'stereo', 0, NULL, NULL, NULL, NULL, NULL,
            NULL, NULL);
)sql";
        char* error = nullptr;
        ASSERT_EQ(sqlite3_exec(raw, sql.c_str(), nullptr, nullptr, &error), SQLITE_OK) << error;
        sqlite3_close(raw);
    }
    auto store = StudyStore::open(file).value_or_throw();
    const SessionInfo info = store->session(1).value_or_throw();
    EXPECT_EQ(info.procedure, Procedure::Constant);
    const Schedule schedule = store->load_schedule(1).value_or_throw();
    ASSERT_EQ(schedule.trials.size(), 2u);
    EXPECT_EQ(schedule.trials[1].mono_plane, 3.0);
    EXPECT_FALSE(schedule.trials[0].adaptive || schedule.trials[1].adaptive);
    EXPECT_EQ(*store->first_undecided_trial(1), 1);
    EXPECT_EQ(decisions(*store, 1), (std::vector<Decision>{{0, 8.0, 2}, {1, 3.0, 0}}));
}

}  // namespace
}  // namespace monoplane::study
