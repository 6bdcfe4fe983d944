// What a study file may and may not do to the lab's data (docs/data.md, "Which commands write"):
// the reading store changes no byte of any file, reads older schemas as they are and derives the
// same session ids every time; every open refuses a 0-byte, truncated, foreign, newer or damaged
// file with one line and nothing written; migration keeps a copy of the original; and a
// participant has one live session, whoever races to start it.
#include <gtest/gtest.h>
#include <sched.h>
#include <sqlite3.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "study/file_digest.h"
#include "study/session_hold.h"
#include "study/session_uuid.h"
#include "study/store_schema.h"
#include "study/study_store.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

int exec(const fs::path& file, const std::string& sql) {
    sqlite3* db = nullptr;
    sqlite3_open(file.c_str(), &db);
    const int rc = sqlite3_exec(db, sql.c_str(), nullptr, nullptr, nullptr);
    sqlite3_close_v2(db);
    return rc;
}

// Each of a database's files (the database, its -wal and -shm) with its digest, or "absent".
std::map<std::string, std::string> fingerprint(const fs::path& db) {
    std::map<std::string, std::string> files;
    for (const char* suffix : {"", "-wal", "-shm", "-holds"}) {
        const fs::path file = db.string() + suffix;
        Result<FileDigest> digest = digest_file(file);
        files[suffix] = digest ? digest->sha256 : "absent";
    }
    return files;
}

std::vector<std::string> directory_listing(const fs::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

Schedule two_trial_schedule(int participant_index, int session_number = 1) {
    Schedule schedule;
    schedule.seed = 7;
    schedule.participant_index = participant_index;
    schedule.session_number = session_number;
    schedule.block_order = {"beams"};
    schedule.trials.push_back(
        {0, false, 0, "beams", 8.0, 0, RenderMode::Stereo, RenderMode::Hybrid});
    schedule.trials.push_back(
        {1, false, 0, "beams", 3.0, 1, RenderMode::Hybrid, RenderMode::Stereo});
    return schedule;
}

constexpr std::string_view kProtocolA =
    "name = \"day\"\nscenes = [\"beams\"]\nmono_planes = [2, 6, 12]\n"
    "alternatives = [\"stereo\", \"hybrid\"]\nsessions = 3\n";
// The same design, another comment: a change of text only.
constexpr std::string_view kProtocolAText =
    "# wording fixed\nname = \"day\"\nscenes = [\"beams\"]\nmono_planes = [2, 6, 12]\n"
    "alternatives = [\"stereo\", \"hybrid\"]\nsessions = 3\n";
// Another design: other distances.
constexpr std::string_view kProtocolB =
    "name = \"day\"\nscenes = [\"beams\"]\nmono_planes = [3, 8]\n"
    "alternatives = [\"stereo\", \"hybrid\"]\nsessions = 3\n";

SessionInfo info_for(const std::string& code, int session_number,
                     std::string_view protocol = kProtocolA) {
    SessionInfo info;
    info.participant_code = code;
    info.session_number = session_number;
    info.protocol_name = "day";
    info.protocol_text = std::string(protocol);
    Result<Protocol> parsed = parse_protocol(protocol, "test");
    EXPECT_TRUE(parsed.ok()) << parsed.error().message;
    info.protocol_hash = parsed ? parsed->text_hash : 0;
    info.software_version = "test";
    info.hmd = "vive";
    info.runtime = "none";
    info.device = "none";
    info.started_utc = "2026-12-01T09:00:00Z";
    return info;
}

class StudyIntegrityTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "integrity_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        db_ = dir_ / "study.sqlite";
    }
    void TearDown() override {
        fs::permissions(dir_, fs::perms::owner_all);
        fs::remove_all(dir_);
    }

    // A study with one participant and session (status as given), closed.
    void make_study(SessionStatus status = SessionStatus::Completed) {
        auto store = StudyStore::open(db_);
        ASSERT_TRUE(store.ok()) << store.error().message;
        Result<std::int64_t> id = (*store)->begin_session(info_for("k9", 1), two_trial_schedule(0));
        ASSERT_TRUE(id.ok()) << id.error().message;
        ASSERT_TRUE((*store)->set_status(*id, status).ok());
    }

    fs::path dir_;
    fs::path db_;
};

