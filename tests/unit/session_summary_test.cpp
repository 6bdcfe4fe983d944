// The summary `study run|resume` print after a session and the launcher shows
// (app/commands/session_summary.h): counts, duration, missed frames and flagged trials, notes,
// on a database the test builds.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "app/commands/session_summary.h"
#include "study/study_store.h"

namespace monoplane::app {
namespace {

namespace fs = std::filesystem;
using study::FrameRecord;
using study::ScheduledTrial;

ScheduledTrial trial(int index, int block, double m) {
    ScheduledTrial t;
    t.index = index;
    t.practice = block < 0;
    t.block = block;
    t.scene = "beams";
    t.mono_plane = m;
    t.label1_mode = study::RenderMode::Stereo;
    t.label2_mode = study::RenderMode::Hybrid;
    return t;
}

// One practice trial, then four data trials.
study::Schedule schedule() {
    study::Schedule s;
    s.seed = 7;
    s.block_order = {"beams"};
    s.trials = {trial(0, -1, 5.0), trial(1, 0, 1.6), trial(2, 0, 8.0), trial(3, 0, 1.6),
                trial(4, 0, 8.0)};
    return s;
}

// The demo protocol with a missed-frame threshold of 20 %, as the session ran it.
std::string protocol_text() {
    const char* source = std::getenv("MONOPLANE_SOURCE_DIR");
    std::ifstream file(fs::path(source ? source : ".") / "protocols" / "demo.toml");
    std::stringstream text;
    text << file.rdbuf();
    return "missed_frame_threshold = 0.2\n" + text.str();
}

study::SessionInfo info(const std::string& code, const std::string& runtime) {
    study::SessionInfo i;
    i.participant_code = code;
    i.protocol_name = "demo";
    i.protocol_text = protocol_text();
    i.software_version = "0.1.0";
    i.hmd = "vive";
    i.runtime = runtime;
    i.device = "lab-pc";
    i.started_utc = "2026-12-03T09:00:00Z";
    return i;
}

study::TrialOutcome chose(int label) {
    study::TrialOutcome o;
    o.choice = label;
    o.chosen_mode = label == 1 ? study::RenderMode::Stereo : study::RenderMode::Hybrid;
    o.valid = true;
    return o;
}

class SessionSummaryTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "summary_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        auto opened = study::StudyStore::open(dir_ / "study.sqlite");
        ASSERT_TRUE(opened.ok()) << opened.error().message;
        store_ = std::move(opened).value();
    }
    void TearDown() override {
        store_.reset();
        fs::remove_all(dir_);
    }

    // Queues `count` frames showing `shown` in `trial` (none: a screen), the first `missed` of
    // them missed, 0.1 s apart on the runtime's clock.
    void frames(std::int64_t id, std::optional<int> trial, const std::string& shown, int count,
                int missed) {
        for (int i = 0; i < count; ++i) {
            FrameRecord f;
            f.frame = next_frame_;
            f.display_time_ns = 1'000'000'000 + next_frame_ * 100'000'000;
            ++next_frame_;
            f.trial_index = trial;
            f.shown = shown;
            f.missed = i < missed;
            store_->queue_frame(id, f);
        }
    }

    void sql(const std::string& statement) {
        sqlite3* db = nullptr;
        ASSERT_EQ(sqlite3_open((dir_ / "study.sqlite").c_str(), &db), SQLITE_OK);
        EXPECT_EQ(sqlite3_exec(db, statement.c_str(), nullptr, nullptr, nullptr), SQLITE_OK);
        sqlite3_close(db);
    }

    fs::path dir_;
    std::unique_ptr<study::StudyStore> store_;
    std::int64_t next_frame_ = 0;
};

