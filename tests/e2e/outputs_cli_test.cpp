// What `analyze --out` and `study export --out` write, run as a lab runs them (issue 42): the
// analysis folder is replaced whole (a scene's figures of the run before are gone), a folder of
// other files is refused with one line and left as it was, forced the analysis goes in among
// them; an export replaces only an export of the same study (more sessions since, or a copy of
// the database) and refuses another study's or one that does not record its study, unless
// forced; summary.json's integer and number variables are JSON numbers. Every run is the real
// executable (`--headset none`: the simulated observer answers).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "tests/e2e/child_process.h"
#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

// Three scenes (two for "two.toml"), two distances, one practice trial; the variables of each
// type.
std::string protocol(const std::string& scenes) {
    return "name = \"outputs\"\nscenes = [" + scenes +
           "]\nmono_planes = [3, 8]\nalternatives = [\"stereo\", \"hybrid\"]\n"
           "practice_trials = 1\n"
           "[[variables]]\nname = \"age\"\ntype = \"integer\"\nmin = 18\nmax = 99\n"
           "[[variables]]\nname = \"height_m\"\ntype = \"number\"\n"
           "[[variables]]\nname = \"vision\"\ntype = \"choice\"\n"
           "choices = [\"normal\", \"corrected\"]\n"
           "[[variables]]\nname = \"remark\"\ntype = \"text\"\n";
}

// Every file under `root`, relative, sorted (folders only where empty, as "name/").
std::set<std::string> files_in(const fs::path& root) {
    std::set<std::string> files;
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(root)) {
        const std::string name = e.path().lexically_relative(root).generic_string();
        if (!e.is_directory())
            files.insert(name);
        else if (fs::is_empty(e.path()))
            files.insert(name + "/");
    }
    return files;
}

// The files of an analysis of sessions that showed `scenes`.
std::set<std::string> analysis_files(const std::vector<std::string>& scenes) {
    std::set<std::string> files = {
        ".monoplane-analysis",      "report.html",           "summary.json",
        "rates_by_scene.csv",       "rates_by_distance.csv", "rates_by_scene_distance.csv",
        "rates_by_first_scene.csv", "logistic.csv",          "psychometric.csv",
        "questionnaire.csv"};
    for (const std::string figure : {"choices", "decision_times", "switches"}) {
        files.insert("figures/" + figure + ".svg");
        files.insert("figures/" + figure + ".png");
    }
    for (const std::string& scene : scenes) {
        files.insert("figures/psychometric_" + scene + ".svg");
        files.insert("figures/psychometric_" + scene + ".png");
    }
    return files;
}

// The sessions an export's record names, as a refusal names them: "P1 session 1 (started T)".
std::vector<std::string> recorded_sessions(const fs::path& record) {
    std::vector<std::string> sessions;
    std::istringstream lines(read_file(record));
    for (std::string line; std::getline(lines, line);) {
        if (!line.starts_with("session ")) continue;
        std::istringstream words(line.substr(8));
        std::string number, started, code;
        words >> number >> started >> code;
        sessions.push_back(code + " session " + number + " (started " + started + ")");
    }
    return sessions;
}

class OutputsCli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("monoplane_outputs_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        std::ofstream(dir_ / "three.toml") << protocol("\"beams\", \"landscape\", \"spheres\"");
        std::ofstream(dir_ / "two.toml") << protocol("\"beams\", \"landscape\"");
    }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(dir_);
    }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // `monoplane ARGS...`: its exit status, and what it printed in *output.
    int monoplane(std::vector<std::string> args, std::string* output = nullptr) {
        args.insert(args.begin(), MONOPLANE_EXE);
        std::string ignored;
        return run_to_end(args, output ? output : &ignored, dir_.string());
    }
    void session(const std::string& protocol, const std::string& db, const std::string& code,
                 const std::vector<std::string>& vars) {
        std::vector<std::string> args = {"study",     "run",    "--protocol",    path(protocol),
                                         "--db",      path(db), "--participant", code,
                                         "--headset", "none",   "--observer",    "default"};
        for (const std::string& v : vars) args.insert(args.end(), {"--var", v});
        std::string out;
        ASSERT_EQ(monoplane(args, &out), 0) << out;
    }
    int analyze(const std::string& db, const std::string& out, bool force = false,
                std::string* output = nullptr) {
        std::vector<std::string> args = {"analyze", "--db", path(db), "--out", out};
        if (force) args.push_back("--force");
        return monoplane(args, output);
    }
    int export_to(const std::string& db, const std::string& format, const std::string& out,
                  bool force = false, std::string* output = nullptr) {
        std::vector<std::string> args = {"study",    "export", "--db",  path(db),
                                         "--format", format,   "--out", out};
        if (force) args.push_back("--force");
        return monoplane(args, output);
    }

    fs::path dir_;
};