// --- Files that are no study ------------------------------------------------------------------

TEST_F(StudyIntegrityTest, EveryOpenRefusesAZeroByteFileWritingNothing) {
    std::ofstream(db_).close();
    for (auto open : {+[](const fs::path& p) { return StudyStore::open(p); },
                      +[](const fs::path& p) { return StudyStore::open_existing(p); },
                      +[](const fs::path& p) { return StudyStore::open_read_only(p); }}) {
        auto store = open(db_);
        ASSERT_FALSE(store.ok());
        EXPECT_NE(
            store.error().message.find("is 0 bytes: not a study database; a copy that failed?"),
            std::string::npos)
            << store.error().message;
        EXPECT_EQ(fs::file_size(db_), 0u);
        EXPECT_EQ(directory_listing(dir_), std::vector<std::string>{"study.sqlite"});
    }
}

TEST_F(StudyIntegrityTest, ReadingAndResumingRefuseAMissingFileAndCreateNone) {
    for (auto open : {+[](const fs::path& p) { return StudyStore::open_existing(p); },
                      +[](const fs::path& p) { return StudyStore::open_read_only(p); }}) {
        auto store = open(db_);
        ASSERT_FALSE(store.ok());
        EXPECT_NE(
            store.error().message.find("no study database '" + db_.string() + "' (no such file)"),
            std::string::npos)
            << store.error().message;
        EXPECT_TRUE(directory_listing(dir_).empty());
    }
}

TEST_F(StudyIntegrityTest, ATruncatedCopyIsRefusedNamingBothSizes) {
    make_study();
    const std::uintmax_t whole = fs::file_size(db_);
    ASSERT_GE(whole, 8192u);  // several pages: the schema of a study takes more than one
    const fs::path copy = dir_ / "copy.sqlite";
    fs::copy_file(db_, copy);
    fs::resize_file(copy, 4096);
    const auto before = fingerprint(copy);
    for (auto open : {+[](const fs::path& p) { return StudyStore::open(p); },
                      +[](const fs::path& p) { return StudyStore::open_read_only(p); }}) {
        auto store = open(copy);
        ASSERT_FALSE(store.ok());
        EXPECT_NE(store.error().message.find("is truncated: 4096 bytes of the " +
                                             std::to_string(whole) + " its header promises"),
                  std::string::npos)
            << store.error().message;
        EXPECT_EQ(fingerprint(copy), before);
    }
}

TEST_F(StudyIntegrityTest, AnotherProgramsDatabaseKeepsEveryByteWhateverOpensIt) {
    ASSERT_EQ(exec(db_,
                   "CREATE TABLE photos (id INTEGER PRIMARY KEY, path TEXT);"
                   "INSERT INTO photos (path) VALUES ('a.jpg');"),
              SQLITE_OK);
    const auto before = fingerprint(db_);
    for (auto open : {+[](const fs::path& p) { return StudyStore::open(p); },
                      +[](const fs::path& p) { return StudyStore::open_existing(p); },
                      +[](const fs::path& p) { return StudyStore::open_read_only(p); }}) {
        auto store = open(db_);
        ASSERT_FALSE(store.ok());
        EXPECT_NE(store.error().message.find("is a SQLite database of another program"),
                  std::string::npos)
            << store.error().message;
        // Header byte 19 (the journal mode) included: nothing switched it to WAL.
        EXPECT_EQ(fingerprint(db_), before);
    }
}

TEST_F(StudyIntegrityTest, ANewerSchemaIsRefusedUnchangedByEveryOpen) {
    make_study();
    ASSERT_EQ(exec(db_, "PRAGMA user_version = " + std::to_string(StudyStore::kSchemaVersion + 1)),
              SQLITE_OK);
    const auto before = fingerprint(db_);
    for (auto open : {+[](const fs::path& p) { return StudyStore::open(p); },
                      +[](const fs::path& p) { return StudyStore::open_read_only(p); }}) {
        auto store = open(db_);
        ASSERT_FALSE(store.ok());
        EXPECT_NE(store.error().message.find("newer than this build of monoplane knows"),
                  std::string::npos);
        EXPECT_EQ(fingerprint(db_), before);
    }
}

