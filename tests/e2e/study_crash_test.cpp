// Crash safety (issue 4, item 5; issue 17, item 5): a child process running a session is killed
// with SIGKILL mid-session; after each kill SQLite's integrity_check is ok, the database opens
// cleanly, every write the child reported as committed is there, and `study resume` finishes the
// session with the right number of trials. Headless sessions (`--headset none`) are killed at
// random moments; sessions on the simulated headset (`--headset simulated`, the path participants
// use) right after a varied number of committed writes, their resumed runs too, and there the
// frame log (table frames) must hold every frame displayed before the last committed event.
// Issue 42, item 5: on both paths the runs of a resumed session share one time axis and frame
// numbering, and a trial, a break or an instruction page cut short keeps what its runs showed.
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "study/study_store.h"
#include "tests/e2e/child_process.h"

namespace monoplane {
namespace {

// What a child reported as committed, from its --trace lines:
// "committed trial 3 switched label 2 t 123 frame 11", "committed trial 3 outcome choice 2",
// "committed answer 1: 5", "committed session completed".
struct CommittedEvent {
    int trial = 0;
    std::string kind;
    int label = 0;
    std::int64_t time_ns = 0;
    std::int64_t frame = 0;
    auto key() const { return std::tie(trial, kind, label, time_ns, frame); }
    bool operator<(const CommittedEvent& o) const { return key() < o.key(); }
};

struct Committed {
    std::vector<CommittedEvent> events;
    std::vector<std::pair<int, int>> outcomes;  // trial, choice
    std::vector<std::pair<int, int>> answers;   // item (1-based), value, in order
    int lines = 0;
    std::string last;  // the last committed line, without "committed "
};

Committed parse_committed(const std::string& output) {
    Committed c;
    std::istringstream lines(output);
    std::string line;
    while (std::getline(lines, line)) {
        std::istringstream words(line);
        std::string tag, what;
        words >> tag >> what;
        if (tag != "committed") continue;
        ++c.lines;
        c.last = line.substr(10);
        if (what == "answer") {
            int item = 0, value = 0;
            char colon = 0;
            words >> item >> colon >> value;
            c.answers.emplace_back(item, value);
            continue;
        }
        if (what != "trial") continue;
        CommittedEvent e;
        words >> e.trial >> e.kind;
        if (e.kind == "outcome") {
            std::string choice_word;
            int choice = 0;
            words >> choice_word >> choice;
            c.outcomes.emplace_back(e.trial, choice);
            continue;
        }
        std::string w;
        words >> w >> e.label >> w >> e.time_ns >> w >> e.frame;
        c.events.push_back(e);
    }
    return c;
}

// The kind of a committed write: shown, switched, confirmed, refused, outcome, questionnaire,
// answer or session.
std::string write_kind(const std::string& line) {
    std::istringstream words(line);
    std::string first, trial, kind;
    words >> first >> trial >> kind;
    return first == "trial" ? kind : first;
}

// PRAGMA integrity_check through a connection of its own, as an sqlite3 shell would run it.
std::string integrity_check(const std::string& path) {
    sqlite3* db = nullptr;
    std::string result = "cannot open";
    if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK) {
        sqlite3_stmt* stmt = nullptr;
        result = "cannot run";
        if (sqlite3_prepare_v2(db, "PRAGMA integrity_check", -1, &stmt, nullptr) == SQLITE_OK) {
            result.clear();
            while (sqlite3_step(stmt) == SQLITE_ROW) {
                const auto* text = reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0));
                result += (result.empty() ? "" : "; ") + std::string(text ? text : "");
            }
            sqlite3_finalize(stmt);
        }
    }
    sqlite3_close_v2(db);
    return result;
}

// Every committed event is stored, as often as it was committed (a resumed run may repeat an
// event of a trial the kill left undecided).
void expect_events_kept(const std::vector<CommittedEvent>& committed,
                        const std::vector<study::TrialEvent>& stored) {
    std::map<CommittedEvent, int> count;
    for (const study::TrialEvent& e : stored) {
        ++count[{e.trial_index, std::string(study::event_kind_name(e.kind)), e.label, e.time_ns,
                 e.frame}];
    }
    for (const CommittedEvent& c : committed) {
        EXPECT_GT(count[c]--, 0) << "lost: trial " << c.trial << " " << c.kind << " label "
                                 << c.label << " t " << c.time_ns << " frame " << c.frame;
    }
}

void expect_outcomes_kept(const std::vector<std::pair<int, int>>& outcomes,
                          const std::vector<study::TrialRecord>& records, std::int64_t id) {
    for (const auto& [trial, choice] : outcomes) {
        bool found = false;
        for (const study::TrialRecord& r : records) {
            found = found || (r.session_id == id && r.trial.index == trial && r.decided &&
                              r.outcome.choice == choice);
        }
        EXPECT_TRUE(found) << "lost decision of trial " << trial;
    }
}

