// The study database (docs/data.md): WAL, schema version, private files, unique
// pseudonymous participants, exact round trips, resumption, and every failure a clear error that
// leaves earlier data intact (locked, not a database, newer schema, unwritable, disk full).
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "study/session_hold.h"
#include "study/store_schema.h"
#include "study/study_store.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

// A raw second connection, as another process or an sqlite3 shell would hold.
struct RawDb {
    sqlite3* db = nullptr;
    explicit RawDb(const fs::path& path) { EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK); }
    ~RawDb() { sqlite3_close_v2(db); }
    int exec(const std::string& sql) {
        return sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr);
    }
    std::int64_t integer(const std::string& sql) {
        sqlite3_stmt* stmt = nullptr;
        EXPECT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt, nullptr), SQLITE_OK) << sql;
        EXPECT_EQ(sqlite3_step(stmt), SQLITE_ROW) << sql;
        const std::int64_t value = sqlite3_column_int64(stmt, 0);
        sqlite3_finalize(stmt);
        return value;
    }
    std::string text(const std::string& sql) {
        sqlite3_stmt* stmt = nullptr;
        EXPECT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt, nullptr), SQLITE_OK) << sql;
        EXPECT_EQ(sqlite3_step(stmt), SQLITE_ROW) << sql;
        const auto* data = reinterpret_cast<const char*>(sqlite3_column_text(stmt, 0));
        std::string value = data != nullptr ? data : "";
        sqlite3_finalize(stmt);
        return value;
    }
};

// Two practice trials, then blocks of `per_block` distances for spheres and beams.
Schedule make_test_schedule(int participant_index, int per_block = 3) {
    Schedule schedule;
    schedule.seed = 18446744073709551557ull;  // above 2^63: must survive SQLite's signed integers
    schedule.participant_index = participant_index;
    schedule.block_order = {"spheres", "beams"};
    const double planes[] = {1.6, 8.0, 39.5, 3.0, 31.0};
    int index = 0;
    for (int p = 0; p < 2; ++p)
        schedule.trials.push_back({index++, true, -1, "landscape", 5.0, p,
                                   p == 0 ? RenderMode::Stereo : RenderMode::Hybrid,
                                   p == 0 ? RenderMode::Hybrid : RenderMode::Stereo});
    for (int block = 0; block < 2; ++block)
        for (int i = 0; i < per_block; ++i) {
            const int alt = (i + block) % 2;
            schedule.trials.push_back({index++, false, block, schedule.block_order[block],
                                       planes[i % 5], alt,
                                       alt == 0 ? RenderMode::Stereo : RenderMode::Hybrid,
                                       alt == 0 ? RenderMode::Hybrid : RenderMode::Stereo});
        }
    return schedule;
}

SessionInfo make_info(const std::string& code) {
    SessionInfo info;
    info.participant_code = code;
    info.protocol_name = "fink2019";
    info.protocol_hash = 0xcbf29ce484222325ull;
    info.protocol_text = "name = \"fink2019\"\nscenes = [\"beams\"]\n";
    info.software_version = "0.1.0";
    info.hmd = "vive";
    info.runtime = "none";
    info.device = "simulated";
    info.observer = "default";
    info.started_utc = "2024-05-01T09:30:00Z";
    return info;
}

class StudyStoreTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "study_store_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        db_ = dir_ / "study.db";
    }
    void TearDown() override {
        fs::permissions(dir_, fs::perms::owner_all);
        fs::remove_all(dir_);
    }

    std::unique_ptr<StudyStore> open_store(const StoreOptions& options = {}) {
        Result<std::unique_ptr<StudyStore>> store = StudyStore::open(db_, options);
        EXPECT_TRUE(store.ok()) << store.error().message;
        return store.ok() ? std::move(store).value() : nullptr;
    }

    std::int64_t begin(StudyStore& store, const std::string& code) {
        Result<int> index = store.participant_count();
        EXPECT_TRUE(index.ok());
        Result<std::int64_t> id = store.begin_session(make_info(code), make_test_schedule(*index));
        EXPECT_TRUE(id.ok()) << id.error().message;
        return id.ok() ? *id : -1;
    }

    fs::path dir_;
    fs::path db_;
};