TEST_F(StudyIntegrityTest, ADamagedPageIsRefusedBeforeAnythingReadsIt) {
    make_study();
    // Overwrite the middle of the last page (a table's b-tree page) with garbage.
    const std::uintmax_t size = fs::file_size(db_);
    {
        std::fstream file(db_, std::ios::in | std::ios::out | std::ios::binary);
        file.seekp(static_cast<std::streamoff>(size - 4096));
        const std::string garbage(4096, '\xA5');
        file.write(garbage.data(), static_cast<std::streamsize>(garbage.size()));
    }
    const auto before = fingerprint(db_);
    for (auto open : {+[](const fs::path& p) { return StudyStore::open_existing(p); },
                      +[](const fs::path& p) { return StudyStore::open_read_only(p); }}) {
        auto store = open(db_);
        ASSERT_FALSE(store.ok());
        const std::string& message = store.error().message;
        EXPECT_TRUE(message.find("is damaged") != std::string::npos ||
                    message.find("is damaged (") != std::string::npos)
            << message;
        EXPECT_EQ(fingerprint(db_), before);
    }
}

// --- Reading changes nothing ------------------------------------------------------------------

TEST_F(StudyIntegrityTest, AReadingStoreChangesNoByteAndRefusesEveryWrite) {
    make_study();
    const auto before = fingerprint(db_);
    ASSERT_EQ(before.at("-wal"), "absent");  // a closed study: one file
    {
        auto store = StudyStore::open_read_only(db_);
        ASSERT_TRUE(store.ok()) << store.error().message;
        EXPECT_TRUE((*store)->read_only());
        Result<std::vector<RosterRow>> roster = (*store)->roster();
        ASSERT_TRUE(roster.ok());
        ASSERT_EQ(roster->size(), 1u);
        EXPECT_EQ((*roster)[0].participant_code, "k9");
        EXPECT_TRUE(is_session_uuid((*roster)[0].session_uuid));
        EXPECT_FALSE((*store)->set_status((*roster)[0].session_id, SessionStatus::Aborted).ok());
        EXPECT_EQ(fingerprint(db_), before);  // while open, too
    }
    EXPECT_EQ(fingerprint(db_), before);
    EXPECT_EQ(directory_listing(dir_), std::vector<std::string>{"study.sqlite"});
}

TEST_F(StudyIntegrityTest, AReadingStoreSeesWhatALiveWriterCommittedAndLeavesItsFilesAlone) {
    auto writer = StudyStore::open(db_);
    ASSERT_TRUE(writer.ok());
    Result<std::int64_t> id = (*writer)->begin_session(info_for("k9", 1), two_trial_schedule(0));
    ASSERT_TRUE(id.ok());
    TrialEvent shown;
    shown.kind = EventKind::Shown;
    shown.label = 1;
    shown.time_ns = 5;
    ASSERT_TRUE((*writer)->append_event(*id, shown).ok());
    const auto before = fingerprint(db_);
    ASSERT_NE(before.at("-wal"), "absent");  // the writer's log holds the session
    auto reader = StudyStore::open_read_only(db_);
    ASSERT_TRUE(reader.ok()) << reader.error().message;
    Result<std::vector<TrialEvent>> events = (*reader)->events(*id);
    ASSERT_TRUE(events.ok());
    ASSERT_EQ(events->size(), 1u);
    EXPECT_EQ((*events)[0].time_ns, 5);
    EXPECT_EQ(fingerprint(db_), before);
}

