// A study day on the command line, as an experimenter meets it (issue 30): a participant's
// sessions with their own schedules and rotated scene order, variables checked before anything is
// written, notes, the roster, resume choosing a session by participant, a live session never
// taken over while a dead one resumes at once, and a database of the previous schema resumed and
// exported. Every run is the real executable (`--headset none`: the simulated observer answers).
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "study/study_store.h"
#include "tests/e2e/child_process.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

// The demo design, with what a study day adds: three sessions, each condition twice, a required
// and an optional variable, one instruction page and a break every four data trials.
constexpr const char* kDayProtocol = R"(name = "day"
scenes = ["beams", "landscape", "spheres"]
mono_planes = [3, 8]
alternatives = ["stereo", "hybrid"]
practice_trials = 1
sessions = 3
repetitions = 2
[[instructions]]
text = "Press SWITCH to compare, CONFIRM to choose."
[breaks]
every_trials = 4
min_s = 2
[[variables]]
name = "age"
type = "integer"
min = 18
max = 99
required = true
help = "Age in years"
[[variables]]
name = "vision"
type = "choice"
choices = ["normal", "corrected"]
)";

class StudyDayCli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("monoplane_day_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        std::ofstream(dir_ / "day.toml") << kDayProtocol;
    }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(dir_);
    }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // `monoplane study ARGS...`; the exit status, and what it printed in *output.
    int study(std::vector<std::string> args, std::string* output = nullptr) {
        args.insert(args.begin(), {MONOPLANE_EXE, "study"});
        return run_to_end(args, output, dir_.string());
    }
    int run(const std::string& db, const std::string& code, std::vector<std::string> extra,
            std::string* output = nullptr) {
        std::vector<std::string> args = {"run",  "--protocol", path("day.toml"),
                                         "--db", db,           "--participant",
                                         code,   "--headset",  "none"};
        args.insert(args.end(), extra.begin(), extra.end());
        return study(args, output);
    }

    static std::unique_ptr<study::StudyStore> open(const std::string& db) {
        auto store = study::StudyStore::open(db);
        EXPECT_TRUE(store.ok()) << store.error().message;
        return std::move(store).value();
    }

    fs::path dir_;
};