mode_t file_mode(const fs::path& path) {
    struct stat st {};
    EXPECT_EQ(::stat(path.c_str(), &st), 0) << path;
    return st.st_mode & 0777;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

TEST_F(StudyStoreTest, CreatesAndReopensWithTheSessionIntact) {
    std::int64_t id = 0;
    {
        auto store = open_store();
        ASSERT_TRUE(store);
        EXPECT_EQ(*store->participant_count(), 0);
        id = begin(*store, "P01");
        EXPECT_EQ(id, 1);
    }
    auto store = open_store();
    ASSERT_TRUE(store);
    EXPECT_EQ(*store->participant_count(), 1);
    const Result<SessionInfo> info = store->session(id);
    ASSERT_TRUE(info.ok()) << info.error().message;
    const SessionInfo expected = make_info("P01");
    EXPECT_EQ(info->id, id);
    EXPECT_EQ(info->participant_code, "P01");
    EXPECT_EQ(info->participant_index, 0);
    EXPECT_EQ(info->protocol_name, expected.protocol_name);
    EXPECT_EQ(info->protocol_hash, expected.protocol_hash);
    EXPECT_EQ(info->protocol_text, expected.protocol_text);
    EXPECT_EQ(info->seed, 18446744073709551557ull);
    EXPECT_EQ(info->software_version, "0.1.0");
    EXPECT_EQ(info->hmd, "vive");
    EXPECT_EQ(info->runtime, "none");
    EXPECT_EQ(info->device, "simulated");
    EXPECT_EQ(info->observer, "default");
    EXPECT_EQ(info->started_utc, "2024-05-01T09:30:00Z");
    EXPECT_EQ(info->status, SessionStatus::Running);
    EXPECT_FALSE(store->session(id + 1).ok());
}

TEST_F(StudyStoreTest, FillsTheStartTimeWhenNotGiven) {
    auto store = open_store();
    SessionInfo info = make_info("P01");
    info.started_utc.clear();
    const Result<std::int64_t> id = store->begin_session(info, make_test_schedule(0));
    ASSERT_TRUE(id.ok()) << id.error().message;
    const std::string started = store->session(*id)->started_utc;
    ASSERT_EQ(started.size(), 20u) << started;  // 2024-05-01T09:30:00Z
    EXPECT_EQ(started[4], '-');
    EXPECT_EQ(started[10], 'T');
    EXPECT_EQ(started[19], 'Z');
}

TEST_F(StudyStoreTest, UsesWalAndRecordsTheSchemaVersion) {
    auto store = open_store();
    ASSERT_TRUE(store);
    RawDb raw(db_);
    EXPECT_EQ(raw.text("PRAGMA journal_mode"), "wal");
    EXPECT_EQ(raw.integer("PRAGMA user_version"), StudyStore::kSchemaVersion);
    EXPECT_EQ(StudyStore::kSchemaVersion, 10);
    EXPECT_EQ(raw.integer("PRAGMA application_id"), 0x4D505354);
    // Version 2 added frames, version 3 scene_files and session_notes, version 5 planned_trials,
    // version 7 participant_variables, version 8 session_runs, version 9 presses (version 10
    // added columns only).
    EXPECT_EQ(raw.integer("SELECT count(*) FROM sqlite_schema WHERE type = 'table'"), 12);
}

TEST_F(StudyStoreTest, FilesAreReadableByTheOwnerOnly) {
    const mode_t old_mask = ::umask(0);  // even with a permissive umask
    auto store = open_store();
    ::umask(old_mask);
    ASSERT_TRUE(store);
    begin(*store, "P01");
    ASSERT_TRUE(store->append_event(1, TrialEvent{EventKind::Shown, 0, 1, 10, 0, -1}).ok());
    EXPECT_EQ(file_mode(db_), 0600u);
    ASSERT_TRUE(fs::exists(db_.string() + "-wal"));
    EXPECT_EQ(file_mode(db_.string() + "-wal"), 0600u);
    EXPECT_EQ(file_mode(db_.string() + "-shm"), 0600u);
}

TEST_F(StudyStoreTest, RefusesASecondSessionForAParticipant) {
    auto store = open_store();
    const std::int64_t first = begin(*store, "P01");
    // Ended: an unfinished one is refused as interrupted (StudyIntegrityTest).
    ASSERT_TRUE(store->set_status(first, SessionStatus::Completed).ok());
    const Result<std::int64_t> again =
        store->begin_session(make_info("P01"), make_test_schedule(1));
    ASSERT_FALSE(again.ok());
    EXPECT_TRUE(contains(again.error().message, "'P01' already has session 1"))
        << again.error().message;
    EXPECT_TRUE(contains(again.error().message, "monoplane study resume")) << again.error().message;
    EXPECT_EQ(*store->participant_count(), 1);

    const std::int64_t second = begin(*store, "P02");
    EXPECT_EQ(second, first + 1);
    EXPECT_EQ(store->session(second)->participant_index, 1);  // the next Latin square row
    EXPECT_EQ(*store->participant_count(), 2);
}

TEST_F(StudyStoreTest, AcceptsPseudonymsOnly) {
    auto store = open_store();
    for (const std::string& bad : std::vector<std::string>{"", "Jane Doe", "J\xc3\xb6rg", "P,01",
                                                           "a\"b", std::string(65, 'x')}) {
        const Result<std::int64_t> id = store->begin_session(make_info(bad), make_test_schedule(0));
        ASSERT_FALSE(id.ok()) << bad;
        EXPECT_TRUE(contains(id.error().message, "1 to 64 letters, digits, '_' or '-'"))
            << id.error().message;
    }
    EXPECT_EQ(*store->participant_count(), 0);
    EXPECT_GT(begin(*store, "P_07-b"), 0);
    EXPECT_GT(begin(*store, std::string(64, 'z')), 0);
}

TEST_F(StudyStoreTest, RefusesAScheduleMadeForAnotherLatinSquareRow) {
    auto store = open_store();
    SessionInfo info = make_info("P01");
    info.participant_number = 2;  // the participant is number 3, the schedule made for number 4
    const Result<std::int64_t> id = store->begin_session(info, make_test_schedule(3));
    ASSERT_FALSE(id.ok());
    EXPECT_TRUE(contains(id.error().message, "made for participant number 4"))
        << id.error().message;
    EXPECT_TRUE(contains(id.error().message, "participant number 3")) << id.error().message;
    EXPECT_EQ(*store->participant_count(), 0);  // nothing half-written
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM sessions"), 0);
}

TEST_F(StudyStoreTest, StoresTheWholeScheduleBeforeTheFirstTrial) {
    auto store = open_store();
    const Schedule schedule = make_test_schedule(0, 5);
    const Result<std::int64_t> id = store->begin_session(make_info("P01"), schedule);
    ASSERT_TRUE(id.ok()) << id.error().message;
    const Result<Schedule> loaded = store->load_schedule(*id);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    EXPECT_EQ(loaded->seed, schedule.seed);
    EXPECT_EQ(loaded->participant_index, 0);
    EXPECT_EQ(loaded->block_order, schedule.block_order);
    ASSERT_EQ(loaded->trials.size(), 12u);
    for (std::size_t i = 0; i < schedule.trials.size(); ++i) {
        const ScheduledTrial& a = schedule.trials[i];
        const ScheduledTrial& b = loaded->trials[i];
        EXPECT_EQ(b.index, a.index);
        EXPECT_EQ(b.practice, a.practice);
        EXPECT_EQ(b.block, a.block);
        EXPECT_EQ(b.scene, a.scene);
        EXPECT_EQ(b.mono_plane, a.mono_plane);  // exact: REAL is a double
        EXPECT_EQ(b.label1_alternative, a.label1_alternative);
        EXPECT_EQ(b.label1_mode, a.label1_mode);
        EXPECT_EQ(b.label2_mode, a.label2_mode);
    }
    EXPECT_EQ(*store->first_undecided_trial(*id), 0);
    EXPECT_FALSE(store->load_schedule(*id + 7).ok());
}

TEST_F(StudyStoreTest, RefusesABadSchedule) {
    auto store = open_store();
    Schedule schedule = make_test_schedule(0);
    schedule.trials[3].index = 9;
    Result<std::int64_t> id = store->begin_session(make_info("P01"), schedule);
    ASSERT_FALSE(id.ok());
    EXPECT_TRUE(contains(id.error().message, "scheduled trial 3")) << id.error().message;
    schedule = make_test_schedule(0);
    schedule.trials.clear();
    EXPECT_FALSE(store->begin_session(make_info("P01"), schedule).ok());
    EXPECT_EQ(*store->participant_count(), 0);
}

TEST_F(StudyStoreTest, EventsAndOutcomesRoundTripExactly) {
    std::int64_t id = 0;
    const std::vector<TrialEvent> events = {
        {EventKind::Shown, 2, 1, 1'000'000'123, 60, -1},
        {EventKind::Switched, 2, 2, 2'500'000'000, 150, -1},
        {EventKind::Refused, 2, 0, 2'600'000'000, -1, -1},
        {EventKind::Paused, 2, 0, 3'000'000'000, -1, -1},
        {EventKind::Resumed, 2, 0, 4'000'000'000, -1, -1},
        {EventKind::Switched, 2, 1, 4'100'000'001, 250, -1},
        {EventKind::Confirmed, 2, 1, 9'223'372'036'854'775'807, 9'000'000'000, -1},
        {EventKind::Aborted, 3, 0, 12, -1, -1},
    };
    TrialOutcome outcome;
    outcome.choice = 1;
    outcome.chosen_mode = RenderMode::Stereo;  // trial 2 shows stereo under label 1
    outcome.valid = true;
    outcome.switches = 2;
    outcome.time_on_label_ns[0] = 1'500'000'000;
    outcome.time_on_label_ns[1] = 1'600'000'001;
    outcome.decision_time_ns = 3'100'000'001;
    {
        auto store = open_store();
        id = begin(*store, "P01");
        for (const TrialEvent& event : events) {
            const Result<void> ok = store->append_event(id, event);
            ASSERT_TRUE(ok.ok()) << ok.error().message;
        }
        const Result<void> ok = store->record_outcome(id, 2, outcome);
        ASSERT_TRUE(ok.ok()) << ok.error().message;
    }
    auto store = open_store();  // what a resumed session would see
    const Result<std::vector<TrialEvent>> loaded = store->events(id);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    ASSERT_EQ(loaded->size(), events.size());
    for (std::size_t i = 0; i < events.size(); ++i) {
        EXPECT_EQ((*loaded)[i].kind, events[i].kind) << i;
        EXPECT_EQ((*loaded)[i].trial_index, events[i].trial_index) << i;
        EXPECT_EQ((*loaded)[i].label, events[i].label) << i;
        EXPECT_EQ((*loaded)[i].time_ns, events[i].time_ns) << i;
        EXPECT_EQ((*loaded)[i].frame, events[i].frame) << i;
        EXPECT_EQ((*loaded)[i].page, -1) << i;
    }
    const Result<std::vector<TrialRecord>> trials = store->trials(id);
    ASSERT_TRUE(trials.ok()) << trials.error().message;
    ASSERT_EQ(trials->size(), 8u);
    const TrialRecord& decided = (*trials)[2];
    EXPECT_EQ(decided.session_id, id);
    EXPECT_EQ(decided.participant_code, "P01");
    EXPECT_EQ(decided.trial.index, 2);
    EXPECT_EQ(decided.trial.scene, "spheres");
    EXPECT_EQ(decided.trial.mono_plane, 1.6);
    EXPECT_TRUE(decided.decided);
    EXPECT_EQ(decided.outcome.choice, 1);
    EXPECT_EQ(decided.outcome.chosen_mode, RenderMode::Stereo);
    EXPECT_TRUE(decided.outcome.valid);
    EXPECT_EQ(decided.outcome.switches, 2);
    EXPECT_EQ(decided.outcome.time_on_label_ns[0], 1'500'000'000);
    EXPECT_EQ(decided.outcome.time_on_label_ns[1], 1'600'000'001);
    EXPECT_EQ(decided.outcome.decision_time_ns, 3'100'000'001);
    EXPECT_FALSE((*trials)[3].decided);
    EXPECT_EQ((*trials)[3].outcome.choice, 0);
}

TEST_F(StudyStoreTest, RefusesEventsAndOutcomesForUnknownTrialsOrBadValues) {
    auto store = open_store();
    const std::int64_t id = begin(*store, "P01");
    Result<void> bad = store->append_event(id, TrialEvent{EventKind::Shown, 99, 1, 5, 0, -1});
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(contains(bad.error().message, "trial 99 of session 1")) << bad.error().message;
    EXPECT_FALSE(store->append_event(id + 1, TrialEvent{EventKind::Shown, 0, 1, 5, 0, -1}).ok());
    EXPECT_FALSE(store->append_event(id, TrialEvent{EventKind::Shown, 0, 3, 5, 0, -1}).ok());
    EXPECT_TRUE(store->events(id)->empty());

    TrialOutcome outcome;
    outcome.choice = 2;
    outcome.chosen_mode = RenderMode::Stereo;  // trial 2: label 2 is hybrid
    bad = store->record_outcome(id, 2, outcome);
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(contains(bad.error().message, "is not label 2's mode 'hybrid'"))
        << bad.error().message;
    outcome.chosen_mode = RenderMode::Hybrid;
    EXPECT_FALSE(store->record_outcome(id, 42, outcome).ok());
    outcome.choice = 0;
    EXPECT_FALSE(store->record_outcome(id, 2, outcome).ok());
    outcome.choice = 2;
    ASSERT_TRUE(store->record_outcome(id, 2, outcome).ok());
    bad = store->record_outcome(id, 2, outcome);
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(contains(bad.error().message, "already decided")) << bad.error().message;
}

TEST_F(StudyStoreTest, ResumesAtTheFirstUndecidedTrial) {
    auto store = open_store();
    const std::int64_t id = begin(*store, "P01");
    const Schedule schedule = *store->load_schedule(id);
    auto decide = [&](int index) {
        const ScheduledTrial& t = schedule.trials[static_cast<std::size_t>(index)];
        TrialOutcome outcome;
        outcome.choice = 2;
        outcome.chosen_mode = t.label2_mode;
        outcome.valid = true;
        outcome.switches = 1;
        const Result<void> ok = store->record_outcome(id, index, outcome);
        ASSERT_TRUE(ok.ok()) << ok.error().message;
    };
    for (int index : {0, 1, 3}) decide(index);
    EXPECT_EQ(*store->first_undecided_trial(id), 2);
    decide(2);
    EXPECT_EQ(*store->first_undecided_trial(id), 4);
    for (int index = 4; index < 8; ++index) decide(index);
    EXPECT_EQ(*store->first_undecided_trial(id), 8);  // all decided: the trial count
    EXPECT_FALSE(store->first_undecided_trial(id + 1).ok());
}

TEST_F(StudyStoreTest, TracksStatusAndTheLatestUnfinishedSession) {
    auto store = open_store();
    EXPECT_FALSE(store->latest_unfinished_session()->has_value());
    const std::int64_t first = begin(*store, "P01");
    const std::int64_t second = begin(*store, "P02");
    EXPECT_EQ(store->latest_unfinished_session()->value(), second);
    ASSERT_TRUE(store->set_status(second, SessionStatus::Completed).ok());
    EXPECT_EQ(store->session(second)->status, SessionStatus::Completed);
    EXPECT_EQ(store->latest_unfinished_session()->value(), first);
    ASSERT_TRUE(store->set_status(first, SessionStatus::Paused).ok());
    EXPECT_EQ(store->latest_unfinished_session()->value(), first);
    ASSERT_TRUE(store->set_status(first, SessionStatus::Completed).ok());
    EXPECT_FALSE(store->latest_unfinished_session()->has_value());
    EXPECT_FALSE(store->set_status(99, SessionStatus::Aborted).ok());
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM sessions WHERE ended_utc IS NOT NULL"), 2);
    EXPECT_EQ(session_status_name(SessionStatus::Aborted), "aborted");
}

TEST_F(StudyStoreTest, RecordsQuestionnaireAnswersTheLatestCounting) {
    auto store = open_store();
    const std::int64_t id = begin(*store, "P01");
    ASSERT_TRUE(store->record_answer(id, 0, "I noticed differences", 3).ok());
    ASSERT_TRUE(store->record_answer(id, 1, "It was comfortable", 6).ok());
    ASSERT_TRUE(store->record_answer(id, 0, "I noticed differences", 5).ok());  // asked again
    EXPECT_FALSE(store->record_answer(id, 2, "x", 0).ok());
    EXPECT_FALSE(store->record_answer(id + 1, 2, "x", 1).ok());
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM answers"), 2);
    EXPECT_EQ(raw.integer("SELECT answer FROM answers WHERE item = 0"), 5);
    EXPECT_EQ(raw.text("SELECT text FROM answers WHERE item = 1"), "It was comfortable");
}

TEST_F(StudyStoreTest, RefusesANewerSchemaWithoutTouchingIt) {
    { ASSERT_TRUE(open_store()); }
    {
        RawDb raw(db_);
        ASSERT_EQ(
            raw.exec("PRAGMA user_version = " + std::to_string(StudyStore::kSchemaVersion + 1)),
            SQLITE_OK);
    }
    const Result<std::unique_ptr<StudyStore>> store = StudyStore::open(db_);
    ASSERT_FALSE(store.ok());
    const std::string& message = store.error().message;
    EXPECT_TRUE(
        contains(message, "schema version 11, newer than this build of monoplane knows (10)"))
        << message;
    EXPECT_TRUE(contains(message, db_.string())) << message;
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("PRAGMA user_version"), 11);
    EXPECT_TRUE(fs::exists(db_));
}

TEST_F(StudyStoreTest, ALockedDatabaseIsAClearErrorNamingTheFile) {
    StoreOptions quick;
    quick.busy_timeout_ms = 100;
    auto store = open_store(quick);
    const std::int64_t id = begin(*store, "P01");
    {
        RawDb other(db_);
        ASSERT_EQ(other.exec("BEGIN EXCLUSIVE"), SQLITE_OK);  // in WAL: holds the write lock
        const Result<void> blocked =
            store->append_event(id, TrialEvent{EventKind::Shown, 0, 1, 5, 0, -1});
        ASSERT_FALSE(blocked.ok());
        EXPECT_TRUE(contains(blocked.error().message, "'" + db_.string() + "' is locked"))
            << blocked.error().message;
        const Result<std::int64_t> session =
            store->begin_session(make_info("P02"), make_test_schedule(1));
        ASSERT_FALSE(session.ok());
        EXPECT_TRUE(contains(session.error().message, "is locked")) << session.error().message;
        // Readers are not blocked (WAL): the experimenter's view and an export keep working.
        EXPECT_EQ(*store->participant_count(), 1);
        ASSERT_EQ(other.exec("ROLLBACK"), SQLITE_OK);
    }
    ASSERT_TRUE(store->append_event(id, TrialEvent{EventKind::Shown, 0, 1, 5, 0, -1}).ok());
    EXPECT_EQ(store->events(id)->size(), 1u);
    EXPECT_EQ(*store->participant_count(), 1);
}

TEST_F(StudyStoreTest, OpeningADatabaseLockedExclusivelyIsAClearError) {
    RawDb other(db_);  // a rollback-journal database: an exclusive lock blocks readers too
    ASSERT_EQ(other.exec("CREATE TABLE t (x); BEGIN EXCLUSIVE; INSERT INTO t VALUES (1);"),
              SQLITE_OK);
    StoreOptions quick;
    quick.busy_timeout_ms = 100;
    const Result<std::unique_ptr<StudyStore>> store = StudyStore::open(db_, quick);
    ASSERT_FALSE(store.ok());
    EXPECT_TRUE(contains(store.error().message, "'" + db_.string() + "' is locked"))
        << store.error().message;
    ASSERT_EQ(other.exec("COMMIT"), SQLITE_OK);
}

TEST_F(StudyStoreTest, RefusesAFileThatIsNotADatabase) {
    const std::string text(8192, 'x');
    std::ofstream(db_) << text;
    const Result<std::unique_ptr<StudyStore>> store = StudyStore::open(db_);
    ASSERT_FALSE(store.ok());
    EXPECT_TRUE(contains(store.error().message, "'" + db_.string() + "' is not a SQLite database"))
        << store.error().message;
    std::ifstream in(db_);
    const std::string after((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(after, text);  // untouched
}

TEST_F(StudyStoreTest, RefusesAnotherProgramsDatabase) {
    {
        RawDb other(db_);
        ASSERT_EQ(other.exec("CREATE TABLE photos (id INTEGER)"), SQLITE_OK);
    }
    const Result<std::unique_ptr<StudyStore>> store = StudyStore::open(db_);
    ASSERT_FALSE(store.ok());
    EXPECT_TRUE(contains(store.error().message, "another program")) << store.error().message;
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM sqlite_schema"), 1);
    EXPECT_EQ(raw.integer("PRAGMA user_version"), 0);
}

TEST_F(StudyStoreTest, AnUnwritableDirectoryIsAClearError) {
    const fs::path locked_dir = dir_ / "readonly";
    fs::create_directory(locked_dir);
    fs::permissions(locked_dir, fs::perms::owner_read | fs::perms::owner_exec);
    fs::path path = locked_dir / "study.db";
    if (::access(locked_dir.c_str(), W_OK) == 0)
        path = "/sys/monoplane_study.db";  // root ignores modes
    const Result<std::unique_ptr<StudyStore>> store = StudyStore::open(path);
    ASSERT_FALSE(store.ok());
    const std::string& message = store.error().message;
    EXPECT_TRUE(contains(message, "cannot create study database '" + path.string() + "'"))
        << message;
    EXPECT_TRUE(contains(message, "ermission denied")) << message;
    EXPECT_FALSE(fs::exists(path));

    const Result<std::unique_ptr<StudyStore>> missing =
        StudyStore::open(dir_ / "no" / "such" / "dir.db");
    ASSERT_FALSE(missing.ok());
    EXPECT_TRUE(contains(missing.error().message, "No such file or directory"))
        << missing.error().message;
}

TEST_F(StudyStoreTest, AFullDiskFailsTheWriteAndKeepsEarlierData) {
    std::int64_t id = 0;
    {
        auto store = open_store();
        id = begin(*store, "P01");
    }
    // The database may not grow: writes fail as on a full disk once the last page is used up.
    StoreOptions full;
    full.max_page_count = 1;  // SQLite clamps it to the current size
    int written = 0;
    std::string message;
    {
        auto store = open_store(full);
        ASSERT_TRUE(store);
        for (; written < 100000; ++written) {
            const Result<void> ok = store->append_event(
                id,
                TrialEvent{EventKind::Switched, 2, 1 + written % 2, 1000 + written, written, -1});
            if (!ok) {
                message = ok.error().message;
                break;
            }
        }
        ASSERT_LT(written, 100000) << "the limit never took effect";
        EXPECT_GT(written, 0) << "the last page had room for some events";
        EXPECT_TRUE(contains(message, "disk full while appending a 'switched' event")) << message;
        EXPECT_TRUE(contains(message, db_.string())) << message;

        // A whole session does not fit either, and nothing of it stays behind.
        const Result<std::int64_t> session =
            store->begin_session(make_info("P02"), make_test_schedule(1, 400));
        ASSERT_FALSE(session.ok());
        EXPECT_TRUE(contains(session.error().message, "disk full while storing the schedule"))
            << session.error().message;
        EXPECT_EQ(*store->participant_count(), 1);
    }
    auto store = open_store();  // space again
    const Result<std::vector<TrialEvent>> events = store->events(id);
    ASSERT_TRUE(events.ok()) << events.error().message;
    ASSERT_EQ(events->size(), static_cast<std::size_t>(written));
    if (written > 0) {
        EXPECT_EQ(events->back().time_ns, 1000 + written - 1);
        EXPECT_EQ(events->back().frame, written - 1);
    }
    EXPECT_EQ(*store->participant_count(), 1);
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM trials"), 8);
    EXPECT_EQ(raw.text("PRAGMA integrity_check"), "ok");
    ASSERT_TRUE(store->append_event(id, TrialEvent{EventKind::Confirmed, 2, 1, 5, 7, -1}).ok());
}

}  // namespace
}  // namespace monoplane::study

namespace monoplane::study {
namespace {

FrameRecord make_frame(std::int64_t index, std::optional<int> trial) {
    FrameRecord f;
    f.frame = index;
    f.trial_index = trial;
    f.shown = trial ? "label1" : "neutral";
    f.display_time_ns = 1'000'000'000 + index * 11'111'111;
    f.cpu_ms = 2.5 + static_cast<double>(index);
    f.missed = index == 3;
    if (trial) f.head = std::array<double, 7>{0.25, 1.6, -3.0, 0.5, 0.5, -0.5, 0.5};
    return f;
}

TEST_F(StudyStoreTest, TheFrameLogBecomesDurableWithTheNextEvent) {
    auto store = open_store();
    const std::int64_t id = begin(*store, "P01");
    store->queue_frame(id, make_frame(2, std::nullopt));
    store->queue_frame(id, make_frame(3, 0));
    RawDb raw(db_);
    // Queued rows wait in memory: nothing on disk yet.
    EXPECT_EQ(raw.integer("SELECT count(*) FROM frames"), 0);
    const Result<void> shown = store->append_event(id, {EventKind::Shown, 0, 1, 1'050, 3, -1});
    ASSERT_TRUE(shown.ok()) << shown.error().message;
    // The event's transaction carried them.
    EXPECT_EQ(raw.integer("SELECT count(*) FROM frames"), 2);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM frames WHERE gpu_ms IS NULL"), 2);
    // A GPU time known later fills its row; flush_frames writes without an event.
    store->queue_frame_gpu_ms(id, 3, 7.25, 12.5);  // a hybrid frame's m (schema 4)
    store->queue_frame(id, make_frame(4, 0));
    ASSERT_TRUE(store->flush_frames().ok());
    EXPECT_EQ(raw.integer("SELECT count(*) FROM frames"), 3);
    const Result<std::vector<FrameRecord>> frames = store->frames(id);
    ASSERT_TRUE(frames.ok()) << frames.error().message;
    ASSERT_EQ(frames->size(), 3u);
    const FrameRecord& neutral = (*frames)[0];
    EXPECT_EQ(neutral.frame, 2);
    EXPECT_FALSE(neutral.trial_index);
    EXPECT_EQ(neutral.shown, "neutral");
    EXPECT_FALSE(neutral.head);
    EXPECT_FALSE(neutral.gpu_ms);
    const FrameRecord& trial = (*frames)[1];
    EXPECT_EQ(trial.trial_index, 0);
    EXPECT_EQ(trial.display_time_ns, 1'033'333'333);
    EXPECT_EQ(trial.cpu_ms, 5.5);
    ASSERT_TRUE(trial.gpu_ms);
    EXPECT_EQ(*trial.gpu_ms, 7.25);
    EXPECT_EQ(trial.mono_plane, 12.5);
    EXPECT_FALSE(neutral.mono_plane);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM frames WHERE mono_plane = 12.5"), 1);
    EXPECT_TRUE(trial.missed);
    ASSERT_TRUE(trial.head);
    EXPECT_EQ(*trial.head, (std::array<double, 7>{0.25, 1.6, -3.0, 0.5, 0.5, -0.5, 0.5}));
    EXPECT_FALSE((*frames)[2].missed);
    EXPECT_FALSE(trial.pipelines_created);  // not logged: NULL (schema 6)
    EXPECT_FALSE(trial.driver_compiles);
    // A bad row fails the write that carries it, and the event with it: nothing half-written.
    FrameRecord bad = make_frame(5, 0);
    bad.shown = "sideways";
    store->queue_frame(id, bad);
    EXPECT_FALSE(store->append_event(id, {EventKind::Switched, 0, 2, 1'060, 5, -1}).ok());
    EXPECT_EQ(raw.integer("SELECT count(*) FROM events WHERE kind = 'switched'"), 0);
}

// Schema 6: what each frame built. The driver's count is NULL where it cannot be counted.
TEST_F(StudyStoreTest, TheFrameLogKeepsWhatEachFrameBuilt) {
    auto store = open_store();
    const std::int64_t id = begin(*store, "P01");
    FrameRecord first = make_frame(0, std::nullopt);
    first.pipelines_created = 41;
    first.driver_compiles = 57;
    FrameRecord steady = make_frame(1, 0);
    steady.pipelines_created = 0;
    steady.driver_compiles = 0;
    FrameRecord uncounted = make_frame(2, 0);
    uncounted.pipelines_created = 0;
    store->queue_frame(id, first);
    store->queue_frame(id, steady);
    store->queue_frame(id, uncounted);
    ASSERT_TRUE(store->flush_frames().ok());
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT sum(pipelines_created) FROM frames"), 41);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM frames WHERE driver_compiles IS NULL"), 1);
    const Result<std::vector<FrameRecord>> frames = store->frames(id);
    ASSERT_TRUE(frames.ok()) << frames.error().message;
    ASSERT_EQ(frames->size(), 3u);
    EXPECT_EQ((*frames)[0].pipelines_created, 41);
    EXPECT_EQ((*frames)[0].driver_compiles, 57);
    EXPECT_EQ((*frames)[1].driver_compiles, 0);
    EXPECT_EQ((*frames)[2].pipelines_created, 0);
    EXPECT_FALSE((*frames)[2].driver_compiles);
    // A negative count is no count: the row is refused.
    FrameRecord negative = make_frame(3, 0);
    negative.driver_compiles = -1;
    store->queue_frame(id, negative);
    EXPECT_FALSE(store->flush_frames().ok());
}

// Schema 10: the eye tracker's sample per frame where gaze was recorded. A valid sample keeps its
// direction; an invalid one (a blink) has none; a frame without gaze is NULL throughout.
TEST_F(StudyStoreTest, TheFrameLogKeepsTheGazeSampleOfEachFrame) {
    auto store = open_store();
    const std::int64_t id = begin(*store, "P01");
    FrameRecord looking = make_frame(0, 0);
    looking.gaze = GazeRecord{true, {0.24253562503633297, 0.0, -0.9701425001453319}};
    looking.gaze_point = GazePointRecord{.error_arcmin = 2.5, .depth_m = 12.0, .mono_plane_m = 8};
    FrameRecord blinking = make_frame(1, 0);
    blinking.gaze = GazeRecord{false, {0.5, 0.5, 0.5}};  // what a blink's pose said: not kept
    const FrameRecord unrecorded = make_frame(2, 0);
    FrameRecord at_the_sky = looking;
    at_the_sky.frame = 3;
    at_the_sky.gaze_point = GazePointRecord{.error_arcmin = 7.25, .mono_plane_m = 3};
    for (const FrameRecord& f : {looking, blinking, unrecorded, at_the_sky})
        store->queue_frame(id, f);
    ASSERT_TRUE(store->flush_frames().ok());
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM frames WHERE gaze_valid = 1"), 2);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM frames WHERE gaze_valid = 0 AND gaze_dir_x IS "
                          "NULL AND gaze_dir_y IS NULL AND gaze_dir_z IS NULL"),
              1);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM frames WHERE gaze_valid IS NULL AND "
                          "gaze_error_arcmin IS NULL"),
              1);
    const Result<std::vector<FrameRecord>> frames = store->frames(id);
    ASSERT_TRUE(frames.ok()) << frames.error().message;
    ASSERT_EQ(frames->size(), 4u);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM frames WHERE gaze_error_arcmin = 7.25 AND "
                          "gaze_depth_m IS NULL AND gaze_mono_plane_m = 3"),
              1);
    ASSERT_TRUE((*frames)[0].gaze_point);
    EXPECT_EQ((*frames)[0].gaze_point->error_arcmin, 2.5);
    EXPECT_EQ((*frames)[0].gaze_point->depth_m, 12.0);
    EXPECT_TRUE((*frames)[0].gaze_point->beyond_mono_plane());
    ASSERT_TRUE((*frames)[3].gaze_point);
    EXPECT_FALSE((*frames)[3].gaze_point->depth_m);  // the sky
    EXPECT_TRUE((*frames)[3].gaze_point->beyond_mono_plane());
    ASSERT_TRUE((*frames)[0].gaze);
    EXPECT_TRUE((*frames)[0].gaze->valid);
    EXPECT_EQ((*frames)[0].gaze->direction, looking.gaze->direction);
    ASSERT_TRUE((*frames)[1].gaze);
    EXPECT_FALSE((*frames)[1].gaze->valid);
    EXPECT_FALSE((*frames)[2].gaze);
    EXPECT_FALSE((*frames)[2].gaze_point);
}

TEST_F(StudyStoreTest, AResumedRunsFramesContinueAfterEveryNumberUsed) {
    auto store = open_store();
    const std::int64_t id = begin(*store, "P01");
    EXPECT_EQ(*store->next_frame_number(id), 0);
    ASSERT_TRUE(store->append_event(id, {EventKind::Shown, 0, 1, 1'050, 9, -1}).ok());
    EXPECT_EQ(*store->next_frame_number(id), 10);  // an event names frame 9
    store->queue_frame(id, make_frame(12, 0));
    ASSERT_TRUE(store->flush_frames().ok());
    EXPECT_EQ(*store->next_frame_number(id), 13);  // the log reaches frame 12
    // Another session's numbers do not count.
    const std::int64_t other = begin(*store, "P02");
    EXPECT_EQ(*store->next_frame_number(other), 0);
}

// Each run of a session (its start, each resume) gets its row and a run_started event: numbered
// on, with this process's host and pid, its frames after every number used and its clock after
// the latest time stored, so a runtime whose clock started again near 0 continues the session's
// axis. The frames still queued are the earlier run's and go first.
TEST_F(StudyStoreTest, EachRunIsPlacedAfterEverythingStored) {
    auto store = open_store();
    const std::int64_t id = begin(*store, "P01");
    EXPECT_TRUE(store->runs(id)->empty());
    const Result<RunStart> first = store->begin_run(id, {.runtime = "", .clock_start_ns = 5'000});
    ASSERT_TRUE(first.ok()) << first.error().message;
    EXPECT_EQ(first->run, 1);
    EXPECT_EQ(first->first_frame, 0);
    EXPECT_EQ(first->clock_offset_ns, 0);  // the first run's clock is the session's axis
    EXPECT_EQ(first->start_ns, 5'000);
    ASSERT_TRUE(store->append_event(id, {EventKind::Shown, 0, 1, 6'000, 3, -1, ""}).ok());
    FrameRecord late = make_frame(4, 0);
    late.display_time_ns = 9'000;
    store->queue_frame(id, late);

    const Result<RunStart> second =
        store->begin_run(id, {.runtime = "simulated", .clock_start_ns = 100});
    ASSERT_TRUE(second.ok()) << second.error().message;
    EXPECT_EQ(second->run, 2);
    EXPECT_EQ(second->first_frame, 5);
    EXPECT_EQ(second->start_ns, 9'001);
    EXPECT_EQ(second->clock_offset_ns, 8'901);
    EXPECT_EQ(second->session_time(200), 9'101);
    EXPECT_EQ(second->session_time(50), 9'001);  // nothing of a run before its start
    EXPECT_EQ(store->frames(id)->size(), 1u);

    const std::vector<RunRecord> runs = store->runs(id).value_or_throw();
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].run, 1);
    EXPECT_EQ(runs[0].runtime, "none");  // the session's
    EXPECT_EQ(runs[1].runtime, "simulated");
    for (const RunRecord& r : runs) {
        EXPECT_EQ(r.host, host_name());
        EXPECT_EQ(r.pid, static_cast<long>(::getpid()));
        EXPECT_EQ(r.started_utc.size(), 20u);
    }
    EXPECT_EQ(runs[1].first_frame, 5);
    EXPECT_EQ(runs[1].clock_offset_ns, 8'901);
    std::vector<std::int64_t> started;
    for (const TrialEvent& e : store->events(id).value_or_throw()) {
        if (e.kind != EventKind::RunStarted) continue;
        EXPECT_EQ(e.trial_index, -1);
        EXPECT_EQ(e.frame, -1);
        started.push_back(e.time_ns);
    }
    EXPECT_EQ(started, (std::vector<std::int64_t>{5'000, 9'001}));

    // A session that logged before runs were recorded (schema 7) had its run 1 then.
    const std::int64_t older = begin(*store, "P02");
    ASSERT_TRUE(store->append_event(older, {EventKind::Shown, 0, 1, 70, 2, -1, ""}).ok());
    const RunStart resumed = store->begin_run(older, {.clock_start_ns = 0}).value_or_throw();
    EXPECT_EQ(resumed.run, 2);
    EXPECT_EQ(resumed.first_frame, 3);
    EXPECT_EQ(resumed.start_ns, 71);

    const Result<RunStart> unknown = store->begin_run(id + 10, {});
    ASSERT_FALSE(unknown.ok());
    EXPECT_TRUE(contains(unknown.error().message, "no session")) << unknown.error().message;
    EXPECT_FALSE(store->runs(id + 10).ok());
}

// The outcome says how many runs showed its trial; an undecided trial reads as 1.
TEST_F(StudyStoreTest, AnOutcomeKeepsTheRunsThatShowedItsTrial) {
    auto store = open_store();
    const std::int64_t id = begin(*store, "P01");
    TrialOutcome outcome;
    outcome.choice = 2;
    outcome.chosen_mode = RenderMode::Hybrid;  // trial 0 shows hybrid under label 2
    outcome.switches = 7;
    outcome.runs = 3;
    ASSERT_TRUE(store->record_outcome(id, 0, outcome).ok());
    outcome.runs = 0;
    const Result<void> none = store->record_outcome(id, 1, outcome);
    ASSERT_FALSE(none.ok());
    EXPECT_TRUE(contains(none.error().message, "0 runs")) << none.error().message;
    const std::vector<TrialRecord> trials = store->trials(id).value_or_throw();
    EXPECT_EQ(trials[0].outcome.runs, 3);
    EXPECT_EQ(trials[0].outcome.switches, 7);
    EXPECT_FALSE(trials[1].decided);
    EXPECT_EQ(trials[1].outcome.runs, 1);
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT runs FROM trials WHERE trial_index = 0"), 3);
    EXPECT_EQ(raw.integer("SELECT runs FROM trials WHERE trial_index = 1"), 1);
}

TEST_F(StudyStoreTest, StoresTheSessionsRenderSettings) {
    auto store = open_store();
    SessionInfo info = make_info("P01");
    info.render = {"taa", "stereo", "medium"};
    const Result<std::int64_t> id = store->begin_session(info, make_test_schedule(0));
    ASSERT_TRUE(id.ok()) << id.error().message;
    EXPECT_EQ(store->session(*id)->render, (RenderSettings{"taa", "stereo", "medium"}));
    info = make_info("P02");
    info.render.detail.clear();  // not recorded: NULL, read back as ""
    const Result<std::int64_t> second = store->begin_session(info, make_test_schedule(1));
    ASSERT_TRUE(second.ok()) << second.error().message;
    EXPECT_EQ(store->session(*second)->render, (RenderSettings{"none", "off", ""}));
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM sessions WHERE render_detail IS NULL"), 1);
}

// A database written by the first release (schema version 1, made here from its schema and
// rows as that release wrote them) opens, migrates, resumes and exports.
TEST_F(StudyStoreTest, MigratesAVersion1DatabaseForward) {
    {
        RawDb raw(db_);
        ASSERT_EQ(raw.exec(std::string(store_migrations()[0])), SQLITE_OK);
        ASSERT_EQ(raw.exec("PRAGMA application_id = " + std::to_string(kStoreApplicationId)),
                  SQLITE_OK);
        ASSERT_EQ(raw.exec("PRAGMA user_version = 1"), SQLITE_OK);
        const char* rows = R"sql(
INSERT INTO participants VALUES (1, 'P07', 0, '2026-11-01T10:00:00Z');
INSERT INTO sessions (id, participant_id, protocol_name, protocol_hash, protocol_text, seed,
    block_order, software_version, hmd, runtime, device, observer, started_utc, status)
    VALUES (1, 1, 'demo', '0000000000000001', 'name = "demo"', '11', 'beams',
            'monoplane 0.1.0', 'vive', 'none', 'none', 'default', '2026-11-01T10:00:01Z',
            'running');
INSERT INTO trials (session_id, trial_index, practice, block, scene, mono_plane,
    label1_alternative, label1_mode, label2_mode, decided, choice, chosen_mode, valid,
    switches, time_label1_ns, time_label2_ns, decision_time_ns, decided_utc)
    VALUES (1, 0, 0, 0, 'beams', 8.0, 0, 'stereo', 'hybrid', 1, 2, 'hybrid', 1, 3,
            1000000000, 2000000000, 3000000000, '2026-11-01T10:00:05Z');
INSERT INTO trials (session_id, trial_index, practice, block, scene, mono_plane,
    label1_alternative, label1_mode, label2_mode)
    VALUES (1, 1, 0, 0, 'beams', 3.0, 1, 'hybrid', 'stereo');
INSERT INTO events (session_id, trial_index, kind, label, time_ns, frame)
    VALUES (1, 0, 'shown', 1, 5, -1);
)sql";
        ASSERT_EQ(raw.exec(rows), SQLITE_OK) << sqlite3_errmsg(raw.db);
    }
    auto store = open_store();
    ASSERT_TRUE(store);
    {
        RawDb raw(db_);
        EXPECT_EQ(raw.integer("PRAGMA user_version"), StudyStore::kSchemaVersion);
    }
    const Result<SessionInfo> info = store->session(1);
    ASSERT_TRUE(info.ok()) << info.error().message;
    EXPECT_EQ(info->participant_code, "P07");
    EXPECT_EQ(info->render, (RenderSettings{"none", "off", ""}));  // what version 1 rendered
    // Resume: the schedule and the first undecided trial.
    ASSERT_TRUE(store->load_schedule(1).ok());
    EXPECT_EQ(*store->first_undecided_trial(1), 1);
    TrialOutcome outcome;
    outcome.choice = 1;
    outcome.chosen_mode = RenderMode::Hybrid;
    outcome.valid = true;
    ASSERT_TRUE(store->record_outcome(1, 1, outcome).ok());
    const Result<std::vector<TrialRecord>> trials = store->trials();
    ASSERT_TRUE(trials.ok());
    ASSERT_EQ(trials->size(), 2u);
    EXPECT_TRUE((*trials)[0].decided);
    EXPECT_EQ((*trials)[0].outcome.switches, 3);
    EXPECT_TRUE((*trials)[1].decided);
    // The new table works on the migrated file.
    store->queue_frame(1, make_frame(1, 1));
    ASSERT_TRUE(store->flush_frames().ok());
    EXPECT_EQ(store->frames(1)->size(), 1u);
}

// Imported scenes (schema version 3): the files each was read from, with size and SHA-256.
constexpr std::string_view kDigestA =
    "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad";
constexpr std::string_view kDigestB =
    "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855";

// make_test_schedule with its second block showing the glTF file "models/room.gltf".
Schedule make_imported_schedule(int participant_index) {
    Schedule schedule = make_test_schedule(participant_index);
    schedule.block_order[1] = "models/room.gltf";
    for (ScheduledTrial& t : schedule.trials)
        if (t.block == 1) t.scene = "models/room.gltf";
    return schedule;
}

std::vector<SceneFileRecord> room_records() {
    return {{"models/room.gltf", 0, "/study/models/room.gltf", {1234, std::string(kDigestA)}},
            {"models/room.gltf", 1, "/study/models/room.bin", {0, std::string(kDigestB)}}};
}

TEST_F(StudyStoreTest, StoresTheSceneFilesWithTheSessionDurably) {
    SessionInfo info = make_info("P01");
    info.scene_files = room_records();
    std::int64_t id = 0;
    {
        auto store = open_store();
        const Result<std::int64_t> begun = store->begin_session(info, make_imported_schedule(0));
        ASSERT_TRUE(begun.ok()) << begun.error().message;
        id = *begun;
        // Committed with the session: another connection sees the rows while the store is open.
        RawDb raw(db_);
        EXPECT_EQ(raw.integer("SELECT count(*) FROM scene_files WHERE session_id = " +
                              std::to_string(id)),
                  2);
        EXPECT_EQ(raw.text("SELECT sha256 FROM scene_files WHERE file_index = 0"), kDigestA);
        EXPECT_EQ(raw.integer("SELECT size_bytes FROM scene_files WHERE file_index = 0"), 1234);
        EXPECT_EQ(raw.text("SELECT path FROM scene_files WHERE file_index = 1"),
                  "/study/models/room.bin");
    }
    auto store = open_store();
    const Result<SessionInfo> read = store->session(id);
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->scene_files, room_records());
    EXPECT_TRUE(read->notes.empty());
    // The trials keep the label as written.
    EXPECT_EQ(store->load_schedule(id)->trials.back().scene, "models/room.gltf");
}

TEST_F(StudyStoreTest, RefusesSceneFilesThatCannotBeEvidenceWritingNothing) {
    auto store = open_store();
    const auto refused = [&](std::vector<SceneFileRecord> records, const std::string& why) {
        SessionInfo info = make_info("P01");
        info.scene_files = std::move(records);
        const Result<std::int64_t> id = store->begin_session(info, make_imported_schedule(0));
        EXPECT_FALSE(id.ok()) << why;
        if (!id.ok()) {
            EXPECT_TRUE(contains(id.error().message, why)) << id.error().message;
        }
    };
    refused({}, "scene 'models/room.gltf' names a glTF file but no record of the file itself");
    refused({room_records()[1]}, "no record of the file itself (file 0)");
    std::vector<SceneFileRecord> records = room_records();
    records[1].path = "models/room.bin";
    refused(records, "the path 'models/room.bin' is not absolute");
    records = room_records();
    records[0].digest.sha256[3] = 'F';
    refused(records, "is not a SHA-256 digest in 64 lowercase hex digits");
    records = room_records();
    records[1].scene = "hall.glb";
    refused(records, "scene file record of 'hall.glb' (file 1): the schedule shows no such scene");
    records = room_records();
    records[1].file_index = 0;
    refused(records, "scene file record of 'models/room.gltf' (file 0) is listed twice");
    EXPECT_EQ(*store->participant_count(), 0);
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM scene_files"), 0);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM sessions"), 0);
}

TEST_F(StudyStoreTest, SessionNotesAreKeptInOrder) {
    auto store = open_store();
    const std::int64_t id = begin(*store, "P01");
    ASSERT_TRUE(store->add_session_note(id, "first").ok());
    ASSERT_TRUE(store->add_session_note(id, "second, with \"quotes\"").ok());
    const Result<SessionInfo> info = store->session(id);
    ASSERT_TRUE(info.ok()) << info.error().message;
    ASSERT_EQ(info->notes.size(), 2u);
    EXPECT_EQ(info->notes[0].text, "first");
    EXPECT_EQ(info->notes[1].text, "second, with \"quotes\"");
    EXPECT_EQ(info->notes[0].noted_utc.size(), 20u);  // YYYY-MM-DDThh:mm:ssZ
    EXPECT_FALSE(store->add_session_note(id, "").ok());
    const Result<void> unknown = store->add_session_note(id + 1, "x");
    ASSERT_FALSE(unknown.ok());
    EXPECT_TRUE(contains(unknown.error().message, "no session " + std::to_string(id + 1)))
        << unknown.error().message;
}

// A database of schema version 2 (made here from versions 1 and 2 of the schema, with rows as
// that release wrote them: a session, its trials, an event, a frame) opens, migrates to version
// 3, resumes, exports, and its new tables take rows.
TEST_F(StudyStoreTest, MigratesAVersion2DatabaseForward) {
    {
        RawDb raw(db_);
        ASSERT_EQ(raw.exec(std::string(store_migrations()[0])), SQLITE_OK);
        ASSERT_EQ(raw.exec(std::string(store_migrations()[1])), SQLITE_OK);
        ASSERT_EQ(raw.exec("PRAGMA application_id = " + std::to_string(kStoreApplicationId)),
                  SQLITE_OK);
        ASSERT_EQ(raw.exec("PRAGMA user_version = 2"), SQLITE_OK);
        const char* rows = R"sql(
INSERT INTO participants VALUES (1, 'P08', 0, '2027-01-01T10:00:00Z');
INSERT INTO sessions (id, participant_id, protocol_name, protocol_hash, protocol_text, seed,
    block_order, software_version, hmd, runtime, device, observer, started_utc, status,
    render_anti_aliasing, render_ssao, render_detail)
    VALUES (1, 1, 'demo', '0000000000000002', 'name = "demo"', '12', 'spheres',
            'monoplane 0.1.0', 'vive', 'simulated', 'llvmpipe', 'default',
            '2027-01-01T10:00:01Z', 'running', 'taa', 'off', 'test');
INSERT INTO trials (session_id, trial_index, practice, block, scene, mono_plane,
    label1_alternative, label1_mode, label2_mode)
    VALUES (1, 0, 0, 0, 'spheres', 8.0, 0, 'stereo', 'hybrid');
INSERT INTO events (session_id, trial_index, kind, label, time_ns, frame)
    VALUES (1, 0, 'shown', 1, 5, 3);
INSERT INTO frames (session_id, frame, trial_index, shown, display_time_ns, cpu_ms, missed)
    VALUES (1, 3, 0, 'label1', 100, 1.5, 0);
)sql";
        ASSERT_EQ(raw.exec(rows), SQLITE_OK) << sqlite3_errmsg(raw.db);
    }
    auto store = open_store();
    ASSERT_TRUE(store);
    {
        RawDb raw(db_);
        EXPECT_EQ(raw.integer("PRAGMA user_version"), StudyStore::kSchemaVersion);
        EXPECT_EQ(raw.text("PRAGMA integrity_check"), "ok");
    }
    const Result<SessionInfo> info = store->session(1);
    ASSERT_TRUE(info.ok()) << info.error().message;
    EXPECT_EQ(info->render, (RenderSettings{"taa", "off", "test"}));
    EXPECT_TRUE(info->scene_files.empty());  // version 2 showed built-in scenes only
    EXPECT_EQ(store->frames(1)->size(), 1u);
    EXPECT_EQ(*store->first_undecided_trial(1), 0);
    EXPECT_EQ(*store->next_frame_number(1), 4);
    TrialOutcome outcome;
    outcome.choice = 2;
    outcome.chosen_mode = RenderMode::Hybrid;
    ASSERT_TRUE(store->record_outcome(1, 0, outcome).ok());
    ASSERT_TRUE(store->add_session_note(1, "migrated").ok());
    EXPECT_EQ(store->session(1)->notes.size(), 1u);
    // A new session with an imported scene in the migrated file.
    SessionInfo imported = make_info("P09");
    imported.scene_files = room_records();
    const Result<std::int64_t> id = store->begin_session(imported, make_imported_schedule(1));
    ASSERT_TRUE(id.ok()) << id.error().message;
    EXPECT_EQ(store->session(*id)->scene_files, room_records());
    EXPECT_EQ(store->trials()->size(), 9u);
}

}  // namespace
}  // namespace monoplane::study