TEST_F(StudyIntegrityTest, AFileOfMode0444InAFolderOfMode0555IsRead) {
    make_study();
    fs::permissions(db_, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    fs::remove(db_.string() + "-holds");
    fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec);
    const auto before = fingerprint(db_);
    auto store = StudyStore::open_read_only(db_);
    ASSERT_TRUE(store.ok()) << store.error().message;
    EXPECT_EQ((*store)->roster()->size(), 1u);
    EXPECT_EQ(fingerprint(db_), before);
    if (::geteuid() != 0) {  // root writes anyway: the refusal is checked for other users
        auto writer = StudyStore::open_existing(db_);
        ASSERT_FALSE(writer.ok());
        EXPECT_NE(writer.error().message.find("is read-only for you"), std::string::npos)
            << writer.error().message;
    }
}

// On a read-only mount (an archive, a CD) even root cannot write: the study reads, the writers
// say why they cannot. In a child with its own mount namespace; skipped where none can be made.
TEST_F(StudyIntegrityTest, AStudyOnAReadOnlyMountIsReadAndNotWritten) {
    make_study(SessionStatus::Running);
    const auto before = fingerprint(db_);
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        if (::unshare(CLONE_NEWNS) != 0 ||
            ::mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0 ||
            ::mount(dir_.c_str(), dir_.c_str(), nullptr, MS_BIND, nullptr) != 0 ||
            ::mount(nullptr, dir_.c_str(), nullptr, MS_REMOUNT | MS_BIND | MS_RDONLY, nullptr) != 0)
            std::_Exit(77);
        auto reader = StudyStore::open_read_only(db_);
        if (!reader.ok() || (*reader)->roster()->size() != 1) std::_Exit(1);
        auto writer = StudyStore::open_existing(db_);
        if (writer.ok() || writer.error().message.find("is read-only for you") == std::string::npos)
            std::_Exit(2);
        std::_Exit(0);
    }
    int status = 0;
    ASSERT_EQ(::waitpid(child, &status, 0), child);
    ASSERT_TRUE(WIFEXITED(status));
    if (WEXITSTATUS(status) == 77) GTEST_SKIP() << "no mount namespace here (not root?)";
    EXPECT_EQ(WEXITSTATUS(status), 0) << "1: not read; 2: a writer not refused as read-only";
    EXPECT_EQ(fingerprint(db_), before);
}

// --- Older schemas ----------------------------------------------------------------------------

// A database as schema version 7 wrote it: one participant, one completed session.
void make_version7_study(const fs::path& db) {
    std::string sql;
    for (int v = 0; v < 7; ++v) sql += std::string(store_migrations()[v]);
    sql += "PRAGMA application_id = " + std::to_string(kStoreApplicationId) + ";";
    sql += "PRAGMA user_version = 7; PRAGMA journal_mode = WAL;";
    sql += R"sql(
INSERT INTO participants (id, code, participant_index, created_utc, participant_number)
    VALUES (1, 'P07', 0, '2026-11-01T10:00:00Z', 0);
INSERT INTO sessions (id, participant_id, protocol_name, protocol_hash, protocol_text, seed,
    block_order, software_version, hmd, runtime, device, observer, started_utc, status)
    VALUES (1, 1, 'demo', '0000000000000001', 'name = "demo"', '11', 'beams',
            'monoplane 0.1.0', 'vive', 'none', 'none', 'default', '2026-11-01T10:00:01Z',
            'completed');
INSERT INTO trials (session_id, trial_index, practice, block, scene, mono_plane,
    label1_alternative, label1_mode, label2_mode, decided, choice, chosen_mode, valid,
    switches, time_label1_ns, time_label2_ns, decision_time_ns, decided_utc)
    VALUES (1, 0, 0, 0, 'beams', 8.0, 0, 'stereo', 'hybrid', 1, 2, 'hybrid', 1, 3,
            1000000000, 2000000000, 3000000000, '2026-11-01T10:00:05Z');
)sql";
    ASSERT_EQ(exec(db, sql), SQLITE_OK);
}

