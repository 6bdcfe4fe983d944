// The record of an export's source (study/export_source.h): written beside the export, read back
// as written; an existing export is replaced by one of the same study (its sessions all in the
// database exported now, more sessions since included) and refused, naming it and the sessions,
// when it is another study's, when its record is missing or unreadable; forcing allows it. The
// whole command, with real databases, is outputs_cli_test's.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "study/export_source.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

ExportData sessions_of(const std::vector<std::pair<std::string, std::string>>& codes_started) {
    ExportData data;
    std::int64_t id = 0;
    for (const auto& [code, started] : codes_started) {
        SessionInfo info;
        info.id = ++id;
        info.participant_code = code;
        info.session_number = 1;
        info.started_utc = started;
        data.sessions.emplace(info.id, info);
    }
    return data;
}

class ExportSourceTest : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "export_source_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        out_ = dir_ / "trials.csv";
    }
    void TearDown() override { fs::remove_all(dir_); }

    // An earlier export at out_ whose record names `source`'s sessions.
    void earlier_export(const ExportSource& source) {
        std::ofstream(out_) << "participant,session,trial_index,block,scene\n";
        std::ofstream record(export_source_path(out_));
        write_export_source(source, record);
    }

    fs::path dir_;
    fs::path out_;
};

const ExportData kSiteA =
    sessions_of({{"a1", "2026-03-01T09:00:00Z"}, {"a2", "2026-03-01T10:00:00Z"}});

TEST_F(ExportSourceTest, TheRecordReadsBackAsWritten) {
    const ExportSource source = export_source(kSiteA, ExportFormat::Csv, dir_ / "a.sqlite");
    std::ostringstream text;
    write_export_source(source, text);
    EXPECT_EQ(text.str(),
              "# monoplane export source: the study sessions the export beside this file holds\n"
              "# `monoplane study export` replaces that export only with one of a database that "
              "holds every session named here, or when forced\n"
              "format csv\n"
              "database " +
                  (dir_ / "a.sqlite").string() +
                  "\n"
                  "session 1 2026-03-01T09:00:00Z a1\n"
                  "session 1 2026-03-01T10:00:00Z a2\n");
    earlier_export(source);
    EXPECT_EQ(export_source_path(out_), dir_ / "trials.csv.source");
    const Result<ExportSource> read = read_export_source(export_source_path(out_));
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->format, "csv");
    EXPECT_EQ(read->database, (dir_ / "a.sqlite").string());
    EXPECT_EQ(read->sessions, source.sessions);
}

TEST_F(ExportSourceTest, TheSameStudyWithMoreSessionsReplacesItsExport) {
    earlier_export(export_source(kSiteA, ExportFormat::Csv, "a.sqlite"));
    const ExportData grown = sessions_of({{"a1", "2026-03-01T09:00:00Z"},
                                          {"a2", "2026-03-01T10:00:00Z"},
                                          {"a3", "2026-03-02T09:00:00Z"}});
    // Another path: the database was copied or moved since.
    EXPECT_FALSE(export_source_problem(
                     out_, export_source(grown, ExportFormat::Csv, "/elsewhere/copy.sqlite"), false)
                     .has_value());
}

TEST_F(ExportSourceTest, AnotherStudysExportIsRefusedNamingItsSessions) {
    earlier_export(export_source(kSiteA, ExportFormat::Csv, "a.sqlite"));
    // Site b also has an a1, started at another time: another session.
    const ExportSource b =
        export_source(sessions_of({{"a1", "2026-03-05T09:00:00Z"}, {"b1", "2026-03-05T10:00:00Z"}}),
                      ExportFormat::Csv, "b.sqlite");
    const std::optional<OutputProblem> problem = export_source_problem(out_, b, false);
    ASSERT_TRUE(problem.has_value());
    EXPECT_EQ(problem->refusal, OutputRefusal::OtherSource);
    EXPECT_EQ(problem->what, "'" + out_.string() +
                                 "' is a csv export of another study: 2 of its 2 sessions are "
                                 "not in this database: a1 session 1 (started "
                                 "2026-03-01T09:00:00Z), a2 session 1 (started "
                                 "2026-03-01T10:00:00Z)");
    EXPECT_EQ(output_error(*problem).message,
              problem->what + "; it is replaced only when forced. Nothing was written.");
    EXPECT_FALSE(export_source_problem(out_, b, true).has_value());
}

TEST_F(ExportSourceTest, AnExportWithoutItsRecordIsRefused) {
    std::ofstream(out_) << "participant,session,trial_index,block,scene\n";
    const std::optional<OutputProblem> problem =
        export_source_problem(out_, export_source(kSiteA, ExportFormat::Csv, "a.sqlite"), false);
    ASSERT_TRUE(problem.has_value());
    EXPECT_EQ(problem->refusal, OutputRefusal::OtherSource);
    EXPECT_EQ(problem->what, "'" + out_.string() +
                                 "' is a csv export that does not record which study it came "
                                 "from ('" +
                                 out_.string() +
                                 ".source' is missing: it was written by an older monoplane, or "
                                 "copied without it)");
}

TEST_F(ExportSourceTest, AnUnreadableRecordIsRefusedNamingItsLine) {
    earlier_export(export_source(kSiteA, ExportFormat::Json, "a.sqlite"));
    std::ofstream(export_source_path(out_), std::ios::app) << "session_uuid 1234\n";
    const std::optional<OutputProblem> problem =
        export_source_problem(out_, export_source(kSiteA, ExportFormat::Json, "a.sqlite"), false);
    ASSERT_TRUE(problem.has_value());
    EXPECT_EQ(problem->what,
              "'" + out_.string() +
                  "' is a json export whose record of its study cannot be read ('" + out_.string() +
                  ".source' line 7: unknown key 'session_uuid' (written by a newer monoplane?); "
                  "expected format, database or session)");
}

TEST_F(ExportSourceTest, ANewExportNeedsNoRecord) {
    EXPECT_FALSE(export_source_problem(out_, export_source(kSiteA, ExportFormat::Csv, "a"), false)
                     .has_value());
}

TEST_F(ExportSourceTest, AFileWhereTheRecordGoesIsRefusedUnlessForced) {
    std::ofstream(export_source_path(out_)) << "my notes on the source\n";
    const std::optional<OutputProblem> problem =
        export_output_problem(out_, ExportFormat::Csv, dir_ / "a.sqlite", false);
    ASSERT_TRUE(problem.has_value());
    EXPECT_EQ(problem->refusal, OutputRefusal::NotAnEarlierOutput);
    EXPECT_EQ(problem->what, "'" + export_source_path(out_).string() +
                                 "' exists and is not an earlier export source record: it begins "
                                 "with 'my notes on the source'");
    EXPECT_FALSE(
        export_output_problem(out_, ExportFormat::Csv, dir_ / "a.sqlite", true).has_value());
}

}  // namespace
}  // namespace monoplane::study
