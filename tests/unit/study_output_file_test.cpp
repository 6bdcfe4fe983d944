// Output files that never destroy what a lab has (study/output_file.h): an export's output that
// is the study database (by any path), any SQLite database, or an existing file that is not an
// earlier export of the same format is refused with a message naming the file and whether
// forcing helps, and nothing changes (bytes and modification time); new files, earlier exports
// of the same format and, forced, other files that are not databases are written whole, by a
// rename. The CLI's words for the same refusals (--out, --force) are cli_wording_test's.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

#include "study/export.h"
#include "study/output_file.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

std::string read_all(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_all(const fs::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

// A file's bytes and modification time, set an hour back so that any write would change it.
struct Snapshot {
    std::string bytes;
    fs::file_time_type mtime;
    bool operator==(const Snapshot&) const = default;
};

Snapshot age_and_snapshot(const fs::path& path) {
    fs::last_write_time(path, fs::file_time_type::clock::now() - std::chrono::hours(1));
    return {read_all(path), fs::last_write_time(path)};
}

Snapshot snapshot(const fs::path& path) {
    return {read_all(path), fs::last_write_time(path)};
}

class OutputFile : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "output_file_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        Result<std::unique_ptr<StudyStore>> store = StudyStore::open(dir_ / "study.db");
        ASSERT_TRUE(store.ok()) << store.error().message;
        store_ = std::move(store).value();
    }
    void TearDown() override {
        store_.reset();
        fs::remove_all(dir_);
    }

    // Exports the (empty) study as `format` to `out`, as `study export` does.
    Result<void> export_to(const fs::path& out, ExportFormat format, bool force) {
        return export_trials(*store_, format, out, force);
    }

    // `out` is refused for `refusal` with a message naming it and saying whether forcing
    // would help, unchanged, and no temporary file is left in its folder.
    void expect_refused(const fs::path& out, ExportFormat format, bool force,
                        const std::string& reason, OutputRefusal refusal) {
        const Snapshot before = age_and_snapshot(out);
        const std::optional<OutputProblem> problem =
            output_problem(out, export_output_kind(format), {store_->path()}, force);
        ASSERT_TRUE(problem.has_value()) << out;
        EXPECT_EQ(problem->refusal, refusal) << problem->what;
        const Result<void> refused = export_to(out, format, force);
        ASSERT_FALSE(refused.ok()) << out;
        const std::string& message = refused.error().message;
        EXPECT_TRUE(message.starts_with(problem->what)) << message;
        EXPECT_NE(message.find("'" + out.string() + "'"), std::string::npos) << message;
        EXPECT_NE(message.find(reason), std::string::npos) << message;
        const bool force_helps = refusal == OutputRefusal::NotAnEarlierOutput;
        EXPECT_EQ(message.find("replaced only when forced") != std::string::npos, force_helps)
            << message;
        EXPECT_EQ(message.find("even when forced") != std::string::npos, !force_helps) << message;
        EXPECT_NE(message.find("Nothing was written"), std::string::npos) << message;
        EXPECT_TRUE(snapshot(out) == before) << out << " changed";
        expect_no_temporary_files();
    }

    void expect_no_temporary_files() {
        for (const fs::directory_entry& entry : fs::directory_iterator(dir_)) {
            EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos)
                << entry.path();
        }
    }

    fs::path dir_;
    std::unique_ptr<StudyStore> store_;
};

// `study export --out s.sqlite` onto the study itself, spelled another way: refused, forced
// or not, and the database is intact.
TEST_F(OutputFile, RefusesTheStudyDatabaseByAnotherPath) {
    const fs::path relative = fs::relative(dir_ / "study.db", fs::current_path());
    ASSERT_NE(relative, dir_ / "study.db");
    expect_refused(relative, ExportFormat::Csv, false,
                   "is the same file as '" + (dir_ / "study.db").string() +
                       "', the database this command reads",
                   OutputRefusal::IsAnInput);
    expect_refused(dir_ / "study.db", ExportFormat::Csv, true,
                   "' is the database this command reads: writing there would destroy it",
                   OutputRefusal::IsAnInput);
    expect_refused(dir_ / "." / "study.db", ExportFormat::Json, true,
                   "the database this command reads", OutputRefusal::IsAnInput);
    fs::create_directory(dir_ / "sub");
    expect_refused(dir_ / "sub" / ".." / "study.db", ExportFormat::NotesCsv, true,
                   "the database this command reads", OutputRefusal::IsAnInput);
    EXPECT_TRUE(StudyStore::open(dir_ / "study.db").ok());
}