TEST_F(StudyIntegrityTest, AnOlderSchemaIsReadAsItIsWithTheSameDerivedIdEveryTime) {
    make_version7_study(db_);
    const auto before = fingerprint(db_);
    std::string first_id;
    for (int read = 0; read < 2; ++read) {
        auto store = StudyStore::open_read_only(db_);
        ASSERT_TRUE(store.ok()) << store.error().message;
        EXPECT_EQ((*store)->found_schema_version(), 7);
        Result<SessionInfo> info = (*store)->session(1);
        ASSERT_TRUE(info.ok());
        EXPECT_EQ(info->participant_code, "P07");
        EXPECT_EQ(info->session_uuid.substr(14, 1), "8");  // derived: RFC 9562 version 8
        if (read == 0) first_id = info->session_uuid;
        EXPECT_EQ(info->session_uuid, first_id);
        EXPECT_EQ(fingerprint(db_), before);
    }
    // A copy elsewhere derives the same id: the id follows the session, not the file.
    const fs::path copy = dir_ / "copy-of-study.sqlite";
    fs::copy_file(db_, copy);
    auto copied = StudyStore::open_read_only(copy);
    ASSERT_TRUE(copied.ok());
    EXPECT_EQ((*copied)->session(1)->session_uuid, first_id);
    // Migrating the file in place keeps a version-7 copy and gives the session the same id.
    {
        auto migrated = StudyStore::open_existing(db_);
        ASSERT_TRUE(migrated.ok()) << migrated.error().message;
        ASSERT_TRUE((*migrated)->schema_backup().has_value());
        EXPECT_EQ(*(*migrated)->schema_backup(), fs::path(db_.string() + ".schema7.bak"));
        EXPECT_EQ((*migrated)->session(1)->session_uuid, first_id);
    }
    sqlite3* backup = nullptr;
    ASSERT_EQ(sqlite3_open(fs::path(db_.string() + ".schema7.bak").c_str(), &backup), SQLITE_OK);
    sqlite3_stmt* stmt = nullptr;
    sqlite3_prepare_v2(backup, "PRAGMA user_version", -1, &stmt, nullptr);
    ASSERT_EQ(sqlite3_step(stmt), SQLITE_ROW);
    EXPECT_EQ(sqlite3_column_int(stmt, 0), 7);
    sqlite3_finalize(stmt);
    sqlite3_close_v2(backup);
}

// --- One live session per participant ---------------------------------------------------------

TEST_F(StudyIntegrityTest, AnInterruptedSessionMustBeResumedOrAbandonedWithAReason) {
    make_study(SessionStatus::Running);  // nobody holds it: interrupted
    auto store = StudyStore::open(db_);
    ASSERT_TRUE(store.ok());
    Result<std::int64_t> refused =
        (*store)->begin_session(info_for("k9", 2), two_trial_schedule(0, 2));
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find(
                  "participant k9's session 1 in '" + db_.string() +
                  "' was interrupted (0 of 2 trials decided). Resume it: monoplane study resume "
                  "--db " +
                  db_.string() + " --participant k9 --session 1"),
              std::string::npos)
        << refused.error().message;
    EXPECT_EQ((*store)->roster()->size(), 1u);

    SessionInfo abandon = info_for("k9", 2);
    abandon.decisions.abandon_session = 1;
    abandon.decisions.abandon_reason = "headset cable broke";
    Result<std::int64_t> second = (*store)->begin_session(abandon, two_trial_schedule(0, 2));
    ASSERT_TRUE(second.ok()) << second.error().message;
    Result<std::vector<RosterRow>> roster = (*store)->roster();
    ASSERT_EQ(roster->size(), 2u);
    EXPECT_EQ((*roster)[0].status, SessionStatus::Aborted);
    EXPECT_EQ((*roster)[0].abandoned_reason, std::optional<std::string>("headset cable broke"));
    EXPECT_FALSE((*roster)[1].abandoned_reason.has_value());
    Result<std::vector<TrialEvent>> events = (*store)->events((*roster)[0].session_id);
    ASSERT_EQ(events->size(), 1u);
    EXPECT_EQ((*events)[0].kind, EventKind::SessionAbandoned);
    EXPECT_EQ((*events)[0].detail, "headset cable broke");
    Result<SessionInfo> first = (*store)->session((*roster)[0].session_id);
    ASSERT_EQ(first->recorded_decisions.size(), 1u);
    EXPECT_EQ(first->recorded_decisions[0].detail, "headset cable broke");
    EXPECT_TRUE((*store)->session(*second)->recorded_decisions.empty());
}