TEST_F(SessionSummaryTest, AHeadsetSessionCountsFramesFlagsTrialsAndKeepsNotes) {
    const auto id = store_->begin_session(info("P01", "simulated"), schedule());
    ASSERT_TRUE(id.ok()) << id.error().message;
    frames(*id, std::nullopt, "instructions", 5, 1);  // a screen: the session's, no trial's
    frames(*id, 0, "label1", 5, 5);                   // practice: never flagged
    frames(*id, 1, "label1", 6, 3);                   // 3 of 10 = 30 % > 20 %: flagged
    frames(*id, 1, "label2", 4, 0);
    frames(*id, 1, "neutral", 1, 1);  // between the labels: not the trial's frames
    frames(*id, 2, "label2", 10, 1);  // 10 %: not flagged
    for (int t : {0, 1, 2}) ASSERT_TRUE(store_->record_outcome(*id, t, chose(1 + t % 2)).ok());
    ASSERT_TRUE(store_
                    ->add_note(*id, {.noted_utc = "2026-12-03T09:05:00Z",
                                     .text = "headset slipped",
                                     .source = study::NoteSource::Window,
                                     .runtime_time_ns = 2'000'000'000,
                                     .trial_index = 1})
                    .ok());
    ASSERT_TRUE(store_
                    ->add_note(*id, {.noted_utc = "2026-12-03T10:00:00Z",
                                     .text = "wears glasses",
                                     .source = study::NoteSource::Command,
                                     .runtime_time_ns = std::nullopt,
                                     .trial_index = std::nullopt})
                    .ok());

    // Not ended: the logged clock, first to last frame (31 frames 0.1 s apart).
    auto running = summarize_session(*store_, *id);
    ASSERT_TRUE(running.ok()) << running.error().message;
    const SessionSummary& r = *running;
    EXPECT_EQ(r.participant_code, "P01");
    EXPECT_EQ(r.status, study::SessionStatus::Running);
    EXPECT_EQ(r.trials_decided, 2);
    EXPECT_EQ(r.trials_planned, 4);
    EXPECT_EQ(r.practice_decided, 1);
    EXPECT_EQ(r.practice_planned, 1);
    EXPECT_EQ(r.duration_basis, DurationBasis::LastLogged);
    EXPECT_NEAR(r.duration_s, 3.0, 1e-9);
    EXPECT_TRUE(r.frame_log);
    EXPECT_EQ(r.frames, 31);
    EXPECT_EQ(r.frames_missed, 11);
    EXPECT_DOUBLE_EQ(r.missed_share, 11.0 / 31.0);
    EXPECT_DOUBLE_EQ(r.missed_frame_threshold, 0.2);
    EXPECT_EQ(r.trials_with_frames, 2);
    ASSERT_EQ(r.flagged.size(), 1u);
    EXPECT_EQ(r.flagged[0].trial_index, 1);
    EXPECT_EQ(r.flagged[0].frames, 10);
    EXPECT_EQ(r.flagged[0].missed, 3);
    EXPECT_DOUBLE_EQ(r.flagged[0].share, 0.3);
    ASSERT_EQ(r.notes.size(), 2u);
    EXPECT_EQ(r.notes[0].text, "headset slipped");

    // Ended 12 min 5 s after it started: the wall clock.
    ASSERT_TRUE(store_->set_status(*id, study::SessionStatus::Completed).ok());
    sql("UPDATE sessions SET ended_utc = '2026-12-03T09:12:05Z' WHERE id = " + std::to_string(*id));
    auto ended = summarize_session(*store_, *id);
    ASSERT_TRUE(ended.ok()) << ended.error().message;
    EXPECT_EQ(ended->duration_basis, DurationBasis::Ended);
    EXPECT_DOUBLE_EQ(ended->duration_s, 725.0);
    const std::vector<std::string> want = {
        "session " + std::to_string(*id) + " (participant P01, session 1) completed",
        "data trials: 2 of 4 decided; practice: 1 of 1",
        "duration: 12 min 5 s (started to ended)",
        "missed frames: 11 of 31 (35.5 %); 1 of 2 trials flagged above 20.0 %: trial 1 (30.0 %)",
        "notes: 2",
        "  2026-12-03T09:05:00Z, trial 1, window: headset slipped",
        "  2026-12-03T10:00:00Z, command: wears glasses",
    };
    EXPECT_EQ(session_summary_lines(*ended), want);
}

TEST_F(SessionSummaryTest, AHeadlessSessionHasNoFrameLogAndTimesItsEvents) {
    const auto id = store_->begin_session(info("H1", "none"), schedule());
    ASSERT_TRUE(id.ok()) << id.error().message;
    using study::EventKind;
    ASSERT_TRUE(store_->append_event(*id, {EventKind::Shown, 1, 1, 5'000'000'000, -1}).ok());
    ASSERT_TRUE(store_->append_event(*id, {EventKind::Confirmed, 1, 1, 7'400'000'000, -1}).ok());
    ASSERT_TRUE(store_->record_outcome(*id, 1, chose(1)).ok());
    auto summary = summarize_session(*store_, *id);
    ASSERT_TRUE(summary.ok()) << summary.error().message;
    EXPECT_FALSE(summary->frame_log);
    EXPECT_EQ(summary->frames, 0);
    EXPECT_TRUE(summary->flagged.empty());
    EXPECT_EQ(summary->duration_basis, DurationBasis::LastLogged);
    EXPECT_NEAR(summary->duration_s, 2.4, 1e-9);
    const std::vector<std::string> lines = session_summary_lines(*summary);
    ASSERT_EQ(lines.size(), 5u);
    EXPECT_EQ(lines[1], "data trials: 1 of 4 decided; practice: 0 of 1");
    EXPECT_EQ(lines[2], "duration: 2 s (not ended: first to last logged event or frame)");
    EXPECT_EQ(lines[3], "missed frames: no frame log (headless session)");
    EXPECT_EQ(lines[4], "notes: 0");
}

TEST_F(SessionSummaryTest, AnUnknownSessionIsAnErrorNamingTheDatabase) {
    auto summary = summarize_session(*store_, 42);
    ASSERT_FALSE(summary.ok());
    EXPECT_NE(summary.error().message.find("study.sqlite"), std::string::npos)
        << summary.error().message;
}

}  // namespace
}  // namespace monoplane::app