TEST_F(OutputsCli, AnalyzeReplacesOnlyItsOwnFolderAndLeavesNoStaleFile) {
    session("three.toml", "three.sqlite", "P1", {"age=34"});
    session("two.toml", "two.sqlite", "Q1", {"age=40"});
    const fs::path out = dir_ / "analysis";
    std::string log;
    ASSERT_EQ(analyze("three.sqlite", out.string(), false, &log), 0) << log;
    EXPECT_EQ(files_in(out), analysis_files({"beams", "landscape", "spheres"}));
    // A rerun on sessions of two scenes: the third scene's figures of the run before are gone.
    ASSERT_EQ(analyze("two.sqlite", out.string(), false, &log), 0) << log;
    EXPECT_EQ(files_in(out), analysis_files({"beams", "landscape"}));
    // Nothing staged is left beside it (".analysis.tmp-*").
    std::set<std::string> beside;
    for (const fs::directory_entry& e : fs::directory_iterator(dir_))
        if (e.path().filename().string().find("analysis") != std::string::npos)
            beside.insert(e.path().filename().string());
    EXPECT_EQ(beside, (std::set<std::string>{"analysis"}));
}

TEST_F(OutputsCli, AThesisFolderIsRefusedUnchangedAndForcedKeepsItsFiles) {
    session("three.toml", "three.sqlite", "P1", {"age=34"});
    session("two.toml", "two.sqlite", "Q1", {"age=40"});
    const fs::path thesis = dir_ / "thesis";
    fs::create_directories(thesis / "chapters");
    std::ofstream(thesis / "thesis.tex") << "\\chapter{Results}\n";
    std::ofstream(thesis / "chapters" / "one.tex") << "one\n";
    std::string log;
    EXPECT_EQ(analyze("three.sqlite", thesis.string(), false, &log), 1);
    EXPECT_EQ(log, "monoplane: --out '" + thesis.string() +
                       "' holds files analyze did not write: chapters/, thesis.tex. Nothing was "
                       "written. Choose a new or empty folder for --out, or give --force to write "
                       "among them (files of the same names are replaced, the others kept).\n");
    EXPECT_EQ(files_in(thesis), (std::set<std::string>{"chapters/one.tex", "thesis.tex"}));
    // Forced: the analysis among the thesis's files, which stay as they were.
    ASSERT_EQ(analyze("three.sqlite", thesis.string(), true, &log), 0) << log;
    std::set<std::string> expected = analysis_files({"beams", "landscape", "spheres"});
    for (const char* mine : {"chapters/one.tex", "thesis.tex"}) expected.insert(mine);
    EXPECT_EQ(files_in(thesis), expected);
    EXPECT_EQ(read_file(thesis / "thesis.tex"), "\\chapter{Results}\n");
    // Forced again with two scenes: the earlier analysis's third scene goes, the thesis stays.
    ASSERT_EQ(analyze("two.sqlite", thesis.string(), true, &log), 0) << log;
    expected = analysis_files({"beams", "landscape"});
    for (const char* mine : {"chapters/one.tex", "thesis.tex"}) expected.insert(mine);
    EXPECT_EQ(files_in(thesis), expected);
    // A file where the folder should be: refused, forced or not.
    std::ofstream(dir_ / "notes.txt") << "mine\n";
    EXPECT_EQ(analyze("two.sqlite", path("notes.txt"), true, &log), 1);
    EXPECT_EQ(log, "monoplane: --out '" + path("notes.txt") +
                       "' exists and is not a folder; choose another --out (--force does not "
                       "replace a file with a folder). Nothing was written.\n");
    EXPECT_EQ(read_file(dir_ / "notes.txt"), "mine\n");
}

TEST_F(OutputsCli, SummaryJsonKeepsTheVariablesTypes) {
    session("three.toml", "three.sqlite", "P1",
            {"age=34", "height_m=1.75", "vision=normal", "remark=12"});
    session("three.toml", "three.sqlite", "P2", {"age=51", "height_m=2", "vision=corrected"});
    std::string log;
    ASSERT_EQ(analyze("three.sqlite", path("db"), false, &log), 0) << log;
    const nlohmann::json db = nlohmann::json::parse(read_file(dir_ / "db" / "summary.json"));
    const nlohmann::json& p1 = db.at("participant_details").at(0).at("variables");
    const nlohmann::json& p2 = db.at("participant_details").at(1).at("variables");
    EXPECT_TRUE(p1.at("age").is_number_integer());
    EXPECT_EQ(p1.at("age"), 34);
    EXPECT_TRUE(p1.at("height_m").is_number_float());
    EXPECT_EQ(p1.at("height_m"), 1.75);
    EXPECT_EQ(p1.at("vision"), "normal");
    EXPECT_EQ(p1.at("remark"), "12");  // text, whatever it looks like
    EXPECT_EQ(p2.at("age"), 51);
    EXPECT_TRUE(p2.at("height_m").is_number());
    EXPECT_EQ(p2.at("height_m"), 2);
    EXPECT_TRUE(p2.at("remark").is_null());
    // From the CSV export, which records no types, columns of numbers are numbers.
    ASSERT_EQ(export_to("three.sqlite", "csv", path("three.csv"), false, &log), 0) << log;
    ASSERT_EQ(monoplane({"analyze", "--csv", path("three.csv"), "--out", path("csv")}, &log), 0)
        << log;
    const nlohmann::json csv = nlohmann::json::parse(read_file(dir_ / "csv" / "summary.json"));
    const nlohmann::json& c1 = csv.at("participant_details").at(0).at("variables");
    EXPECT_EQ(c1.at("age"), 34);
    EXPECT_EQ(c1.at("height_m"), 1.75);
    EXPECT_EQ(c1.at("vision"), "normal");
}