TEST_F(StudyIntegrityTest, ASessionRunningInAnotherProcessIsNamedAndRefused) {
    make_study(SessionStatus::Running);
    Result<SessionHold> hold = SessionHold::acquire(db_, 1);
    ASSERT_TRUE(hold.ok());
    auto store = StudyStore::open(db_);
    SessionInfo abandon = info_for("k9", 2);
    abandon.decisions.abandon_session = 1;  // a running session cannot be abandoned
    abandon.decisions.abandon_reason = "gone";
    Result<std::int64_t> refused = (*store)->begin_session(abandon, two_trial_schedule(0, 2));
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("participant k9's session 1 in '" + db_.string() +
                                           "' is running: process " + std::to_string(::getpid()) +
                                           " on "),
              std::string::npos)
        << refused.error().message;
}

TEST_F(StudyIntegrityTest, AbandoningNeedsAnInterruptedSessionAndAReason) {
    make_study(SessionStatus::Completed);
    auto store = StudyStore::open(db_);
    SessionInfo abandon = info_for("k9", 2);
    abandon.decisions.abandon_session = 1;
    abandon.decisions.abandon_reason = "x";
    Result<std::int64_t> refused = (*store)->begin_session(abandon, two_trial_schedule(0, 2));
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("--abandon 1: participant k9's session 1 in '" +
                                           db_.string() + "' is not an interrupted session"),
              std::string::npos)
        << refused.error().message;
}

// Two processes start the same new participant at the same moment, 100 times: each time
// exactly one begins session 1 and the other is refused, naming the running session.
TEST_F(StudyIntegrityTest, OfTwoProcessesRacingToStartAParticipantExactlyOneStarts) {
    for (int race = 0; race < 100; ++race) {
        const std::string code = "r" + std::to_string(race);
        int go[2];
        int done[2];
        ASSERT_EQ(::pipe(go), 0);
        ASSERT_EQ(::pipe(done), 0);
        pid_t children[2];
        for (pid_t& child : children) {
            child = ::fork();
            ASSERT_GE(child, 0);
            if (child == 0) {
                ::close(go[1]);
                char byte = 0;
                if (::read(go[0], &byte, 1) != 1) std::_Exit(3);  // both start at once
                auto store = StudyStore::open(db_, StoreOptions{.busy_timeout_ms = 10000});
                if (!store.ok()) std::_Exit(4);
                std::optional<SessionHold> hold;
                SessionInfo info = info_for(code, 1);
                info.started_utc.clear();
                const int index = *(*store)->participant_count();
                Result<std::int64_t> id = (*store)->begin_session(
                    info, two_trial_schedule(index), [&](std::int64_t new_id) -> Result<void> {
                        Result<SessionHold> taken = SessionHold::acquire(db_, new_id);
                        MONOPLANE_TRY(taken);
                        hold.emplace(std::move(taken).value());
                        return Ok{};
                    });
                if (!id.ok()) {
                    const bool named =
                        id.error().message.find("is running: process") != std::string::npos;
                    std::_Exit(named ? 1 : 5);
                }
                // Keep the session running until the parent has both answers.
                if (::read(done[0], &byte, 1) != 1) std::_Exit(6);
                std::_Exit(0);
            }
        }
        ::close(go[0]);
        ::close(done[0]);
        const char start[2] = {1, 1};
        ASSERT_EQ(::write(go[1], start, 2), 2);
        ::close(go[1]);
        // The refused one ends first; then let the running one end.
        int first = 0;
        const pid_t ended = ::wait(&first);
        const char finish[2] = {1, 1};
        ASSERT_EQ(::write(done[1], finish, 2), 2);
        ::close(done[1]);
        int second = 0;
        ::waitpid(ended == children[0] ? children[1] : children[0], &second, 0);
        ASSERT_TRUE(WIFEXITED(first) && WIFEXITED(second)) << "race " << race;
        EXPECT_EQ(WEXITSTATUS(first), 1) << "race " << race << ": the refused one";
        EXPECT_EQ(WEXITSTATUS(second), 0) << "race " << race << ": the one that started";
    }
    auto store = StudyStore::open_read_only(db_);
    ASSERT_TRUE(store.ok());
    Result<std::vector<RosterRow>> roster = (*store)->roster();
    ASSERT_EQ(roster->size(), 100u);  // one session each, never two
    for (const RosterRow& row : *roster) EXPECT_EQ(row.session_number, 1);
}