TEST_F(StudyDayCli, VariablesAreCheckedBeforeTheDatabaseIsCreated) {
    const std::string db = path("s.sqlite");
    std::string out;
    EXPECT_NE(run(db, "P1", {}, &out), 0);
    EXPECT_NE(out.find("age"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(db));
    EXPECT_NE(run(db, "P1", {"--var", "age=17"}, &out), 0);
    EXPECT_NE(out.find("age"), std::string::npos) << out;
    EXPECT_NE(out.find("18"), std::string::npos) << out;  // the allowed range
    EXPECT_NE(run(db, "P1", {"--var", "age=30", "--var", "vision=blue"}, &out), 0);
    EXPECT_NE(out.find("normal"), std::string::npos) << out;  // the allowed choices
    EXPECT_NE(run(db, "P1", {"--var", "age=30", "--var", "agee=3"}, &out), 0);
    EXPECT_NE(out.find("agee"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(db));
}

TEST_F(StudyDayCli, SessionsOfAParticipantRotateTheSceneOrderAndKeepTheirVariables) {
    const std::string db = path("s.sqlite");
    std::string out;
    ASSERT_EQ(run(db, "P1", {"--var", "age=30", "--participant-number", "2", "--seed", "5"}, &out),
              0)
        << out;
    ASSERT_EQ(run(db, "P1", {"--seed", "6"}, &out), 0) << out;  // session 2: variables kept
    auto store = open(db);
    const auto roster = store->roster().value_or_throw();
    ASSERT_EQ(roster.size(), 2u);
    const auto first = store->find_session("P1", 1).value_or_throw();
    const auto second = store->find_session("P1", 2).value_or_throw();
    ASSERT_TRUE(first && second);
    const study::SessionInfo info1 = store->session(*first).value_or_throw();
    const study::SessionInfo info2 = store->session(*second).value_or_throw();
    EXPECT_EQ(info1.participant_number, 1);  // --participant-number 2 is the second: row 1
    EXPECT_EQ(info2.participant_number, 1);
    EXPECT_EQ(info2.session_number, 2);
    ASSERT_EQ(info1.variables.size(), 1u);
    EXPECT_EQ(info1.variables[0].name, "age");
    EXPECT_EQ(info1.variables[0].value, "30");
    EXPECT_EQ(info2.variables, info1.variables);

    // Williams' row 1 for three scenes is 1 2 0 (landscape, spheres, beams); session 2 starts
    // one place later.
    const study::Schedule s1 = store->load_schedule(*first).value_or_throw();
    const study::Schedule s2 = store->load_schedule(*second).value_or_throw();
    EXPECT_EQ(s1.block_order, (std::vector<std::string>{"landscape", "spheres", "beams"}));
    EXPECT_EQ(s2.block_order, (std::vector<std::string>{"spheres", "beams", "landscape"}));

    // Every scene x distance twice per session, the showings numbered 1 and 2.
    std::map<std::pair<std::string, double>, std::multiset<int>> showings;
    for (const study::TrialRecord& r : store->trials(*first).value_or_throw()) {
        EXPECT_TRUE(r.decided);
        EXPECT_EQ(r.session_number, 1);
        if (!r.trial.practice)
            showings[{r.trial.scene, r.trial.mono_plane}].insert(r.trial.repetition);
    }
    EXPECT_EQ(showings.size(), 6u);
    for (const auto& [condition, reps] : showings) EXPECT_EQ(reps, (std::multiset<int>{1, 2}));
    store.reset();

    // Refusals, each with nothing written.
    EXPECT_NE(run(db, "P1", {"--session", "2"}, &out), 0);
    EXPECT_NE(out.find("study resume"), std::string::npos) << out;
    EXPECT_NE(run(db, "P1", {"--session", "4"}, &out), 0);
    EXPECT_NE(out.find("the next is session 3"), std::string::npos) << out;
    EXPECT_NE(run(db, "P1", {"--var", "age=31"}, &out), 0);
    EXPECT_NE(out.find("30"), std::string::npos) << out;  // the recorded value
    EXPECT_NE(run(db, "P2", {"--var", "age=40", "--participant-number", "2"}, &out), 0);
    EXPECT_NE(out.find("taken by participant P1"), std::string::npos) << out;
    ASSERT_EQ(run(db, "P1", {}, &out), 0) << out;  // session 3 of 3
    EXPECT_NE(run(db, "P1", {}, &out), 0);
    EXPECT_NE(out.find("sessions = 3"), std::string::npos) << out;
    EXPECT_EQ(open(db)->roster().value_or_throw().size(), 3u);
}

TEST_F(StudyDayCli, NotesTheRosterAndResumeBySessionNumber) {
    const std::string db = path("s.sqlite");
    std::string out;
    ASSERT_EQ(run(db, "P1", {"--var", "age=30", "--seed", "1"}, &out), 0) << out;
    ASSERT_EQ(run(db, "P2", {"--var", "age=41", "--var", "vision=corrected", "--seed", "2"}, &out),
              0)
        << out;
    ASSERT_EQ(study({"note", "--db", db, "--participant", "P1", "=1+1 adjusted the strap"}, &out),
              0)
        << out;
    EXPECT_NE(study({"note", "--db", db, "--participant", "P1", "--session", "2", "x"}, &out), 0);
    EXPECT_NE(out.find("has no session 2"), std::string::npos) << out;
    EXPECT_NE(study({"note", "--db", db, "--participant", "P9", "x"}, &out), 0);
    EXPECT_NE(out.find("P9"), std::string::npos) << out;
    EXPECT_NE(study({"note", "--db", db, "--participant", "P1", "   "}, &out), 0);

    auto store = open(db);
    const auto id = store->find_session("P1", 1).value_or_throw();
    ASSERT_TRUE(id);
    const study::SessionInfo info = store->session(*id).value_or_throw();
    ASSERT_EQ(info.notes.size(), 1u);
    EXPECT_EQ(info.notes[0].text, "=1+1 adjusted the strap");  // kept as typed
    EXPECT_EQ(info.notes[0].source, study::NoteSource::Command);
    EXPECT_FALSE(info.notes[0].trial_index.has_value());
    store.reset();

    ASSERT_EQ(study({"list", "--db", db, "--json"}, &out), 0) << out;
    const nlohmann::json roster = nlohmann::json::parse(out.substr(0, out.rfind('}') + 1));
    ASSERT_EQ(roster["sessions"].size(), 2u);
    for (const nlohmann::json& s : roster["sessions"]) {
        // 1 practice trial apart: 3 scenes x 2 distances x 2 repetitions.
        EXPECT_EQ(s["trials_planned"], 12);
        EXPECT_EQ(s["trials_decided"], 12);
        EXPECT_EQ(s["state"], "completed");
        EXPECT_EQ(s["session"], 1);
        EXPECT_TRUE(s["held_by"].is_null());
        EXPECT_EQ(s["gaze"], false);  // headless sessions record no eye gaze
    }
    EXPECT_EQ(roster["sessions"][1]["participant"], "P2");
    EXPECT_EQ(roster["sessions"][1]["participant_number"], 2);

    EXPECT_NE(study({"resume", "--db", db, "--session", "1"}, &out), 0);
    EXPECT_NE(out.find("--session-id"), std::string::npos) << out;
    EXPECT_NE(study({"resume", "--db", db, "--participant", "P1"}, &out), 0);
    EXPECT_NE(out.find("no unfinished session"), std::string::npos) << out;
}

// A participant's second session on another lab PC: that database does not know them, so the
// session number and the number they were given on the first PC come from the experimenter; the
// scene order goes on as if both sessions were in one database.
TEST_F(StudyDayCli, ASecondSessionOnAnotherPcContinuesTheParticipantsSceneOrder) {
    std::string out;
    ASSERT_EQ(run(path("pc1.sqlite"), "P1",
                  {"--var", "age=30", "--participant-number", "2", "--seed", "5"}, &out),
              0)
        << out;
    EXPECT_NE(run(path("pc2.sqlite"), "P1", {"--var", "age=30", "--session", "2"}, &out), 0);
    EXPECT_NE(out.find("--participant-number"), std::string::npos) << out;
    EXPECT_FALSE(fs::exists(path("pc2.sqlite")));
    ASSERT_EQ(run(path("pc2.sqlite"), "P1",
                  {"--var", "age=30", "--session", "2", "--participant-number", "2", "--seed", "6"},
                  &out),
              0)
        << out;
    auto store = open(path("pc2.sqlite"));
    const auto id = store->find_session("P1", 2).value_or_throw();
    ASSERT_TRUE(id);
    // Row 1 (landscape, spheres, beams) rotated by one place, as in one database.
    EXPECT_EQ(store->load_schedule(*id).value_or_throw().block_order,
              (std::vector<std::string>{"spheres", "beams", "landscape"}));
}

TEST_F(StudyDayCli, ALiveSessionIsNeverTakenOverAndADeadOneResumesAtOnce) {
    const std::string db = path("s.sqlite");
    const std::vector<std::string> slow = {
        MONOPLANE_EXE,   "study", "run",   "--protocol", path("day.toml"), "--db", db,
        "--participant", "P1",    "--var", "age=30",     "--headset",      "none"};
    // Each session stands still after its third write (stopped, as a busy machine may stop it),
    // alive and holding the session.
    const auto third = [](int k, const std::string&) { return k == 3; };
    SteppedChild running = run_until_committed(slow, third, {});
    ASSERT_TRUE(running.stopped) << running.output;
    std::string refused;
    EXPECT_NE(study({"resume", "--db", db}, &refused), 0);
    EXPECT_NE(refused.find("being run by process " + std::to_string(running.pid)),
              std::string::npos)
        << refused;
    std::string listed;
    ASSERT_EQ(study({"list", "--db", db}, &listed), 0) << listed;
    EXPECT_NE(listed.find("running (process " + std::to_string(running.pid)), std::string::npos)
        << listed;
    // The running session goes on undisturbed to its end.
    EXPECT_EQ(continue_to_end(running), 0) << running.output;
    EXPECT_EQ(open(db)->session(1).value_or_throw().status, study::SessionStatus::Completed);

    // A session whose process died is free at once: no stale flag to clear.
    std::vector<std::string> second = slow;
    second[8] = "P2";
    const KilledRun killed = kill_child(run_until_committed(second, third, {}));
    ASSERT_TRUE(killed.killed) << killed.output;
    ASSERT_EQ(study({"list", "--db", db}, &listed), 0);
    EXPECT_NE(listed.find("interrupted"), std::string::npos) << listed;
    std::string resumed;
    ASSERT_EQ(study({"resume", "--db", db, "--participant", "P2"}, &resumed), 0) << resumed;
    const auto id = open(db)->find_session("P2", 1).value_or_throw();
    ASSERT_TRUE(id);
    EXPECT_EQ(open(db)->session(*id).value_or_throw().status, study::SessionStatus::Completed);
}

std::string file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

// Nothing a lab has is overwritten by mistake: an export onto its own database (by another path
// too), onto another study's database, onto a protocol or another format's export is refused
// with nothing changed; --force replaces only a file that is no database.
TEST_F(StudyDayCli, AnExportNeverOverwritesADatabaseOrAnUnrelatedFile) {
    const std::string db = path("s.sqlite");
    std::string out;
    ASSERT_EQ(run(db, "P1", {"--var", "age=30"}, &out), 0) << out;
    ASSERT_EQ(run(path("other.sqlite"), "Q1", {"--var", "age=30"}, &out), 0) << out;
    const std::string db_bytes = file_bytes(db);
    const std::string other_bytes = file_bytes(path("other.sqlite"));
    const std::string protocol_bytes = file_bytes(path("day.toml"));
    const auto export_to = [&](const std::string& target, bool force) {
        std::vector<std::string> args = {"export", "--db", db, "--format", "csv", "--out", target};
        if (force) args.push_back("--force");
        return study(args, &out);
    };
    EXPECT_NE(export_to(db, false), 0);
    EXPECT_NE(export_to(db, true), 0);
    EXPECT_NE(export_to((dir_ / "." / "s.sqlite").string(), true), 0);
    EXPECT_NE(export_to(path("other.sqlite"), true), 0);
    EXPECT_NE(export_to(path("day.toml"), false), 0);
    EXPECT_NE(out.find("--force"), std::string::npos) << out;
    EXPECT_EQ(file_bytes(db), db_bytes);
    EXPECT_EQ(file_bytes(path("other.sqlite")), other_bytes);
    EXPECT_EQ(file_bytes(path("day.toml")), protocol_bytes);
    ASSERT_EQ(study({"export", "--db", db, "--format", "json", "--out", path("s.json")}), 0);
    EXPECT_NE(export_to(path("s.json"), false), 0);  // another format's export
    ASSERT_EQ(export_to(path("s.csv"), false), 0) << out;
    ASSERT_EQ(export_to(path("s.csv"), false), 0) << out;  // an earlier export of the same kind
    ASSERT_EQ(export_to(path("day.toml"), true), 0) << out;
    EXPECT_EQ(file_bytes(path("day.toml")), file_bytes(path("s.csv")));
}

// A database of the previous schema (tests/fixtures/study/README.md) is migrated when opened; its
// interrupted session resumes and the export carries the new columns with the old sessions'
// values (session 1, repetition 1).
TEST_F(StudyDayCli, ASchemaSixDatabaseMigratesResumesAndExports) {
    const std::string db = path("old.sqlite");
    fs::copy_file(source_dir() + "/tests/fixtures/study/schema6.sqlite", db);
    std::string out;
    ASSERT_EQ(study({"resume", "--db", db, "--participant", "A2"}, &out), 0) << out;
    auto store = open(db);
    const auto roster = store->roster().value_or_throw();
    ASSERT_EQ(roster.size(), 2u);
    for (const study::RosterRow& row : roster) {
        EXPECT_EQ(row.status, study::SessionStatus::Completed) << row.participant_code;
        EXPECT_EQ(row.trials_decided, 6);  // demo: 3 scenes x 2 distances, practice apart
        EXPECT_EQ(row.session_number, 1);
    }
    EXPECT_EQ(store->participant("A2").value_or_throw()->participant_number, 1);
    store.reset();
    ASSERT_EQ(study({"export", "--db", db, "--format", "csv", "--out", path("old.csv")}, &out), 0)
        << out;
    std::ifstream csv(path("old.csv"));
    std::string header;
    std::getline(csv, header);
    std::vector<std::string> columns;
    for (std::size_t at = 0; at <= header.size();) {
        const std::size_t comma = std::min(header.find(',', at), header.size());
        columns.push_back(header.substr(at, comma - at));
        at = comma + 1;
    }
    const auto column = [&](const std::string& name) {
        return std::find(columns.begin(), columns.end(), name) - columns.begin();
    };
    ASSERT_LT(column("session"), static_cast<long>(columns.size())) << header;
    ASSERT_LT(column("repetition"), static_cast<long>(columns.size())) << header;
    int rows = 0;
    for (std::string line; std::getline(csv, line); ++rows) {
        std::vector<std::string> cells;
        for (std::size_t at = 0; at <= line.size();) {
            const std::size_t comma = std::min(line.find(',', at), line.size());
            cells.push_back(line.substr(at, comma - at));
            at = comma + 1;
        }
        EXPECT_EQ(cells.at(static_cast<std::size_t>(column("session"))), "1") << line;
        EXPECT_EQ(cells.at(static_cast<std::size_t>(column("repetition"))), "1") << line;
    }
    EXPECT_EQ(rows, 14);  // two sessions of 7 trials, practice included
}

}  // namespace
}  // namespace monoplane