TEST_F(OutputsCli, AnExportReplacesOnlyAnExportOfTheSameStudy) {
    session("three.toml", "three.sqlite", "P1", {"age=34"});
    session("three.toml", "three.sqlite", "P2", {"age=51"});
    session("two.toml", "two.sqlite", "Q1", {"age=40"});
    const fs::path csv = dir_ / "site.csv";
    const fs::path record = dir_ / "site.csv.source";
    std::string log;
    ASSERT_EQ(export_to("three.sqlite", "csv", csv.string(), false, &log), 0) << log;
    const std::vector<std::string> sessions = recorded_sessions(record);
    ASSERT_EQ(sessions.size(), 2u);
    EXPECT_TRUE(sessions[0].starts_with("P1 session 1 (started ")) << sessions[0];
    EXPECT_TRUE(sessions[1].starts_with("P2 session 1 (started ")) << sessions[1];
    const std::string csv_bytes = read_file(csv);
    const std::string record_bytes = read_file(record);
    // Another study's export of the same format: refused, both files as they were.
    EXPECT_EQ(export_to("two.sqlite", "csv", csv.string(), false, &log), 1);
    EXPECT_EQ(log,
              "monoplane: '" + csv.string() +
                  "' is a csv export of another study: 2 of its 2 sessions are not in this "
                  "database: " +
                  sessions[0] + ", " + sessions[1] +
                  ". Give --force to replace it, or choose another --out. Nothing was written.\n");
    EXPECT_EQ(read_file(csv), csv_bytes);
    EXPECT_EQ(read_file(record), record_bytes);
    // The same study with a session more, and a copy of its database elsewhere: replaced.
    session("three.toml", "three.sqlite", "P3", {"age=29"});
    ASSERT_EQ(export_to("three.sqlite", "csv", csv.string(), false, &log), 0) << log;
    EXPECT_EQ(recorded_sessions(record).size(), 3u);
    fs::create_directories(dir_ / "copy");
    fs::copy_file(dir_ / "three.sqlite", dir_ / "copy" / "three.sqlite");
    ASSERT_EQ(export_to("copy/three.sqlite", "csv", csv.string(), false, &log), 0) << log;
    // Forced: another study's export replaces it, and its record says so.
    ASSERT_EQ(export_to("two.sqlite", "csv", csv.string(), true, &log), 0) << log;
    ASSERT_EQ(recorded_sessions(record).size(), 1u);
    EXPECT_TRUE(recorded_sessions(record)[0].starts_with("Q1 session 1 ("));
}

TEST_F(OutputsCli, AJsonExportWithoutItsRecordIsReplacedOnlyWhenForced) {
    session("three.toml", "three.sqlite", "P1", {"age=34"});
    session("two.toml", "two.sqlite", "Q1", {"age=40"});
    const fs::path json = dir_ / "site.json";
    std::string log;
    ASSERT_EQ(export_to("three.sqlite", "json", json.string(), false, &log), 0) << log;
    EXPECT_EQ(export_to("two.sqlite", "json", json.string(), false, &log), 1);
    EXPECT_NE(log.find("is a json export of another study: 1 of its 1 session is not in this "
                       "database: P1 session 1 (started "),
              std::string::npos)
        << log;
    // An export whose record is gone (an older monoplane's, a copy without it): refused, even
    // from its own study, since nothing says which study it is.
    fs::remove(dir_ / "site.json.source");
    const std::string bytes = read_file(json);
    EXPECT_EQ(export_to("three.sqlite", "json", json.string(), false, &log), 1);
    EXPECT_EQ(log, "monoplane: '" + json.string() +
                       "' is a json export that does not record which study it came from ('" +
                       json.string() +
                       ".source' is missing: it was written by an older monoplane, or copied "
                       "without it). Give --force to replace it, or choose another --out. Nothing "
                       "was written.\n");
    EXPECT_EQ(read_file(json), bytes);
    EXPECT_FALSE(fs::exists(dir_ / "site.json.source"));
    ASSERT_EQ(export_to("three.sqlite", "json", json.string(), true, &log), 0) << log;
    EXPECT_EQ(recorded_sessions(dir_ / "site.json.source").size(), 1u);
}

}  // namespace
}  // namespace monoplane