TEST_F(OutputFile, RefusesASymbolicLinkToTheDatabase) {
    fs::create_symlink(dir_ / "study.db", dir_ / "trials.csv");
    expect_refused(dir_ / "trials.csv", ExportFormat::Csv, true, "the database this command reads",
                   OutputRefusal::IsAnInput);
    EXPECT_TRUE(fs::is_symlink(dir_ / "trials.csv"));
    // Not an input of this command, still a database: refused as one.
    const Result<void> other =
        check_output(dir_ / "trials.csv", export_output_kind(ExportFormat::Csv), {}, true);
    ASSERT_FALSE(other.ok());
    EXPECT_NE(other.error().message.find("is an SQLite database"), std::string::npos);
}

// Another study's database (any SQLite file, whatever its name) is never replaced.
TEST_F(OutputFile, RefusesAnySqliteDatabase) {
    const fs::path other = dir_ / "other_study.csv";
    sqlite3* db = nullptr;
    ASSERT_EQ(sqlite3_open(other.c_str(), &db), SQLITE_OK);
    ASSERT_EQ(
        sqlite3_exec(db, "CREATE TABLE t(x); INSERT INTO t VALUES (1);", nullptr, nullptr, nullptr),
        SQLITE_OK);
    sqlite3_close(db);
    ASSERT_TRUE(is_sqlite_file(other));
    expect_refused(other, ExportFormat::Csv, false, "is an SQLite database",
                   OutputRefusal::IsADatabase);
    expect_refused(other, ExportFormat::Csv, true, "is an SQLite database",
                   OutputRefusal::IsADatabase);
}

// The write-ahead log and the other files beside the database belong to it.
TEST_F(OutputFile, RefusesTheDatabasesCompanionFiles) {
    for (const std::string suffix : {"-wal", "-shm", "-journal", "-holds"}) {
        const fs::path companion = dir_ / ("study.db" + suffix);
        const Result<void> refused = check_output(companion, export_output_kind(ExportFormat::Csv),
                                                  {dir_ / "study.db"}, true);
        ASSERT_FALSE(refused.ok()) << suffix;
        EXPECT_NE(refused.error().message.find("belongs to the database"), std::string::npos)
            << refused.error().message;
    }
}

TEST_F(OutputFile, RefusesAProtocolUnlessForced) {
    const fs::path protocol = dir_ / "fink2019.toml";
    write_all(protocol, "name = \"fink2019\"\nscenes = [\"beams\"]\n");
    expect_refused(protocol, ExportFormat::Csv, false,
                   "is not an earlier csv export: it begins with 'name = \"fink2019\"';",
                   OutputRefusal::NotAnEarlierOutput);
    ASSERT_TRUE(export_to(protocol, ExportFormat::Csv, true).ok());
    EXPECT_EQ(read_all(protocol).substr(0, 28), "participant,session,trial_in");
}

// An earlier export of another format is not replaced by mistake; one of the same format is.
TEST_F(OutputFile, RefusesAnEarlierExportOfAnotherFormat) {
    const fs::path notes = dir_ / "notes.csv";
    ASSERT_TRUE(export_to(notes, ExportFormat::NotesCsv, false).ok());
    expect_refused(notes, ExportFormat::Csv, false, "is not an earlier csv export",
                   OutputRefusal::NotAnEarlierOutput);
    expect_refused(notes, ExportFormat::FramesCsv, false, "is not an earlier frames-csv export",
                   OutputRefusal::NotAnEarlierOutput);
    const fs::path json = dir_ / "trials.json";
    ASSERT_TRUE(export_to(json, ExportFormat::Json, false).ok());
    expect_refused(json, ExportFormat::NotesCsv, false, "is not an earlier notes-csv export",
                   OutputRefusal::NotAnEarlierOutput);
}

