// The study database across a study day (schema version 7, docs/data.md): a participant's
// further sessions with their numbers, study-wide participant numbers and variables, repetitions,
// the roster, experimenter notes, the participant's screens as events and frames, and a
// version-6 database migrating forward with every old row intact.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "study/store_schema.h"
#include "study/study_store.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

// A raw second connection, as an sqlite3 shell would hold.
struct RawDb {
    sqlite3* db = nullptr;
    explicit RawDb(const fs::path& path) { EXPECT_EQ(sqlite3_open(path.c_str(), &db), SQLITE_OK); }
    ~RawDb() { sqlite3_close_v2(db); }
    RawDb(const RawDb&) = delete;
    RawDb& operator=(const RawDb&) = delete;
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

ScheduledTrial trial(int index, int block, const std::string& scene, double m, int repetition) {
    ScheduledTrial t;
    t.index = index;
    t.practice = block < 0;
    t.block = block;
    t.scene = scene;
    t.mono_plane = m;
    t.label1_alternative = index % 2;
    t.label1_mode = index % 2 == 0 ? RenderMode::Stereo : RenderMode::Hybrid;
    t.label2_mode = index % 2 == 0 ? RenderMode::Hybrid : RenderMode::Stereo;
    t.repetition = repetition;
    return t;
}

// One practice trial, then beams at 1.6 and 8 m, each shown twice (repetitions = 2).
Schedule make_schedule_for(int participant_number, int session_number) {
    Schedule s;
    s.seed = 40 + static_cast<std::uint64_t>(session_number);
    s.participant_index = participant_number;
    s.session_number = session_number;
    s.block_order = {"beams"};
    s.trials = {trial(0, -1, "landscape", 5.0, 1), trial(1, 0, "beams", 8.0, 1),
                trial(2, 0, "beams", 1.6, 1), trial(3, 0, "beams", 1.6, 2),
                trial(4, 0, "beams", 8.0, 2)};
    return s;
}

// A staircase session: one practice trial, then three slots whose m is chosen as each starts.
Schedule make_staircase_schedule(int participant_number) {
    Schedule s = make_schedule_for(participant_number, 1);
    for (std::size_t i = 1; i < s.trials.size() - 1; ++i) {
        s.trials[i].adaptive = true;
        s.trials[i].mono_plane = std::nan("");
        s.trials[i].repetition = 1;
    }
    s.trials.pop_back();
    return s;
}

SessionInfo make_info(const std::string& code, int participant_number = 0, int session_number = 1) {
    SessionInfo info;
    info.participant_code = code;
    info.participant_number = participant_number;
    info.session_number = session_number;
    info.protocol_name = "day";
    info.protocol_hash = 0x0123456789abcdefull;
    info.protocol_text = "name = \"day\"\n";
    info.software_version = "0.1.0";
    info.hmd = "vive";
    info.runtime = "none";
    info.device = "lab-pc";
    info.observer = "default";
    info.started_utc = "2026-12-03T09:00:00Z";
    return info;
}

std::vector<VariableValue> variables() {
    return {{"age", VariableType::Integer, "34"},
            {"vision", VariableType::Choice, "corrected"},
            {"remark", VariableType::Text, "=1+1, \"quoted\""}};
}

SessionNote make_note(const std::string& text, NoteSource source = NoteSource::Command,
                      std::optional<std::int64_t> runtime_time_ns = std::nullopt,
                      std::optional<int> trial_index = std::nullopt,
                      const std::string& noted_utc = "") {
    SessionNote note;
    note.noted_utc = noted_utc;
    note.text = text;
    note.source = source;
    note.runtime_time_ns = runtime_time_ns;
    note.trial_index = trial_index;
    return note;
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

class StudyDayStoreTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "study_day_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        db_ = dir_ / "day.sqlite";
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::unique_ptr<StudyStore> open_store() {
        Result<std::unique_ptr<StudyStore>> store = StudyStore::open(db_);
        EXPECT_TRUE(store.ok()) << store.error().message;
        return store.ok() ? std::move(store).value() : nullptr;
    }

    // A participant's later session begins after their earlier ones ended (an unfinished one
    // refuses it: StudyIntegrityTest); these tests are about the numbering, so they end them.
    void end_earlier_sessions(const SessionInfo& info) {
        if (info.session_number <= 1) return;
        RawDb raw(db_);
        ASSERT_EQ(raw.exec("UPDATE sessions SET status = 'completed' WHERE status IN "
                           "('running', 'paused') AND participant_id = (SELECT id FROM "
                           "participants WHERE code = '" +
                           info.participant_code + "')"),
                  SQLITE_OK);
    }

    // Begins a session that must be accepted.
    std::int64_t begin(StudyStore& store, const SessionInfo& info, const Schedule& schedule) {
        end_earlier_sessions(info);
        Result<std::int64_t> id = store.begin_session(info, schedule);
        EXPECT_TRUE(id.ok()) << id.error().message;
        return id.ok() ? *id : -1;
    }

    // Begins a session that must be refused with `why`, writing nothing.
    void refused(StudyStore& store, const SessionInfo& info, const Schedule& schedule,
                 const std::string& why) {
        end_earlier_sessions(info);
        RawDb raw(db_);
        const std::int64_t sessions = raw.integer("SELECT count(*) FROM sessions");
        const std::int64_t participants = raw.integer("SELECT count(*) FROM participants");
        const std::int64_t values = raw.integer("SELECT count(*) FROM participant_variables");
        Result<std::int64_t> id = store.begin_session(info, schedule);
        ASSERT_FALSE(id.ok()) << why;
        EXPECT_TRUE(contains(id.error().message, why)) << id.error().message;
        EXPECT_EQ(raw.integer("SELECT count(*) FROM sessions"), sessions);
        EXPECT_EQ(raw.integer("SELECT count(*) FROM participants"), participants);
        EXPECT_EQ(raw.integer("SELECT count(*) FROM participant_variables"), values);
    }

    fs::path dir_;
    fs::path db_;
};

TEST_F(StudyDayStoreTest, AParticipantComesBackForASecondSession) {
    auto store = open_store();
    ASSERT_TRUE(store);
    EXPECT_EQ(store->path(), db_);
    SessionInfo first = make_info("A1", 4);
    first.variables = variables();
    const std::int64_t one = begin(*store, first, make_schedule_for(4, 1));
    // The second session: no variables given (they are the participant's), the stored number.
    const std::int64_t two = begin(*store, make_info("A1", 0, 2), make_schedule_for(4, 2));
    ASSERT_GT(two, one);

    const Result<SessionInfo> info = store->session(two);
    ASSERT_TRUE(info.ok()) << info.error().message;
    EXPECT_EQ(info->session_number, 2);
    EXPECT_EQ(info->participant_number, 4);
    EXPECT_EQ(info->participant_index, 0);
    EXPECT_EQ(info->variables, variables());
    EXPECT_EQ(info->ended_utc, "");
    EXPECT_EQ(store->session(one)->session_number, 1);

    const Result<std::optional<ParticipantRecord>> p = store->participant("A1");
    ASSERT_TRUE(p.ok()) << p.error().message;
    ASSERT_TRUE(*p);
    EXPECT_EQ((*p)->code, "A1");
    EXPECT_EQ((*p)->participant_number, 4);
    EXPECT_EQ((*p)->variables, variables());
    EXPECT_EQ((*p)->sessions, (std::vector<std::pair<int, std::int64_t>>{{1, one}, {2, two}}));
    EXPECT_EQ((*p)->next_session_number(), 3);
    EXPECT_FALSE(*store->participant("B1"));
    EXPECT_EQ(*store->find_session("A1", 2), two);
    EXPECT_EQ(*store->find_session("A1", 1), one);
    EXPECT_FALSE(*store->find_session("A1", 3));
    EXPECT_FALSE(*store->find_session("B1", 1));
    EXPECT_EQ(*store->participant_count(), 1);

    const Result<Schedule> schedule = store->load_schedule(two);
    ASSERT_TRUE(schedule.ok()) << schedule.error().message;
    EXPECT_EQ(schedule->session_number, 2);
    EXPECT_EQ(schedule->participant_index, 4);  // the number that picked the Latin-square row
    EXPECT_EQ(schedule->seed, 42u);
    // Giving the same variables again is accepted too.
    SessionInfo third = make_info("A1", 4, 3);
    third.variables = variables();
    begin(*store, third, make_schedule_for(4, 3));
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM participant_variables"), 3);
    EXPECT_EQ(raw.text("SELECT type FROM participant_variables WHERE name = 'vision'"), "choice");
}

TEST_F(StudyDayStoreTest, RefusesSessionNumbersNumbersAndVariablesThatDoNotFit) {
    auto store = open_store();
    SessionInfo a1 = make_info("A1", 4);
    a1.variables = variables();
    // Ended: an unfinished session is refused as interrupted first (StudyIntegrityTest).
    ASSERT_TRUE(
        store->set_status(begin(*store, a1, make_schedule_for(4, 1)), SessionStatus::Completed)
            .ok());
    refused(*store, make_info("A1", 4, 1), make_schedule_for(4, 1),
            "participant 'A1' already has session 1 in '" + db_.string() +
                "'; use `monoplane study resume --db " + db_.string() +
                " --participant A1 --session 1`");
    refused(*store, make_info("A1", 4, 3), make_schedule_for(4, 3),
            "participant 'A1' has 1 session(s) in '" + db_.string() +
                "'; their next is session 2, not session 3");
    refused(*store, make_info("B1", 4), make_schedule_for(4, 1),
            "participant number 5 is taken by participant 'A1' in '" + db_.string() + "'");
    SessionInfo changed = make_info("A1", 4, 2);
    changed.variables = variables();
    changed.variables[0].value = "35";
    refused(*store, changed, make_schedule_for(4, 2),
            "participant 'A1''s variables were recorded at their first session");
    refused(*store, make_info("A1", 4, 2), make_schedule_for(5, 2),
            "the schedule was made for participant number 6 but participant 'A1' in '" +
                db_.string() + "' is participant number 5");
    refused(*store, make_info("A1", 4, 2), make_schedule_for(4, 3),
            "the schedule was made for session 3 but participant 'A1' is to begin session 2");
    refused(*store, make_info("A1", 4, 0), make_schedule_for(4, 0), "sessions are numbered from 1");
    SessionInfo bad_name = make_info("C1", 7);
    bad_name.variables = {{"Age", VariableType::Integer, "3"}};
    refused(*store, bad_name, make_schedule_for(7, 1), "'Age' is not a variable name");
    bad_name.variables = {{"age", VariableType::Integer, "3"}, {"age", VariableType::Integer, "4"}};
    refused(*store, bad_name, make_schedule_for(7, 1), "participant variable 'age' is given twice");
    Schedule repetition = make_schedule_for(7, 1);
    repetition.trials[2].repetition = 0;
    refused(*store, make_info("C1", 7), repetition, "scheduled trial 2: repetition is below 1");
    // The default number (0 in info) takes the schedule's: participant number 8.
    begin(*store, make_info("C1"), make_schedule_for(7, 1));
    EXPECT_EQ((*store->participant("C1"))->participant_number, 7);
    EXPECT_EQ((*store->participant("C1"))->participant_index, 1);
}

TEST_F(StudyDayStoreTest, RepetitionsAndSessionNumbersReadBackOnEveryTrial) {
    auto store = open_store();
    const std::int64_t one = begin(*store, make_info("A1", 2), make_schedule_for(2, 1));
    const std::int64_t two = begin(*store, make_info("A1", 2, 2), make_schedule_for(2, 2));
    const Result<std::vector<TrialRecord>> trials = store->trials();
    ASSERT_TRUE(trials.ok()) << trials.error().message;
    ASSERT_EQ(trials->size(), 10u);
    const std::vector<int> repetitions = {1, 1, 1, 2, 2};
    for (std::size_t i = 0; i < trials->size(); ++i) {
        const TrialRecord& r = (*trials)[i];
        EXPECT_EQ(r.session_id, i < 5 ? one : two) << i;
        EXPECT_EQ(r.session_number, i < 5 ? 1 : 2) << i;
        EXPECT_EQ(r.participant_code, "A1");
        EXPECT_EQ(r.trial.repetition, repetitions[i % 5]) << i;
    }
    const Result<Schedule> schedule = store->load_schedule(one);
    ASSERT_TRUE(schedule.ok());
    ASSERT_EQ(schedule->trials.size(), 5u);
    EXPECT_EQ(schedule->trials[3].repetition, 2);
    EXPECT_EQ(schedule->trials[3].mono_plane, 1.6);
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT sum(repetition) FROM trials"), 14);
}

TEST_F(StudyDayStoreTest, TheRosterCountsDataTrialsPerSession) {
    auto store = open_store();
    const std::int64_t b1 = begin(*store, make_info("B1", 1), make_schedule_for(1, 1));
    const std::int64_t a1 = begin(*store, make_info("A1", 0), make_schedule_for(0, 1));
    const std::int64_t a2 = begin(*store, make_info("A1", 0, 2), make_schedule_for(0, 2));
    SessionInfo staircase = make_info("C1", 2);
    staircase.runtime = "simulated";
    const std::int64_t c1 = begin(*store, staircase, make_staircase_schedule(2));
    TrialOutcome outcome;
    outcome.choice = 1;
    outcome.chosen_mode = RenderMode::Stereo;  // even trials show stereo under label 1
    for (int t : {0, 2, 4}) ASSERT_TRUE(store->record_outcome(a1, t, outcome).ok());
    ASSERT_TRUE(store->set_status(a1, SessionStatus::Completed).ok());
    ASSERT_TRUE(store->set_status(b1, SessionStatus::Aborted).ok());
    ScheduledTrial slot = make_staircase_schedule(2).trials[2];
    slot.mono_plane = 6.5;
    ASSERT_TRUE(store->record_stimulus(c1, slot).ok());
    ASSERT_TRUE(store->record_outcome(c1, 2, outcome).ok());

    const Result<std::vector<RosterRow>> roster = store->roster();
    ASSERT_TRUE(roster.ok()) << roster.error().message;
    ASSERT_EQ(roster->size(), 4u);
    const RosterRow& r0 = (*roster)[0];  // by code, then session number
    EXPECT_EQ(r0.participant_code, "A1");
    EXPECT_EQ(r0.session_number, 1);
    EXPECT_EQ(r0.session_id, a1);
    EXPECT_EQ(r0.participant_number, 0);
    EXPECT_EQ(r0.status, SessionStatus::Completed);
    EXPECT_EQ(r0.trials_decided, 2);  // trial 0 is practice
    EXPECT_EQ(r0.trials_planned, 4);
    EXPECT_EQ(r0.started_utc, "2026-12-03T09:00:00Z");
    EXPECT_EQ(r0.ended_utc.size(), 20u) << r0.ended_utc;
    EXPECT_EQ(r0.device, "lab-pc");
    EXPECT_EQ(r0.runtime, "none");
    EXPECT_EQ(r0.protocol_hash, 0x0123456789abcdefull);
    EXPECT_EQ(r0.protocol_name, "day");
    EXPECT_EQ((*roster)[1].session_id, a2);
    EXPECT_EQ((*roster)[1].session_number, 2);
    EXPECT_EQ((*roster)[1].status, SessionStatus::Running);
    EXPECT_EQ((*roster)[1].trials_decided, 0);
    EXPECT_EQ((*roster)[1].ended_utc, "");
    EXPECT_EQ((*roster)[2].participant_code, "B1");
    EXPECT_EQ((*roster)[2].participant_number, 1);
    EXPECT_EQ((*roster)[2].status, SessionStatus::Aborted);
    EXPECT_EQ((*roster)[2].ended_utc, store->session(b1)->ended_utc);
    EXPECT_FALSE((*roster)[2].ended_utc.empty());
    const RosterRow& c = (*roster)[3];
    EXPECT_EQ(c.participant_code, "C1");
    EXPECT_EQ(c.runtime, "simulated");
    EXPECT_EQ(c.trials_decided, 1);
    EXPECT_EQ(c.trials_planned, 3);  // the staircase's slots, one started
    // Resumed: no longer ended.
    ASSERT_TRUE(store->set_status(a1, SessionStatus::Running).ok());
    EXPECT_EQ(store->session(a1)->ended_utc, "");
}

TEST_F(StudyDayStoreTest, NotesKeepWhoWroteThemAndWhen) {
    std::int64_t id = 0;
    const SessionNote window{.noted_utc = "2026-12-03T09:12:00Z",
                             .text = "participant adjusted the headset",
                             .source = NoteSource::Window,
                             .runtime_time_ns = 734'000'000'123,
                             .trial_index = 3};
    const SessionNote command{.noted_utc = "2026-12-03T11:00:00Z",
                              .text = "-2 dioptres, forgot glasses\nsecond line",
                              .source = NoteSource::Command,
                              .runtime_time_ns = std::nullopt,
                              .trial_index = std::nullopt};
    {
        auto store = open_store();
        id = begin(*store, make_info("A1"), make_schedule_for(0, 1));
        ASSERT_TRUE(store->add_session_note(id, "resumed with changed scene files").ok());
        ASSERT_TRUE(store->add_note(id, window).ok());
        ASSERT_TRUE(store->add_note(id, command).ok());
        ASSERT_TRUE(store->add_note(id, make_note("x", NoteSource::Window, 0, 0)).ok());
    }
    auto store = open_store();
    const Result<SessionInfo> info = store->session(id);
    ASSERT_TRUE(info.ok()) << info.error().message;
    ASSERT_EQ(info->notes.size(), 4u);
    const SessionNote& software = info->notes[0];
    EXPECT_EQ(software.source, NoteSource::Software);
    EXPECT_EQ(software.text, "resumed with changed scene files");
    EXPECT_EQ(software.noted_utc.size(), 20u);  // stamped
    EXPECT_FALSE(software.runtime_time_ns);
    EXPECT_FALSE(software.trial_index);
    EXPECT_EQ(info->notes[1], window);
    EXPECT_EQ(info->notes[2], command);
    EXPECT_EQ(info->notes[3].runtime_time_ns, 0);
    EXPECT_EQ(info->notes[3].trial_index, 0);
    EXPECT_EQ(info->notes[3].noted_utc.size(), 20u);
    RawDb raw(db_);
    EXPECT_EQ(raw.text("SELECT group_concat(source, ',') FROM session_notes"),
              "software,window,command,window");
}

TEST_F(StudyDayStoreTest, RefusesNotesThatSayNothingOrTooMuchWritingNothing) {
    auto store = open_store();
    const std::int64_t id = begin(*store, make_info("A1"), make_schedule_for(0, 1));
    const auto refused = [&](std::int64_t session, const SessionNote& note,
                             const std::string& why) {
        const Result<void> ok = store->add_note(session, note);
        ASSERT_FALSE(ok.ok()) << why;
        EXPECT_TRUE(contains(ok.error().message, why)) << ok.error().message;
    };
    refused(id, make_note(""), "is empty");
    refused(id, make_note(" \t\r\n "), "is empty");
    refused(id, make_note(std::string(10'001, 'x')), "has 10001 characters; at most 10,000");
    refused(id + 1, make_note("x"),
            "no session " + std::to_string(id + 1) + " in study database '" + db_.string() + "'");
    refused(id, make_note("x", NoteSource::Window, 5, -1), "trial -1 is negative");
    refused(id, make_note("x", NoteSource::Window, -5, 1), "session time -5 ns is negative");
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM session_notes"), 0);
    // 10,000 characters are kept, counted as typed: two bytes each here.
    std::string umlauts;
    for (int i = 0; i < 10'000; ++i) umlauts += "\xc3\xa4";
    ASSERT_TRUE(store->add_note(id, make_note(umlauts)).ok());
    EXPECT_EQ(store->session(id)->notes.at(0).text, umlauts);
}

TEST_F(StudyDayStoreTest, ScreenEventsRoundTripWithoutATrial) {
    const std::vector<TrialEvent> events = {
        {EventKind::InstructionsShown, -1, 0, 100, 0, 0},
        {EventKind::InstructionsConfirmed, -1, 0, 200, 5, 0},
        {EventKind::InstructionsShown, -1, 0, 210, 6, 1},
        {EventKind::InstructionsShown, -1, 0, 300, 9, 0},  // back to page 0
        {EventKind::InstructionsConfirmed, -1, 0, 400, 12, 1},
        {EventKind::Shown, 0, 1, 500, 13, -1},
        {EventKind::Confirmed, 0, 1, 600, 20, -1},
        {EventKind::ReadyShown, -1, 0, 700, 21, -1},
        {EventKind::ReadyConfirmed, -1, 0, 800, 30, -1},
        {EventKind::BreakStarted, -1, 0, 900, 31, -1},
        {EventKind::BreakEnded, -1, 0, 30'000'000'900, 2000, -1},
        {EventKind::EndShown, -1, 0, 30'000'001'000, 2001, -1},
    };
    std::int64_t id = 0;
    {
        auto store = open_store();
        id = begin(*store, make_info("A1"), make_schedule_for(0, 1));
        for (const TrialEvent& e : events) {
            const Result<void> ok = store->append_event(id, e);
            ASSERT_TRUE(ok.ok()) << describe(e) << ": " << ok.error().message;
        }
    }
    auto store = open_store();
    const Result<std::vector<TrialEvent>> loaded = store->events(id);
    ASSERT_TRUE(loaded.ok()) << loaded.error().message;
    ASSERT_EQ(loaded->size(), events.size());
    for (std::size_t i = 0; i < events.size(); ++i) {
        EXPECT_EQ(describe((*loaded)[i]), describe(events[i])) << i;
        EXPECT_EQ((*loaded)[i].page, events[i].page) << i;
        EXPECT_EQ((*loaded)[i].label, events[i].label) << i;
    }
    EXPECT_EQ(*store->next_frame_number(id), 2002);
    RawDb raw(db_);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM events WHERE trial_index IS NULL"), 10);
    EXPECT_EQ(raw.integer("SELECT count(*) FROM events WHERE page IS NOT NULL"), 5);
    EXPECT_EQ(raw.text("SELECT kind FROM events WHERE page = 1 ORDER BY id LIMIT 1"),
              "instructions_shown");
}

TEST_F(StudyDayStoreTest, RefusesScreenEventsThatClaimATrialOrLackAPage) {
    auto store = open_store();
    const std::int64_t id = begin(*store, make_info("A1"), make_schedule_for(0, 1));
    const auto refused = [&](std::int64_t session, const TrialEvent& e, const std::string& why) {
        const Result<void> ok = store->append_event(session, e);
        ASSERT_FALSE(ok.ok()) << why;
        EXPECT_TRUE(contains(ok.error().message, why)) << ok.error().message;
    };
    refused(id, {EventKind::BreakStarted, 2, 0, 1, 1, -1},
            "a 'break_started' event belongs to a screen or the session, not to trial 2");
    refused(id, {EventKind::InstructionsShown, -1, 0, 1, 1, -1},
            "a 'instructions_shown' event needs its instruction page");
    refused(id, {EventKind::EndShown, -1, 0, 1, 1, 0}, "has no instruction page (-1), not page 0");
    refused(id, {EventKind::Switched, -1, 2, 1, 1, -1}, "a 'switched' event needs its trial");
    refused(id + 1, {EventKind::ReadyShown, -1, 0, 1, 1, -1},
            "(no trial) of session " + std::to_string(id + 1) + " (the session must exist)");
    EXPECT_TRUE(store->events(id)->empty());
}

FrameRecord screen_frame(std::int64_t index, const std::string& shown) {
    FrameRecord f;
    f.frame = index;
    f.shown = shown;
    f.display_time_ns = 1'000'000'000 + index * 11'111'111;
    f.cpu_ms = 1.25;
    f.head = std::array<double, 7>{0.0, 1.6, 0.0, 1.0, 0.0, 0.0, 0.0};
    return f;
}

TEST_F(StudyDayStoreTest, TheFrameLogCoversTheScreens) {
    auto store = open_store();
    const std::int64_t id = begin(*store, make_info("A1"), make_schedule_for(0, 1));
    const std::vector<std::string> shown = {"instructions", "ready", "break", "end", "neutral"};
    for (std::size_t i = 0; i < shown.size(); ++i)
        store->queue_frame(id, screen_frame(static_cast<std::int64_t>(i), shown[i]));
    FrameRecord in_trial = screen_frame(5, "label1");
    in_trial.trial_index = 1;
    store->queue_frame(id, in_trial);
    const Result<void> flushed = store->flush_frames();
    ASSERT_TRUE(flushed.ok()) << flushed.error().message;
    const Result<std::vector<FrameRecord>> frames = store->frames(id);
    ASSERT_TRUE(frames.ok()) << frames.error().message;
    ASSERT_EQ(frames->size(), 6u);
    for (std::size_t i = 0; i < shown.size(); ++i) {
        EXPECT_EQ((*frames)[i].shown, shown[i]);
        EXPECT_FALSE((*frames)[i].trial_index);
        EXPECT_EQ((*frames)[i].display_time_ns,
                  screen_frame(static_cast<std::int64_t>(i), "").display_time_ns);
    }
    EXPECT_EQ((*frames)[5].trial_index, 1);
    store->queue_frame(id, screen_frame(6, "menu"));  // no screen of that name
    EXPECT_FALSE(store->flush_frames().ok());
}

// A database of schema version 6 (made here from versions 1 to 6 of the schema, with rows as that
// release wrote them) migrates to version 7: every row reads back with the new defaults, and the
// file takes the new rows.
constexpr const char* kVersion6Rows = R"sql(
INSERT INTO participants VALUES (1, 'P07', 0, '2026-11-01T10:00:00Z');
INSERT INTO participants VALUES (2, 'P08', 1, '2026-11-01T11:00:00Z');
INSERT INTO sessions (id, participant_id, protocol_name, protocol_hash, protocol_text, seed,
    block_order, software_version, hmd, runtime, device, observer, started_utc, ended_utc, status,
    render_anti_aliasing, render_ssao, render_detail, procedure)
    VALUES (1, 1, 'demo', '0000000000000001', 'name = "demo"', '11', 'beams',
            'monoplane 0.1.0', 'vive', 'none', 'none', 'default', '2026-11-01T10:00:01Z',
            '2026-11-01T10:20:00Z', 'completed', 'none', 'off', NULL, 'constant'),
           (2, 2, 'demo', '0000000000000001', 'name = "demo"', '12', 'beams',
            'monoplane 0.1.0', 'vive', 'simulated', 'llvmpipe', 'default',
            '2026-11-01T11:00:01Z', NULL, 'running', 'taa', 'off', 'low', 'constant');
INSERT INTO trials (session_id, trial_index, practice, block, scene, mono_plane,
    label1_alternative, label1_mode, label2_mode, decided, choice, chosen_mode, valid,
    switches, time_label1_ns, time_label2_ns, decision_time_ns, decided_utc)
    VALUES (1, 0, 0, 0, 'beams', 8.0, 0, 'stereo', 'hybrid', 1, 2, 'hybrid', 1, 3,
            1000000000, 2000000000, 3000000000, '2026-11-01T10:00:05Z');
INSERT INTO trials (session_id, trial_index, practice, block, scene, mono_plane,
    label1_alternative, label1_mode, label2_mode)
    VALUES (2, 0, 1, -1, 'landscape', 5.0, 1, 'hybrid', 'stereo'),
           (2, 1, 0, 0, 'beams', 3.0, 0, 'stereo', 'hybrid');
INSERT INTO events (session_id, trial_index, kind, label, time_ns, frame)
    VALUES (1, 0, 'shown', 1, 5, 3), (1, 0, 'switched', 2, 7, 4), (1, 0, 'confirmed', 2, 9, 5),
           (2, 0, 'shown', 1, 11, 2);
INSERT INTO frames (session_id, frame, trial_index, shown, display_time_ns, cpu_ms, gpu_ms,
    missed, head_x, head_y, head_z, head_qw, head_qx, head_qy, head_qz, mono_plane,
    pipelines_created, driver_compiles)
    VALUES (2, 1, NULL, 'neutral', 100, 1.5, NULL, 0, NULL, NULL, NULL, NULL, NULL, NULL, NULL,
            NULL, 12, NULL),
           (2, 2, 0, 'label1', 111, 1.75, 2.5, 1, 0.1, 1.6, -0.2, 1, 0, 0, 0, 5.0, 0, 0);
INSERT INTO session_notes (session_id, noted_utc, note)
    VALUES (2, '2026-11-01T11:05:00Z', 'resumed with changed scene files');
INSERT INTO answers VALUES (1, 0, 'I saw a difference', 4, '2026-11-01T10:19:00Z');
)sql";

TEST_F(StudyDayStoreTest, MigratesAVersion6DatabaseForward) {
    {
        RawDb raw(db_);
        for (std::size_t v = 0; v < 6; ++v)
            ASSERT_EQ(raw.exec(std::string(store_migrations()[v])), SQLITE_OK) << v;
        ASSERT_EQ(raw.exec("PRAGMA application_id = " + std::to_string(kStoreApplicationId)),
                  SQLITE_OK);
        ASSERT_EQ(raw.exec("PRAGMA user_version = 6"), SQLITE_OK);
        ASSERT_EQ(raw.exec(kVersion6Rows), SQLITE_OK) << sqlite3_errmsg(raw.db);
    }
    auto store = open_store();
    ASSERT_TRUE(store);
    {
        RawDb raw(db_);
        EXPECT_EQ(raw.integer("PRAGMA user_version"), StudyStore::kSchemaVersion);
        EXPECT_EQ(raw.text("PRAGMA integrity_check"), "ok");
        EXPECT_EQ(raw.integer("SELECT count(*) FROM pragma_foreign_key_check"), 0);
        EXPECT_EQ(raw.integer("SELECT count(*) FROM sqlite_schema WHERE name IN "
                              "('events_by_session', 'participants_by_number', "
                              "'sessions_by_participant')"),
                  3);
        EXPECT_EQ(raw.integer("SELECT count(*) FROM sqlite_schema WHERE name LIKE '%_v7' OR "
                              "name LIKE '%_v8'"),
                  0);
    }
    // Participants: their number is their index.
    const Result<SessionInfo> s2 = store->session(2);
    ASSERT_TRUE(s2.ok()) << s2.error().message;
    EXPECT_EQ(s2->participant_code, "P08");
    EXPECT_EQ(s2->participant_index, 1);
    EXPECT_EQ(s2->participant_number, 1);
    EXPECT_EQ(s2->session_number, 1);
    EXPECT_TRUE(s2->variables.empty());
    EXPECT_EQ(s2->ended_utc, "");
    EXPECT_EQ(s2->render, (RenderSettings{"taa", "off", "low"}));
    ASSERT_EQ(s2->notes.size(), 1u);
    EXPECT_EQ(s2->notes[0], (SessionNote{.noted_utc = "2026-11-01T11:05:00Z",
                                         .text = "resumed with changed scene files",
                                         .source = NoteSource::Software,
                                         .runtime_time_ns = std::nullopt,
                                         .trial_index = std::nullopt}));
    const Result<SessionInfo> s1 = store->session(1);
    ASSERT_TRUE(s1.ok());
    EXPECT_EQ(s1->participant_number, 0);
    EXPECT_EQ(s1->ended_utc, "2026-11-01T10:20:00Z");
    EXPECT_EQ(s1->status, SessionStatus::Completed);
    EXPECT_EQ(store->answers(1)->at(0).answer, 4);

    // Trials: repetition 1, session 1; outcomes intact.
    const Result<std::vector<TrialRecord>> trials = store->trials();
    ASSERT_TRUE(trials.ok()) << trials.error().message;
    ASSERT_EQ(trials->size(), 3u);
    for (const TrialRecord& r : *trials) {
        EXPECT_EQ(r.trial.repetition, 1);
        EXPECT_EQ(r.session_number, 1);
    }
    EXPECT_TRUE((*trials)[0].decided);
    EXPECT_EQ((*trials)[0].outcome.switches, 3);
    EXPECT_EQ((*trials)[0].outcome.decision_time_ns, 3'000'000'000);
    EXPECT_TRUE((*trials)[1].trial.practice);
    EXPECT_EQ(*store->first_undecided_trial(2), 0);

    // Events and frames survived their tables' rebuild.
    const Result<std::vector<TrialEvent>> events = store->events(1);
    ASSERT_TRUE(events.ok()) << events.error().message;
    ASSERT_EQ(events->size(), 3u);
    EXPECT_EQ(describe((*events)[1]), "trial 0 switched label 2 t 7 frame 4");
    EXPECT_EQ((*events)[1].page, -1);
    const Result<std::vector<FrameRecord>> frames = store->frames(2);
    ASSERT_TRUE(frames.ok()) << frames.error().message;
    ASSERT_EQ(frames->size(), 2u);
    EXPECT_EQ((*frames)[0].pipelines_created, 12);
    EXPECT_FALSE((*frames)[0].driver_compiles);
    EXPECT_EQ((*frames)[1].gpu_ms, 2.5);
    EXPECT_EQ((*frames)[1].mono_plane, 5.0);
    EXPECT_TRUE((*frames)[1].missed);
    EXPECT_EQ((*frames)[1].head, (std::array<double, 7>{0.1, 1.6, -0.2, 1, 0, 0, 0}));
    EXPECT_EQ(*store->next_frame_number(2), 3);

    // The roster and the participants as version 7 knows them.
    const Result<std::vector<RosterRow>> roster = store->roster();
    ASSERT_TRUE(roster.ok()) << roster.error().message;
    ASSERT_EQ(roster->size(), 2u);
    EXPECT_EQ((*roster)[0].trials_decided, 1);
    EXPECT_EQ((*roster)[0].trials_planned, 1);
    EXPECT_EQ((*roster)[1].trials_planned, 1);
    EXPECT_EQ((*store->participant("P07"))->next_session_number(), 2);

    // The migrated file takes what version 7 adds: a screen event, a window note, a second
    // session of P07 (participant number 0), a new participant with variables.
    ASSERT_TRUE(store->append_event(2, {EventKind::BreakStarted, -1, 0, 20, 3, -1}).ok());
    ASSERT_TRUE(store->add_note(2, make_note("ok", NoteSource::Window, 20, 1)).ok());
    store->queue_frame(2, screen_frame(3, "break"));
    ASSERT_TRUE(store->flush_frames().ok());
    // The protocol version P07's first session ran (a change of design needs a reason).
    SessionInfo p07 = make_info("P07", 0, 2);
    p07.protocol_name = "demo";
    p07.protocol_hash = 1;
    p07.protocol_text = "name = \"demo\"";
    const std::int64_t second = begin(*store, p07, make_schedule_for(0, 2));
    EXPECT_EQ(store->session(second)->session_number, 2);
    SessionInfo p09 = make_info("P09", 2);
    p09.variables = variables();
    const std::int64_t third = begin(*store, p09, make_schedule_for(2, 1));
    EXPECT_EQ(store->session(third)->variables, variables());
    EXPECT_EQ(store->session(third)->participant_index, 2);
}

}  // namespace
}  // namespace monoplane::study