// --- Protocol versions ------------------------------------------------------------------------

TEST_F(StudyIntegrityTest, ALaterSessionOfAnotherDesignNeedsAReasonAndATextChangeIsRecorded) {
    make_study(SessionStatus::Completed);
    auto store = StudyStore::open(db_);
    Result<std::int64_t> refused =
        (*store)->begin_session(info_for("k9", 2, kProtocolB), two_trial_schedule(0, 2));
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("protocol 'day' differs in design from participant "
                                           "k9's session 1 in '" +
                                           db_.string() + "': mono_planes: 2, 6, 12 -> 3, 8."),
              std::string::npos)
        << refused.error().message;

    SessionInfo changed = info_for("k9", 2, kProtocolB);
    changed.decisions.protocol_change_reason = "pilot showed 12 m is never chosen";
    Result<std::int64_t> second = (*store)->begin_session(changed, two_trial_schedule(0, 2));
    ASSERT_TRUE(second.ok()) << second.error().message;
    Result<std::vector<TrialEvent>> events = (*store)->events(*second);
    ASSERT_EQ(events->size(), 1u);
    EXPECT_EQ((*events)[0].kind, EventKind::ProtocolChanged);
    EXPECT_EQ((*events)[0].detail,
              "pilot showed 12 m is never chosen (design differs from session 1's: "
              "mono_planes: 2, 6, 12 -> 3, 8)");
    ASSERT_TRUE((*store)->set_status(*second, SessionStatus::Completed).ok());

    // Session 3 is held to session 2's design; a comment changed only: allowed, recorded.
    const std::string kProtocolBText = "# typo fixed\n" + std::string(kProtocolB);
    Result<std::int64_t> third =
        (*store)->begin_session(info_for("k9", 3, kProtocolBText), two_trial_schedule(0, 3));
    ASSERT_TRUE(third.ok()) << third.error().message;
    events = (*store)->events(*third);
    ASSERT_EQ(events->size(), 1u);
    EXPECT_EQ((*events)[0].kind, EventKind::ProtocolTextChanged);
    EXPECT_NE((*events)[0].detail.find("protocol text differs from session 2's"),
              std::string::npos);
}

TEST_F(StudyIntegrityTest, AReasonForAnUnchangedDesignIsRefused) {
    make_study(SessionStatus::Completed);
    auto store = StudyStore::open(db_);
    SessionInfo same = info_for("k9", 2, kProtocolAText);
    same.decisions.protocol_change_reason = "just in case";
    Result<std::int64_t> refused = (*store)->begin_session(same, two_trial_schedule(0, 2));
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("--protocol-changed: protocol 'day' has the design of "
                                           "participant k9's earlier sessions"),
              std::string::npos);
}

// --- Session ids ------------------------------------------------------------------------------

TEST(SessionUuid, RandomIdsAreVersion4AndDerivedOnesVersion8AndStable) {
    const std::string a = random_session_uuid();
    const std::string b = random_session_uuid();
    EXPECT_TRUE(is_session_uuid(a));
    EXPECT_NE(a, b);
    EXPECT_EQ(a[14], '4');
    EXPECT_TRUE(a[19] == '8' || a[19] == '9' || a[19] == 'a' || a[19] == 'b');
    // SHA-256("abc") = ba7816bf 8f01cfea 414140de 5dae2223 ...: version nibble and variant set.
    EXPECT_EQ(derived_session_uuid("abc"), "ba7816bf-8f01-8fea-8141-40de5dae2223");
    EXPECT_FALSE(is_session_uuid("BA7816BF-8F01-8FEA-8141-40DE5DAE2223"));
}

}  // namespace
}  // namespace monoplane::study