TEST_F(OutputFile, WritesNewFilesAndReplacesEarlierExportsOfTheSameFormat) {
    for (ExportFormat format :
         {ExportFormat::Csv, ExportFormat::Json, ExportFormat::FramesCsv, ExportFormat::NotesCsv}) {
        const fs::path out = dir_ / ("export." + std::string(export_format_name(format)));
        ASSERT_TRUE(export_to(out, format, false).ok()) << export_format_name(format);
        const std::string first = read_all(out);
        ASSERT_FALSE(first.empty());
        age_and_snapshot(out);
        const Result<void> again = export_to(out, format, false);
        ASSERT_TRUE(again.ok()) << again.error().message;
        EXPECT_EQ(read_all(out), first);
    }
    expect_no_temporary_files();
}

TEST_F(OutputFile, AMissingFolderOrAFolderAsOutputIsAnError) {
    const Result<void> missing =
        export_to(dir_ / "results" / "trials.csv", ExportFormat::Csv, true);
    ASSERT_FALSE(missing.ok());
    EXPECT_NE(missing.error().message.find("the folder '" + (dir_ / "results").string() +
                                           "' for the output"),
              std::string::npos)
        << missing.error().message;
    EXPECT_FALSE(fs::exists(dir_ / "results"));
    const Result<void> folder = export_to(dir_, ExportFormat::Csv, true);
    ASSERT_FALSE(folder.ok());
    EXPECT_NE(folder.error().message.find("is a folder"), std::string::npos)
        << folder.error().message;
}

// A failing writer leaves the old file as it was and nothing beside it.
TEST_F(OutputFile, AFailedWriteLeavesTheOldFile) {
    const fs::path out = dir_ / "trials.csv";
    write_all(out, "old");
    const Snapshot before = age_and_snapshot(out);
    const Result<void> failed = write_file_atomically(out, [](std::ostream& s) -> Result<void> {
        s << "half of it";
        return Error{"the database went away"};
    });
    ASSERT_FALSE(failed.ok());
    EXPECT_EQ(failed.error().message, "the database went away");
    EXPECT_TRUE(snapshot(out) == before);
    expect_no_temporary_files();
}

// A replaced file keeps its permissions; a new one gets 0666 less the umask; through a
// symbolic link the file it points to is replaced and the link stays.
TEST_F(OutputFile, ModesAndLinksAreKept) {
    const auto write = [](const std::string& text) {
        return [text](std::ostream& s) -> Result<void> {
            s << text;
            return Ok{};
        };
    };
    const fs::path kept = dir_ / "kept.csv";
    write_all(kept, "old");
    fs::permissions(kept, fs::perms::owner_read | fs::perms::owner_write);
    ASSERT_TRUE(write_file_atomically(kept, write("new")).ok());
    EXPECT_EQ(read_all(kept), "new");
    EXPECT_EQ(fs::status(kept).permissions(), fs::perms::owner_read | fs::perms::owner_write);

    const mode_t mask = ::umask(022);
    ::umask(mask);
    const fs::path fresh = dir_ / "fresh.csv";
    ASSERT_TRUE(write_file_atomically(fresh, write("x")).ok());
    EXPECT_EQ(static_cast<mode_t>(fs::status(fresh).permissions()),
              static_cast<mode_t>(0666 & ~mask));

    fs::create_symlink(kept, dir_ / "link.csv");
    ASSERT_TRUE(write_file_atomically(dir_ / "link.csv", write("through the link")).ok());
    EXPECT_TRUE(fs::is_symlink(dir_ / "link.csv"));
    EXPECT_EQ(read_all(kept), "through the link");
    expect_no_temporary_files();
}

}  // namespace
}  // namespace monoplane::study