TEST(StudyCrash, KilledSessionsKeepEveryCommittedWriteAndResume) {
    const std::string exe = MONOPLANE_EXE;
    const std::string protocol = source_dir() + "/protocols/demo.toml";
    // A folder of this process's own: another build's ctest may run this test at the same time.
    const std::filesystem::path dir =
        std::filesystem::temp_directory_path() / ("monoplane_crash_" + std::to_string(getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    std::mt19937_64 random(20190323);
    // How long a whole session takes here, so the kills fall inside it on any machine.
    const auto start = std::chrono::steady_clock::now();
    ASSERT_EQ(run_to_end({exe, "study", "run", "--protocol", protocol, "--participant", "timing",
                          "--db", (dir / "timing.sqlite").string(), "--headset", "none", "--seed",
                          "999", "--pace-ms", "3"}),
              0);
    const auto session_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                                std::chrono::steady_clock::now() - start)
                                .count();
    int killed_mid_session = 0;
    // Under load (ctest -j with GPU tests beside it) many kills land in start-up, before the
    // database exists: allow enough rounds to collect the kills that matter.
    for (int round = 0; round < 150 && killed_mid_session < 22; ++round) {
        SCOPED_TRACE("round " + std::to_string(round));
        const std::string db = (dir / ("crash" + std::to_string(round) + ".sqlite")).string();
        auto [pid, fd] =
            spawn({exe, "study", "run", "--protocol", protocol, "--participant",
                   "P" + std::to_string(round), "--db", db, "--headset", "none", "--seed",
                   std::to_string(1000 + round), "--pace-ms", "3", "--trace"});
        ASSERT_GT(pid, 0);
        // Kill at a random moment between start-up and the end of the session.
        const auto delay = std::chrono::milliseconds(
            static_cast<long>(static_cast<double>(random() % 1000) / 1000.0 * session_ms * 0.95));
        std::this_thread::sleep_for(delay);
        kill(pid, SIGKILL);
        int status = 0;
        waitpid(pid, &status, 0);
        const std::string output = read_all(fd);  // what the child reported before dying
        const bool killed = WIFSIGNALED(status);
        const Committed committed = parse_committed(output);

        if (!std::filesystem::exists(db)) {
            EXPECT_TRUE(committed.events.empty());  // killed before the database existed
            continue;
        }
        EXPECT_EQ(integrity_check(db), "ok");
        auto opened = study::StudyStore::open(db);
        ASSERT_TRUE(opened.ok()) << opened.error().message;  // opens cleanly after the kill
        std::unique_ptr<study::StudyStore> store = std::move(opened).value();
        auto session = store->latest_unfinished_session();
        ASSERT_TRUE(session.ok()) << session.error().message;
        const auto records = store->trials();
        ASSERT_TRUE(records.ok());
        if (!session->has_value()) {
            // The kill came after completion, or before the session row was written.
            continue;
        }
        const std::int64_t id = **session;
        if (killed) ++killed_mid_session;
        const auto events = store->events(id);
        ASSERT_TRUE(events.ok());
        expect_events_kept(committed.events, *events);
        expect_outcomes_kept(committed.outcomes, *records, id);
        store.reset();  // close before the resume process opens it

        ASSERT_EQ(run_to_end({exe, "study", "resume", "--db", db, "--headset", "none"}), 0);
        EXPECT_EQ(integrity_check(db), "ok");
        auto reopened = study::StudyStore::open(db);
        ASSERT_TRUE(reopened.ok());
        const auto schedule = (*reopened)->load_schedule(id);
        ASSERT_TRUE(schedule.ok());
        const auto final_records = (*reopened)->trials(id);
        ASSERT_TRUE(final_records.ok());
        EXPECT_EQ(final_records->size(), schedule->trials.size());
        for (const study::TrialRecord& r : *final_records) EXPECT_TRUE(r.decided) << r.trial.index;
        const auto info = (*reopened)->session(id);
        ASSERT_TRUE(info.ok());
        EXPECT_EQ(info->status, study::SessionStatus::Completed);
        // Decisions made before the kill survived the resume unchanged.
        for (const auto& [trial, choice] : committed.outcomes) {
            for (const study::TrialRecord& r : *final_records) {
                if (r.trial.index == trial) {
                    EXPECT_EQ(r.outcome.choice, choice);
                }
            }
        }
    }
    // Kills that hit a running session with its database in place: at least 20 are required.
    EXPECT_GE(killed_mid_session, 20);
    std::cout << killed_mid_session << " sessions killed mid-way, a session takes " << session_ms
              << " ms\n";
    if (!::testing::Test::HasFailure()) std::filesystem::remove_all(dir);
}

// The simulated headset's virtual clock (docs/simxr.md): frame n of a run is displayed at
// 10 s + n * period, and frame 0 (SYNCHRONIZED) is not rendered; every later frame is.
constexpr std::int64_t kSimBaseNs = 10'000'000'000;
constexpr int kSimRateHz = 2;  // few frames per trial: the observer's dwells are virtual seconds
constexpr std::int64_t kSimPeriodNs = 1'000'000'000 / kSimRateHz;

// The frame log of a simulated-headset session, after a kill or at its end, against what the
// runtime displayed and what was committed. Each run of the session (the first, and each resume)
// starts the runtime's clock again and has its row in session_runs: its frames are numbered from
// its first_frame, and its times are the runtime's plus its clock_offset_ns. So a run's logged
// frame first_frame + n must carry the runtime's display time of its frame n, and in each run the
// rows must be exactly n = 1, 2, ..., L: every frame the runtime displayed up to the run's last
// written frame, none lost or replaced. Every stored event that names a frame has that frame's
// row, showing that event's trial (and, for shown and switched, its label at the event's time):
// so the frames before the last committed event of each run were committed with it. Returns
// "L1+L2+..." (rows per run) for the log.
std::string expect_frame_log_complete(const std::vector<study::FrameRecord>& frames,
                                      const std::vector<study::TrialEvent>& events,
                                      const std::vector<study::RunRecord>& runs) {
    std::map<std::int64_t, const study::FrameRecord*> by_frame;
    std::map<int, std::int64_t> rows;  // per run
    std::int64_t expected_n = 0;
    int current = 0;
    for (const study::FrameRecord& f : frames) {
        by_frame[f.frame] = &f;
        EXPECT_FALSE(f.missed) << "frame " << f.frame << ": the virtual clock misses no slot";
        const study::RunRecord* run = nullptr;
        for (const study::RunRecord& r : runs)
            if (r.first_frame <= f.frame) run = &r;
        if (run == nullptr) {
            ADD_FAILURE() << "frame " << f.frame << " belongs to no run";
            continue;
        }
        const std::int64_t n = f.frame - run->first_frame;
        EXPECT_EQ(f.display_time_ns - run->clock_offset_ns, kSimBaseNs + n * kSimPeriodNs)
            << "frame " << f.frame << " (run " << run->run << ", runtime frame " << n << ")";
        if (run->run != current) {
            current = run->run;
            expected_n = 1;
        }
        EXPECT_EQ(n, expected_n) << "the frame log of run " << run->run << " lacks runtime frame "
                                 << expected_n;
        expected_n = n + 1;
        ++rows[run->run];
    }
    for (const study::TrialEvent& e : events) {
        if (e.frame < 0) continue;
        const std::string what = "event trial " + std::to_string(e.trial_index) + " " +
                                 std::string(study::event_kind_name(e.kind)) + " label " +
                                 std::to_string(e.label) + " frame " + std::to_string(e.frame);
        const auto row = by_frame.find(e.frame);
        if (row == by_frame.end()) {
            ADD_FAILURE() << what << ": its frame is not in the frame log";
            continue;
        }
        const study::FrameRecord& f = *row->second;
        EXPECT_EQ(f.trial_index.value_or(-1), e.trial_index) << what << ", logged " << f.shown;
        if (e.kind == study::EventKind::Shown || e.kind == study::EventKind::Switched) {
            EXPECT_EQ(f.shown, "label" + std::to_string(e.label)) << what;
            EXPECT_EQ(f.display_time_ns, e.time_ns) << what;
        }
    }
    std::string summary;
    for (const auto& [run, count] : rows)
        summary += (summary.empty() ? "" : "+") + std::to_string(count);
    return summary;
}

// The same on the path participants use: `study run --headset simulated` (the simulated OpenXR
// runtime on its virtual clock, the default observer at the controls, the validation layer on),
// killed right after its k-th committed write for varied k, then `study resume` killed the same
// way, several times per database, and a last resume to the end. After each kill: integrity_check,
// every committed event, decision and answer of every run so far, and a complete frame log.
TEST(StudyCrash, KilledHeadsetSessionsKeepEveryCommittedWriteAndFrameAndResume) {
    namespace fs = std::filesystem;
    const std::string exe = MONOPLANE_EXE;
    const std::string protocol = source_dir() + "/protocols/demo.toml";
    const fs::path dir =
        fs::temp_directory_path() / ("monoplane_crash_headset_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string tmpdir = dir.string();
    // Small and fast: 5 % of the Vive's eye size, the test scenes, two frames a second, a short
    // neutral screen.
    const std::vector<std::string> headset = {
        "--headset",          "simulated", "--window",   "off",
        "--resolution-scale", "0.05",      "--sim-rate", std::to_string(kSimRateHz),
        "--neutral-s",        "0.2",       "--trace"};
    const auto run_args = [&](const std::string& db, const std::string& participant, int seed) {
        std::vector<std::string> args = {exe,
                                         "--validation",
                                         "study",
                                         "run",
                                         "--protocol",
                                         protocol,
                                         "--participant",
                                         participant,
                                         "--db",
                                         db,
                                         "--observer",
                                         "default",
                                         "--detail",
                                         "test",
                                         "--seed",
                                         std::to_string(seed)};
        args.insert(args.end(), headset.begin(), headset.end());
        return args;
    };
    const auto resume_args = [&](const std::string& db) {
        std::vector<std::string> args = {exe, "--validation", "study", "resume", "--db", db};
        args.insert(args.end(), headset.begin(), headset.end());
        return args;
    };

    // A whole session, unkilled: how many writes it commits (the kills spread over them), and a
    // reference for the checks.
    const auto start = std::chrono::steady_clock::now();
    std::string output;
    const std::string timing_db = (dir / "timing.sqlite").string();
    ASSERT_EQ(run_to_end(run_args(timing_db, "timing", 999), &output, tmpdir), 0) << output;
    const auto session_ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                                std::chrono::steady_clock::now() - start)
                                .count();
    const int session_lines = parse_committed(output).lines;
    ASSERT_GT(session_lines, 20) << output;
    {
        auto store = study::StudyStore::open(timing_db);
        ASSERT_TRUE(store.ok()) << store.error().message;
        const auto frames = (*store)->frames(1);
        const auto events = (*store)->events(1);
        const auto runs = (*store)->runs(1);
        ASSERT_TRUE(frames.ok() && events.ok() && runs.ok());
        ASSERT_FALSE(frames->empty());
        expect_frame_log_complete(*frames, *events, *runs);
    }

    std::mt19937_64 random(20170318);
    constexpr int kChainKills = 8;  // kills per database before the last resume
    int killed_mid_session = 0;
    std::map<std::string, int> killed_after;  // what the last committed line was
    for (int chain = 0; chain < 6 && killed_mid_session < 22; ++chain) {
        SCOPED_TRACE("database " + std::to_string(chain));
        const std::string db = (dir / ("chain" + std::to_string(chain) + ".sqlite")).string();
        std::vector<CommittedEvent> events;  // committed by every run of this database so far
        std::vector<std::pair<int, int>> outcomes;
        std::map<int, int> answers;  // item (1-based): the latest committed value
        std::string runs;
        bool finished = false;
        for (int segment = 0; segment < kChainKills && !finished; ++segment) {
            SCOPED_TRACE("run " + std::to_string(segment));
            // The first run of each database is killed in a different third of the session;
            // the resumed runs a few writes in (1 to 9), so the kills walk through the rest of
            // it, the questionnaire and the start of each resumed run included.
            const int k = segment == 0 ? 1 + (chain % 3) * (session_lines - 3) / 3 + chain / 3
                                       : 1 + static_cast<int>(random() % 9);
            const KilledRun run = run_and_kill_after(
                segment == 0 ? run_args(db, "H" + std::to_string(chain), 3000 + chain)
                             : resume_args(db),
                k, tmpdir);
            ASSERT_FALSE(run.stalled) << run.output;
            const Committed c = parse_committed(run.output);
            events.insert(events.end(), c.events.begin(), c.events.end());
            outcomes.insert(outcomes.end(), c.outcomes.begin(), c.outcomes.end());
            for (const auto& [item, value] : c.answers) answers[item] = value;

            ASSERT_TRUE(fs::exists(db));  // a committed line came first
            EXPECT_EQ(integrity_check(db), "ok");
            auto opened = study::StudyStore::open(db);
            ASSERT_TRUE(opened.ok()) << opened.error().message;
            std::unique_ptr<study::StudyStore> store = std::move(opened).value();
            const auto info = store->session(1);
            ASSERT_TRUE(info.ok()) << info.error().message;
            finished = info->status == study::SessionStatus::Completed;
            // A run that was not killed ended the session (it had fewer writes left than k).
            EXPECT_TRUE(run.killed || finished) << run.output;
            if (run.killed && !finished) {
                ++killed_mid_session;
                ++killed_after[write_kind(c.last)];
            }
            const auto stored = store->events(1);
            const auto records = store->trials(1);
            const auto stored_answers = store->answers(1);
            const auto frames = store->frames(1);
            const auto session_runs = store->runs(1);
            ASSERT_TRUE(stored.ok() && records.ok() && stored_answers.ok() && frames.ok() &&
                        session_runs.ok());
            expect_events_kept(events, *stored);
            expect_outcomes_kept(outcomes, *records, 1);
            for (const auto& [item, value] : answers) {
                bool found = false;
                for (const study::QuestionnaireAnswer& a : *stored_answers)
                    found = found || (a.item == item - 1 && a.answer == value);
                EXPECT_TRUE(found) << "lost answer " << value << " to item " << item;
            }
            runs = expect_frame_log_complete(*frames, *stored, *session_runs);
        }

        // The last resume, to the end.
        if (!finished) {
            ASSERT_EQ(run_to_end(resume_args(db), &output, tmpdir), 0) << output;
            const Committed c = parse_committed(output);
            events.insert(events.end(), c.events.begin(), c.events.end());
        }
        EXPECT_EQ(integrity_check(db), "ok");
        auto store = study::StudyStore::open(db);
        ASSERT_TRUE(store.ok()) << store.error().message;
        const auto info = (*store)->session(1);
        ASSERT_TRUE(info.ok());
        EXPECT_EQ(info->status, study::SessionStatus::Completed);
        const auto schedule = (*store)->load_schedule(1);
        const auto records = (*store)->trials(1);
        const auto stored = (*store)->events(1);
        const auto frames = (*store)->frames(1);
        const auto session_runs = (*store)->runs(1);
        ASSERT_TRUE(schedule.ok() && records.ok() && stored.ok() && frames.ok() &&
                    session_runs.ok());
        EXPECT_EQ(records->size(), schedule->trials.size());
        for (const study::TrialRecord& r : *records) EXPECT_TRUE(r.decided) << r.trial.index;
        // Decisions made before a kill survived the resumes unchanged.
        for (const auto& [trial, choice] : outcomes) {
            for (const study::TrialRecord& r : *records) {
                if (r.trial.index == trial) {
                    EXPECT_EQ(r.outcome.choice, choice) << trial;
                }
            }
        }
        expect_events_kept(events, *stored);
        runs = expect_frame_log_complete(*frames, *stored, *session_runs);
        std::cout << "database " << chain << ": frame log rows per run " << runs << "\n";
    }
    EXPECT_GE(killed_mid_session, 20);
    std::cout << killed_mid_session
              << " headset sessions killed mid-way (a whole session: " << session_lines
              << " committed writes, " << session_ms << " ms); killed after:";
    for (const auto& [what, count] : killed_after) std::cout << " " << what << " " << count;
    std::cout << "\n";
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

// Issue 30, item 7: sessions killed on the participant's screens and right after an
// experimenter's note resume where they stood, and lose nothing. The protocol has two instruction
// pages, a ready screen, a break every two data trials and an end screen; the note comes from
// `study note` in another process while the session runs, as an experimenter types it.
constexpr const char* kScreensProtocol = R"(name = "screens"
scenes = ["beams", "landscape", "spheres"]
mono_planes = [3, 8]
alternatives = ["stereo", "hybrid"]
practice_trials = 1
[[instructions]]
text = "First page."
[[instructions]]
text = "Second page."
[ready]
text = "Ready."
[breaks]
every_trials = 2
min_s = 3
[end]
text = "Thank you."
)";

// Each break_ended closes a break whose start was logged (in its run, or again in the resumed
// run that showed it).
void expect_breaks_started_before_they_end(const std::vector<study::TrialEvent>& events) {
    bool open = false;
    for (const study::TrialEvent& e : events) {
        if (e.kind == study::EventKind::BreakStarted) open = true;
        if (e.kind == study::EventKind::BreakEnded) {
            EXPECT_TRUE(open) << "break_ended at " << e.time_ns << " without a break_started";
            open = false;
        }
    }
}

struct ScreenCount {
    std::map<std::pair<std::string, int>, int> shown;  // (kind, page) -> events
};

ScreenCount count_screens(const std::vector<study::TrialEvent>& events) {
    ScreenCount c;
    for (const study::TrialEvent& e : events) {
        if (study::is_screen_event(e.kind))
            ++c.shown[{std::string(study::event_kind_name(e.kind)), e.page}];
    }
    return c;
}

// Runs the screens protocol's session into `db` and SIGKILLs it right after the committed write
// whose line starts with `when` (with `note`: once that write is committed, and while the session
// stands there, a note is added from another process); then resumes it to its end. What the
// killed run reported as committed is returned in *committed.
void kill_on_screen_and_resume(const std::string& protocol, const std::string& db,
                               const std::string& when, const std::string& note,
                               const std::string& tmpdir, Committed* committed) {
    const std::string exe = MONOPLANE_EXE;
    SteppedChild child = run_until_committed(
        {exe, "study", "run", "--protocol", protocol, "--db", db, "--participant", "P1",
         "--headset", "none", "--seed", "7"},
        [&when](int, const std::string& line) { return line.starts_with(when); }, tmpdir);
    ASSERT_TRUE(child.stopped) << "the session ended before its write '" << when << "':\n"
                               << child.output;
    if (!note.empty()) {
        ASSERT_EQ(run_to_end({exe, "study", "note", "--db", db, "--participant", "P1", "--", note}),
                  0);
    }
    const KilledRun killed = kill_child(std::move(child));
    ASSERT_TRUE(killed.killed) << killed.output;
    *committed = parse_committed(killed.output);
    ASSERT_TRUE(committed->last.starts_with(when)) << killed.output;
    std::string resumed;
    ASSERT_EQ(
        run_to_end({exe, "study", "resume", "--db", db, "--participant", "P1"}, &resumed, tmpdir),
        0)
        << resumed;
}

TEST(StudyCrash, KilledOnScreensAndAfterANoteResumeWhereTheyStood) {
    namespace fs = std::filesystem;
    const fs::path dir =
        fs::temp_directory_path() / ("monoplane_crash_screens_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string protocol = (dir / "screens.toml").string();
    std::ofstream(protocol) << kScreensProtocol;
    const std::string note = "-participant stood up, =strap adjusted";
    const std::vector<std::pair<std::string, std::string>> kills = {
        {"instructions", "screen instructions_confirmed page 0"},
        {"break", "screen break_started"},
        {"note", "screen break_started"},
    };
    for (const auto& [name, when] : kills) {
        SCOPED_TRACE(name);
        const std::string db = (dir / (name + ".sqlite")).string();
        Committed committed;
        kill_on_screen_and_resume(protocol, db, when, name == "note" ? note : "", dir.string(),
                                  &committed);
        if (::testing::Test::HasFatalFailure()) return;
        EXPECT_EQ(integrity_check(db), "ok");
        auto store = study::StudyStore::open(db).value_or_throw();
        const study::SessionInfo info = store->session(1).value_or_throw();
        EXPECT_EQ(info.status, study::SessionStatus::Completed);
        const auto events = store->events(1).value_or_throw();
        expect_events_kept(committed.events, events);
        const auto trials = store->trials(1).value_or_throw();
        expect_outcomes_kept(committed.outcomes, trials, 1);
        for (const study::TrialRecord& r : trials) EXPECT_TRUE(r.decided) << r.trial.index;
        const ScreenCount screens = count_screens(events);
        const auto count = [&](const std::string& kind, int page) {
            const auto it = screens.shown.find({kind, page});
            return it == screens.shown.end() ? 0 : it->second;
        };
        // Each page read once, though the kill came in the middle of them.
        EXPECT_EQ(count("instructions_confirmed", 0), 1);
        EXPECT_EQ(count("instructions_confirmed", 1), 1);
        EXPECT_EQ(count("instructions_shown", 0), 1);
        EXPECT_EQ(count("ready_confirmed", -1), 1);
        // 6 data trials, a break after the 2nd and the 4th: each ended once; the one the kill
        // cut short (the killed run's last write was its start) logged its start again when the
        // resumed run showed it.
        EXPECT_EQ(count("break_started", -1), name == "instructions" ? 2 : 3);
        EXPECT_EQ(count("break_ended", -1), 2);
        expect_breaks_started_before_they_end(events);
        EXPECT_EQ(count("end_shown", -1), 1);
        if (name == "note") {
            ASSERT_EQ(info.notes.size(), 1u);
            EXPECT_EQ(info.notes[0].text, note);
            EXPECT_EQ(info.notes[0].source, study::NoteSource::Command);
        }
    }
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

// On the simulated headset a break killed midway resumes for what is left of its minimum: no event
// is logged during a break, but the frame log is (flushed every 30 frames), and the resumed run's
// break lasts min_s minus the break time those frames show. The runtime's virtual clock starts
// again at 10 s in the resumed run; its times go on the session's axis after the killed run's,
// so the whole break, from its first start to its end, lasts its minimum there.
TEST(StudyCrash, AHeadsetBreakKilledMidwayResumesForWhatIsLeftOfIt) {
    namespace fs = std::filesystem;
    const std::string exe = MONOPLANE_EXE;
    const fs::path dir =
        fs::temp_directory_path() / ("monoplane_crash_break_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string protocol = (dir / "break.toml").string();
    std::ofstream(protocol) << "name = \"break\"\nscenes = [\"beams\"]\nmono_planes = [3, 8]\n"
                               "alternatives = [\"stereo\", \"hybrid\"]\npractice_trials = 0\n"
                               "[breaks]\nevery_trials = 1\nmin_s = 1800\n";
    const std::string db = (dir / "break.sqlite").string();
    const std::vector<std::string> headset = {
        "--headset",   "simulated",  "--window",   "off",      "--resolution-scale",
        "0.05",        "--sim-rate", "1",          "--detail", "test",
        "--neutral-s", "0.2",        "--observer", "default",  "--trace"};
    std::vector<std::string> run = {exe, "study",         "run", "--protocol", protocol, "--db",
                                    db,  "--participant", "P1",  "--seed",     "3"};
    run.insert(run.end(), headset.begin(), headset.end());
    auto [pid, fd] = spawn(run, dir.string());
    ASSERT_GT(pid, 0);
    std::string output;
    char buffer[4096];
    while (output.find("committed screen break_started") == std::string::npos) {
        const ssize_t n = read(fd, buffer, sizeof buffer);
        if (n <= 0) break;
        output.append(buffer, static_cast<std::size_t>(n));
    }
    ASSERT_NE(output.find("committed screen break_started"), std::string::npos) << output;
    // Wait until the frame log holds a minute of the break (60 frames at 1 Hz), then kill.
    std::int64_t logged_ns = 0;
    study::TrialEvent started;
    for (int tries = 0; tries < 600 && logged_ns < 60'000'000'000; ++tries) {
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        auto store = study::StudyStore::open(db).value_or_throw();
        for (const study::TrialEvent& e : store->events(1).value_or_throw())
            if (e.kind == study::EventKind::BreakStarted) started = e;
        for (const study::FrameRecord& f : store->frames(1).value_or_throw())
            if (f.frame >= started.frame)
                logged_ns = std::max(logged_ns, f.display_time_ns - started.time_ns);
    }
    kill(pid, SIGKILL);
    int status = 0;
    waitpid(pid, &status, 0);
    read_all(fd);
    ASSERT_GE(logged_ns, 60'000'000'000);
    auto store = study::StudyStore::open(db).value_or_throw();
    // What the killed run logged of the break, as the resume will count it.
    for (const study::FrameRecord& f : store->frames(1).value_or_throw())
        if (f.frame >= started.frame)
            logged_ns = std::max(logged_ns, f.display_time_ns - started.time_ns);
    const std::int64_t resumed_from = store->next_frame_number(1).value_or_throw();
    store.reset();
    std::vector<std::string> resume = {exe, "study", "resume", "--db", db, "--participant", "P1"};
    resume.insert(resume.end(), headset.begin(), headset.end());
    std::string resumed;
    ASSERT_EQ(run_to_end(resume, &resumed, dir.string()), 0) << resumed;
    store = study::StudyStore::open(db).value_or_throw();
    std::int64_t first_resumed_ns = -1;
    for (const study::FrameRecord& f : store->frames(1).value_or_throw())
        if (f.frame >= resumed_from && first_resumed_ns < 0) first_resumed_ns = f.display_time_ns;
    std::int64_t ended_ns = -1;
    int starts = 0;
    for (const study::TrialEvent& e : store->events(1).value_or_throw()) {
        if (e.kind == study::EventKind::BreakStarted) ++starts;
        if (e.kind == study::EventKind::BreakEnded && ended_ns < 0) ended_ns = e.time_ns;
    }
    ASSERT_GE(first_resumed_ns, 0);
    ASSERT_GE(ended_ns, 0);
    EXPECT_EQ(starts, 2);  // one break, its start logged again by the resumed run
    // From its first start: 1800 s, the gap to the resumed run's first frame (1 s at 1 Hz) and
    // up to two frames to the confirmation.
    EXPECT_NEAR(static_cast<double>(ended_ns - started.time_ns) / 1e9, 1801.75, 1.75);
    // The observer confirms as soon as the countdown allows: the resumed run's share of the break
    // is the minimum less what was logged before the kill, to within two frames at 1 Hz.
    const double resumed_s = static_cast<double>(ended_ns - first_resumed_ns) / 1e9;
    const double left_s = 1800.0 - static_cast<double>(logged_ns) / 1e9;
    EXPECT_NEAR(resumed_s, left_s, 2.0) << "logged " << logged_ns / 1e9 << " s of the break";
    std::cout << "the killed run logged " << static_cast<double>(logged_ns) / 1e9
              << " s of the break, the resumed run showed it for " << resumed_s << " s more\n";
    EXPECT_EQ(store->session(1).value_or_throw().status, study::SessionStatus::Completed);
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

// Issue 42, item 5: resume keeps the whole truth. On both paths (headless and the simulated
// headset, whose runtime clock starts again at 10 s in every run) a session is killed in a trial
// after its second switch, in a break, or on its second instruction page, and resumed to its end.
// Then the runs are on one time axis (no event time goes back, a run starts 1 ns after the last
// time stored before it, no frame number is used twice), each break_ended follows a
// break_started, and every trial's outcome and export count what all its runs showed: recounted
// here from its events (and frames), the interrupted trial with 2 runs.
constexpr const char* kTruthProtocol = R"(name = "truth"
scenes = ["beams", "spheres"]
mono_planes = [3, 8, 16]
alternatives = ["stereo", "hybrid"]
practice_trials = 0
[[instructions]]
text = "First page."
[[instructions]]
text = """The second page is long, so that the observer reads it for a while: it reads 40 ms a \
character after 2 s, and the kill comes during that time, as it comes during the break's 20 s. \
The second page is long, so that the observer reads it for a while: it reads 40 ms a character \
after 2 s, and the kill comes during that time, as it comes during the break's 20 s."""
[breaks]
every_trials = 2
min_s = 20
)";

// What a trial's events (and, on a headset, its logged frames) say, counted here on their own:
// per run (runs split at run_started, frames by the runs' first frames), each label's time from
// the event that showed it to the next change, pause, or the trial's last record in the run.
struct Recount {
    int runs = 0;
    int switches = 0;
    std::int64_t on_label_ns[2] = {0, 0};
    std::int64_t viewing_ns = 0;
};

Recount recount(const std::vector<study::TrialEvent>& events,
                const std::vector<study::FrameRecord>& frames,
                const std::vector<study::RunRecord>& runs, int trial) {
    using study::EventKind;
    Recount r;
    int visible = 0;
    int run = 0;  // the run the events belong to: run_started events counted
    std::int64_t since = 0, first = 0, paused = 0, last = 0;
    bool is_paused = false;
    const auto end_run = [&] {
        if (visible == 0) return;
        if (!is_paused) {
            // The trial's frames in this run extend its record.
            const std::int64_t from = runs.at(static_cast<std::size_t>(run - 1)).first_frame;
            const std::int64_t to = static_cast<std::size_t>(run) < runs.size()
                                        ? runs[static_cast<std::size_t>(run)].first_frame
                                        : std::numeric_limits<std::int64_t>::max();
            for (const study::FrameRecord& f : frames)
                if (f.trial_index == trial && f.frame >= from && f.frame < to)
                    last = std::max(last, f.display_time_ns);
            r.on_label_ns[visible - 1] += last - since;
        }
        r.viewing_ns += last - first - paused;
        ++r.runs;
        visible = 0;
    };
    for (const study::TrialEvent& e : events) {
        if (e.kind == EventKind::RunStarted) {
            end_run();
            ++run;
        }
        if (e.trial_index != trial) continue;
        if (!is_paused) last = e.time_ns;
        if (e.kind == EventKind::Shown) {
            visible = e.label;
            since = first = e.time_ns;
            paused = 0;
            is_paused = false;
        } else if (e.kind == EventKind::Switched || e.kind == EventKind::Confirmed) {
            r.on_label_ns[visible - 1] += e.time_ns - since;
            since = e.time_ns;
            if (e.kind == EventKind::Switched) visible = e.label;
            r.switches += e.kind == EventKind::Switched;
            if (e.kind == EventKind::Confirmed) {
                last = e.time_ns;
                r.viewing_ns += last - first - paused;
                ++r.runs;
                visible = 0;
            }
        } else if (e.kind == EventKind::Paused) {
            r.on_label_ns[visible - 1] += e.time_ns - since;
            is_paused = true;
            since = e.time_ns;
        } else if (e.kind == EventKind::Resumed) {
            paused += e.time_ns - since;
            since = last = e.time_ns;
            is_paused = false;
        }
    }
    end_run();
    return r;
}

// The session's runs on one time axis: event times never go back in the order logged; a run's
// run_started is 1 ns after the latest event or frame stored before it; frame numbers are never
// used twice (events in logging order, then frames) and a run's frames follow every earlier one;
// frame times rise with their numbers. `clock_start_ns`: where each run's clock starts (its
// offset puts that at the run's start).
void expect_one_axis(const std::vector<study::TrialEvent>& events,
                     const std::vector<study::FrameRecord>& frames,
                     const std::vector<study::RunRecord>& runs, std::int64_t clock_start_ns) {
    std::int64_t latest = std::numeric_limits<std::int64_t>::min();
    std::int64_t last_frame = -1;
    std::size_t run = 0;
    for (std::size_t i = 0; i < events.size(); ++i) {
        const study::TrialEvent& e = events[i];
        EXPECT_GE(e.time_ns, latest) << "event " << i << " goes back in time";
        if (e.kind == study::EventKind::RunStarted) {
            ASSERT_LT(run, runs.size());
            const study::RunRecord& r = runs[run++];
            for (const study::FrameRecord& f : frames)
                if (f.frame < r.first_frame) latest = std::max(latest, f.display_time_ns);
            if (r.run > 1) {
                EXPECT_EQ(e.time_ns, latest + 1) << "run " << r.run;
            }
            EXPECT_EQ(e.time_ns - r.clock_offset_ns, clock_start_ns) << "run " << r.run;
            EXPECT_GT(r.first_frame, last_frame) << "run " << r.run;
        }
        latest = std::max(latest, e.time_ns);
        if (e.frame < 0) continue;
        EXPECT_GT(e.frame, last_frame) << "event " << i << " repeats or goes back in frames";
        last_frame = e.frame;
    }
    EXPECT_EQ(run, runs.size());
    for (std::size_t i = 1; i < frames.size(); ++i) {
        EXPECT_GT(frames[i].frame, frames[i - 1].frame);
        EXPECT_GT(frames[i].display_time_ns, frames[i - 1].display_time_ns)
            << "frame " << frames[i].frame;
    }
}

// The exported CSV's cells by column name, one map per row.
std::vector<std::map<std::string, std::string>> read_export(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::vector<std::string> header;
    std::vector<std::map<std::string, std::string>> rows;
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::istringstream split(line);
        for (std::string cell; std::getline(split, cell, ',');) cells.push_back(cell);
        if (header.empty()) {
            header = cells;
            continue;
        }
        std::map<std::string, std::string>& row = rows.emplace_back();
        for (std::size_t i = 0; i < header.size() && i < cells.size(); ++i)
            row[header[i]] = cells[i];
    }
    return rows;
}

// A committed line's trial and kind ("trial 3 switched ..."), or none.
std::optional<std::pair<int, std::string>> trial_write(const std::string& what) {
    std::istringstream words(what);
    std::string first, kind;
    int trial = 0;
    words >> first >> trial >> kind;
    if (first != "trial") return std::nullopt;
    return std::make_pair(trial, kind);
}

// The committed line after which the session is killed, and how many committed lines come up
// to it, from a whole run of the same session. In a trial: the second switch of the first trial
// that has three at least, so the kill, which lands a frame or two later on a headset, still
// finds it undecided.
std::pair<int, std::string> kill_point(const std::string& output, const std::string& where) {
    std::vector<std::string> committed;
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);)
        if (line.starts_with("committed ")) committed.push_back(line.substr(10));
    std::map<int, int> switches;  // per trial, in the whole session
    for (const std::string& what : committed)
        if (const auto write = trial_write(what); write && write->second == "switched")
            ++switches[write->first];
    std::map<int, int> seen;
    int k = 0;
    for (const std::string& what : committed) {
        ++k;
        const auto write = trial_write(what);
        if (where == "trial" && write && write->second == "switched" &&
            switches[write->first] >= 3 && ++seen[write->first] == 2)
            return {k, what};
        if (where == "break" && what.starts_with("screen break_started")) return {k, what};
        if (where == "instructions" && what.starts_with("screen instructions_shown page 1"))
            return {k, what};
    }
    return {0, ""};
}

struct TruthPath {
    std::string name;
    std::vector<std::string> options;  // for run and resume alike
    std::int64_t clock_start_ns;       // each run's clock's start
};

void expect_whole_truth(const std::string& db, const std::string& kill_where,
                        const std::string& killed_line, const std::string& tmpdir,
                        std::int64_t clock_start_ns) {
    auto store = study::StudyStore::open(db).value_or_throw();
    EXPECT_EQ(store->session(1).value_or_throw().status, study::SessionStatus::Completed);
    const auto events = store->events(1).value_or_throw();
    const auto frames = store->frames(1).value_or_throw();
    const auto runs = store->runs(1).value_or_throw();
    const auto trials = store->trials(1).value_or_throw();
    ASSERT_EQ(runs.size(), 2u);
    expect_one_axis(events, frames, runs, clock_start_ns);
    expect_breaks_started_before_they_end(events);
    if (!frames.empty()) expect_frame_log_complete(frames, events, runs);
    store.reset();

    const std::string csv = tmpdir + "/" + kill_where + ".csv";
    ASSERT_EQ(run_to_end({MONOPLANE_EXE, "study", "export", "--db", db, "--format", "csv", "--out",
                          csv, "--force"}),
              0);
    const auto rows = read_export(csv);
    ASSERT_EQ(rows.size(), trials.size());
    int interrupted = 0;
    for (std::size_t i = 0; i < trials.size(); ++i) {
        const study::TrialRecord& t = trials[i];
        SCOPED_TRACE("trial " + std::to_string(t.trial.index));
        ASSERT_TRUE(t.decided);
        const Recount c = recount(events, frames, runs, t.trial.index);
        EXPECT_EQ(t.outcome.runs, c.runs);
        EXPECT_EQ(t.outcome.switches, c.switches);
        EXPECT_EQ(t.outcome.time_on_label_ns[0], c.on_label_ns[0]);
        EXPECT_EQ(t.outcome.time_on_label_ns[1], c.on_label_ns[1]);
        EXPECT_EQ(t.outcome.decision_time_ns, c.viewing_ns);
        EXPECT_EQ(rows[i].at("runs"), std::to_string(t.outcome.runs));
        EXPECT_EQ(rows[i].at("switches"), std::to_string(t.outcome.switches));
        if (t.outcome.runs > 1) ++interrupted;
    }
    const auto count = [&](study::EventKind kind, int page = -1) {
        return std::ranges::count_if(
            events, [&](const study::TrialEvent& e) { return e.kind == kind && e.page == page; });
    };
    using study::EventKind;
    if (kill_where == "trial") {
        // The trial killed after its second switch: both runs counted, switches before and after.
        std::istringstream words(killed_line);
        std::string word;
        int trial = -1;
        words >> word >> trial;
        ASSERT_EQ(interrupted, 1);
        const study::TrialRecord& t = trials.at(static_cast<std::size_t>(trial));
        EXPECT_EQ(t.outcome.runs, 2);
        EXPECT_GE(t.outcome.switches, 3);  // 2 before the kill, 1 at least to see label 2 again
        EXPECT_EQ(count(EventKind::BreakStarted), count(EventKind::BreakEnded));
    } else {
        EXPECT_EQ(interrupted, 0);
    }
    if (kill_where == "break") {
        // Its start again in the resumed run: one more start than ends; the whole break, from its
        // first start, lasts at least its minimum on the session's axis.
        EXPECT_EQ(count(EventKind::BreakStarted), count(EventKind::BreakEnded) + 1);
        std::int64_t first_start = -1;
        for (const study::TrialEvent& e : events) {
            if (e.kind == EventKind::BreakStarted && first_start < 0) first_start = e.time_ns;
            if (e.kind == EventKind::BreakEnded) {
                EXPECT_GE(e.time_ns - first_start, 20'000'000'000);
                break;
            }
        }
    }
    if (kill_where == "instructions") {
        EXPECT_EQ(count(EventKind::InstructionsShown, 1), 2);  // again in the resumed run
        EXPECT_EQ(count(EventKind::InstructionsConfirmed, 0), 1);
        EXPECT_EQ(count(EventKind::InstructionsConfirmed, 1), 1);
    }
}

TEST(StudyCrash, AResumedSessionKeepsTheWholeTruthOnBothPaths) {
    namespace fs = std::filesystem;
    const std::string exe = MONOPLANE_EXE;
    const fs::path dir =
        fs::temp_directory_path() / ("monoplane_crash_truth_" + std::to_string(getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    const std::string protocol = (dir / "truth.toml").string();
    std::ofstream(protocol) << kTruthProtocol;
    const std::vector<TruthPath> paths = {
        {"headless", {"--headset", "none", "--trace"}, 0},
        {"headset",
         {"--headset", "simulated", "--window", "off", "--resolution-scale", "0.05", "--sim-rate",
          std::to_string(kSimRateHz), "--neutral-s", "0.2", "--observer", "default", "--detail",
          "test", "--trace"},
         kSimBaseNs - kSimPeriodNs},
    };
    for (const TruthPath& path : paths) {
        SCOPED_TRACE(path.name);
        const auto run_args = [&](const std::string& db) {
            std::vector<std::string> args = {exe,      "study",  "run", "--protocol",
                                             protocol, "--db",   db,    "--participant",
                                             "T1",     "--seed", "11"};
            args.insert(args.end(), path.options.begin(), path.options.end());
            return args;
        };
        std::string whole;
        const std::string reference = (dir / (path.name + "_whole.sqlite")).string();
        ASSERT_EQ(run_to_end(run_args(reference), &whole, dir.string()), 0) << whole;
        for (const std::string where : {"trial", "break", "instructions"}) {
            SCOPED_TRACE(where);
            const auto [k, line] = kill_point(whole, where);
            ASSERT_GT(k, 0) << "the whole session has no kill point '" << where << "':\n" << whole;
            const std::string db = (dir / (path.name + "_" + where + ".sqlite")).string();
            const KilledRun killed = run_and_kill_after(run_args(db), k, dir.string());
            ASSERT_TRUE(killed.killed) << killed.output;
            // Seeded observer, virtual clocks: the same session up to the kill.
            EXPECT_EQ(parse_committed(killed.output).last, line);
            std::vector<std::string> resume = {exe, "study", "resume", "--db", db};
            resume.insert(resume.end(), path.options.begin(), path.options.end());
            std::string resumed;
            ASSERT_EQ(run_to_end(resume, &resumed, dir.string()), 0) << resumed;
            EXPECT_EQ(integrity_check(db), "ok");
            expect_whole_truth(db, where, line, dir.string(), path.clock_start_ns);
        }
    }
    if (!::testing::Test::HasFailure()) fs::remove_all(dir);
}

}  // namespace
}  // namespace monoplane
