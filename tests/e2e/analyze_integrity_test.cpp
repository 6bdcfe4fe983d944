// `analyze` never counts a session twice nor pools protocol designs without being told (issue 42,
// parts 3 and 4), run as a lab runs it: a copy of a database analysed with its original (and a
// hard link to it, and its CSV export) is refused naming the files and the session, and with
// --drop-duplicates counts 2 participants, not 4; a backup taken while a session ran differs
// from the finished original and is refused also then; sessions of two designs are refused,
// pooled with --pool-protocols and listed in summary.json and the report; a change of text only
// is one design; a CSV export's versions are known by hash. Every run is the real executable
// (`--headset none`: the simulated observer answers).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tests/e2e/child_process.h"
#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

// Two scenes, two distances, one practice trial: 5 trials, a fraction of a second headless.
constexpr const char* kProtocol =
    "name = \"integrity\"\nscenes = [\"beams\", \"landscape\"]\nmono_planes = [3, 8]\n"
    "alternatives = [\"stereo\", \"hybrid\"]\npractice_trials = 1\n";

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

class AnalyzeIntegrityCli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("monoplane_integrity_" + std::to_string(getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        const std::string text = kProtocol;
        std::ofstream(dir_ / "p.toml") << text;
        // The same design in other words: a comment.
        std::ofstream(dir_ / "p-text.toml") << text << "# the wording of the second site\n";
        // Another design: other distances.
        std::string other = text;
        other.replace(other.find("[3, 8]"), 6, "[2, 6]");
        std::ofstream(dir_ / "q.toml") << other;
    }
    void TearDown() override {
        if (!HasFailure()) fs::remove_all(dir_);
    }

    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    int monoplane(std::vector<std::string> args, std::string* output = nullptr) {
        args.insert(args.begin(), MONOPLANE_EXE);
        std::string ignored;
        return run_to_end(args, output ? output : &ignored, dir_.string());
    }
    void session(const std::string& protocol, const std::string& db, const std::string& code) {
        std::string out;
        ASSERT_EQ(monoplane({"study", "run", "--protocol", path(protocol), "--db", path(db),
                             "--participant", code, "--headset", "none"},
                            &out),
                  0)
            << out;
    }
    // `analyze` over `inputs` (pairs of --db or --csv and a file name) and `options` into
    // DIR/out; its exit status and, in *log, what it printed.
    int analyze(const std::vector<std::pair<std::string, std::string>>& inputs,
                const std::vector<std::string>& options, std::string* log) {
        std::vector<std::string> args = {"analyze"};
        for (const auto& [option, file] : inputs) args.insert(args.end(), {option, path(file)});
        args.insert(args.end(), {"--out", path("out")});
        args.insert(args.end(), options.begin(), options.end());
        return monoplane(args, log);
    }
    nlohmann::json summary() const {
        return nlohmann::json::parse(read_file(dir_ / "out" / "summary.json"));
    }

    fs::path dir_;
};

TEST_F(AnalyzeIntegrityCli, ACopyWithItsOriginalIsRefusedAndCountedOnceWhenAsked) {
    session("p.toml", "site-a.sqlite", "k9");
    session("p.toml", "site-a.sqlite", "k10");
    fs::copy_file(dir_ / "site-a.sqlite", dir_ / "copy.sqlite");
    std::string log;
    EXPECT_EQ(analyze({{"--db", "site-a.sqlite"}, {"--db", "copy.sqlite"}}, {}, &log), 1);
    EXPECT_TRUE(contains(log, path("copy.sqlite") + " holds the same session as " +
                                  path("site-a.sqlite") + " (participant k9, session 1, "))
        << log;
    EXPECT_TRUE(contains(log, "(participant k10, session 1, ")) << log;
    EXPECT_TRUE(contains(log, "give --drop-duplicates to count each once")) << log;
    EXPECT_FALSE(fs::exists(dir_ / "out")) << "a refusal writes nothing";
    // Two sites' codes are no way around it: the copy is judged first.
    EXPECT_EQ(analyze({{"--db", "site-a.sqlite"}, {"--db", "copy.sqlite"}},
                      {"--codes", "per-database"}, &log),
              1);
    EXPECT_TRUE(contains(log, "holds the same session")) << log;

    ASSERT_EQ(
        analyze({{"--db", "site-a.sqlite"}, {"--db", "copy.sqlite"}}, {"--drop-duplicates"}, &log),
        0)
        << log;
    nlohmann::json s = summary();
    EXPECT_EQ(s.at("participants"), 2);
    EXPECT_EQ(s.at("sessions"), 2);
    EXPECT_EQ(s.at("trials").at("total"), 10);
    ASSERT_EQ(s.at("dropped_duplicates").size(), 2u);
    EXPECT_EQ(s["dropped_duplicates"][0].at("participant"), "k9");
    EXPECT_EQ(s["dropped_duplicates"][0].at("kept"), path("site-a.sqlite"));
    EXPECT_EQ(s["dropped_duplicates"][0].at("dropped")[0], path("copy.sqlite"));
    EXPECT_TRUE(
        contains(read_file(dir_ / "out" / "report.html"), "Sessions held by more than one file"));
}

TEST_F(AnalyzeIntegrityCli, AHardLinkAndAnExportAreTheSameSessionsToo) {
    session("p.toml", "site-a.sqlite", "k9");
    fs::create_hard_link(dir_ / "site-a.sqlite", dir_ / "link.sqlite");
    std::string log;
    EXPECT_EQ(analyze({{"--db", "site-a.sqlite"}, {"--db", "link.sqlite"}}, {}, &log), 1);
    EXPECT_TRUE(contains(log, "link.sqlite holds the same session as ")) << log;

    ASSERT_EQ(monoplane({"study", "export", "--db", path("site-a.sqlite"), "--format", "csv",
                         "--out", path("site-a.csv")},
                        &log),
              0)
        << log;
    EXPECT_TRUE(contains(read_file(dir_ / "site-a.csv"), ",session_uuid,software_version,"));
    EXPECT_EQ(analyze({{"--db", "site-a.sqlite"}, {"--csv", "site-a.csv"}}, {}, &log), 1);
    EXPECT_TRUE(contains(log, "site-a.csv holds the same session as ")) << log;
    EXPECT_TRUE(contains(log, "an identical copy")) << log;
    // The export's times are the database's to the nanosecond: identical, counted once.
    ASSERT_EQ(
        analyze({{"--db", "site-a.sqlite"}, {"--csv", "site-a.csv"}}, {"--drop-duplicates"}, &log),
        0)
        << log;
    EXPECT_EQ(summary().at("participants"), 1);
}

TEST_F(AnalyzeIntegrityCli, ABackupTakenWhileTheSessionRanIsRefusedAlsoWhenDropping) {
    // The session killed after some of its writes: the backup is the file as it stood then.
    const KilledRun run = run_and_kill_after(
        {MONOPLANE_EXE, "study", "run", "--protocol", path("p.toml"), "--db", path("site-a.sqlite"),
         "--participant", "k9", "--headset", "none", "--trace"},
        8, dir_.string());
    ASSERT_TRUE(run.killed) << run.output;
    for (const char* suffix : {"", "-wal"})
        if (fs::exists(path("site-a.sqlite") + suffix))
            fs::copy_file(path("site-a.sqlite") + suffix, path("backup.sqlite") + suffix);
    std::string log;
    ASSERT_EQ(monoplane({"study", "resume", "--db", path("site-a.sqlite"), "--participant", "k9",
                         "--headset", "none"},
                        &log),
              0)
        << log;
    for (const std::vector<std::string>& options :
         {std::vector<std::string>{}, std::vector<std::string>{"--drop-duplicates"}}) {
        EXPECT_EQ(analyze({{"--db", "site-a.sqlite"}, {"--db", "backup.sqlite"}}, options, &log),
                  1);
        EXPECT_TRUE(contains(log, path("backup.sqlite") + " holds the same session as " +
                                      path("site-a.sqlite") + " (participant k9, session 1, "))
            << log;
        EXPECT_TRUE(contains(log, "but the copies differ: " + path("backup.sqlite") + " has "))
            << log;
        EXPECT_TRUE(
            contains(log, " of the session's 5 trials decided, " + path("site-a.sqlite") + " 5"))
            << log;
        EXPECT_TRUE(contains(log, "not even with --drop-duplicates")) << log;
        EXPECT_FALSE(fs::exists(dir_ / "out"));
    }
}

TEST_F(AnalyzeIntegrityCli, TwoDesignsAreRefusedAndPooledWhenAskedATextChangeIsOneDesign) {
    session("p.toml", "study.sqlite", "k1");
    session("p-text.toml", "study.sqlite", "k2");
    std::string log;
    // A change of text only: one design, two versions, nothing to ask.
    ASSERT_EQ(analyze({{"--db", "study.sqlite"}}, {}, &log), 0) << log;
    nlohmann::json s = summary();
    ASSERT_EQ(s.at("protocol_versions").size(), 2u);
    EXPECT_EQ(s["protocol_versions"][0].at("design"), 1);
    EXPECT_EQ(s["protocol_versions"][1].at("design"), 1);
    EXPECT_EQ(s.at("pooled_protocols"), false);

    session("q.toml", "study.sqlite", "k3");
    EXPECT_EQ(analyze({{"--db", "study.sqlite"}}, {}, &log), 1);
    EXPECT_TRUE(contains(log, "protocol versions of different designs")) << log;
    EXPECT_TRUE(contains(
        log, ", design 2 (mono_planes: 3, 8 -> 2, 6): 1 session in " + path("study.sqlite")))
        << log;
    EXPECT_TRUE(contains(log, "Give --pool-protocols to pool them")) << log;

    ASSERT_EQ(analyze({{"--db", "study.sqlite"}}, {"--pool-protocols"}, &log), 0) << log;
    s = summary();
    ASSERT_EQ(s.at("protocol_versions").size(), 3u);
    for (int i = 0; i < 3; ++i) {
        const nlohmann::json& v = s["protocol_versions"][i];
        EXPECT_EQ(v.at("name"), "integrity");
        EXPECT_TRUE(v.at("hash").get<std::string>().starts_with("fnv1a64:"));
        EXPECT_EQ(v.at("sessions"), 1);
        EXPECT_EQ(v.at("design"), i < 2 ? 1 : 2);
    }
    EXPECT_EQ(s["protocol_versions"][2].at("design_differences")[0], "mono_planes: 3, 8 -> 2, 6");
    EXPECT_EQ(s.at("pooled_protocols"), true);
    EXPECT_EQ(s.at("participants"), 3);
    const std::string html = read_file(dir_ / "out" / "report.html");
    EXPECT_TRUE(contains(html, "<b>Pooled on request</b>"));
    EXPECT_TRUE(contains(html, "mono_planes: 3, 8 -&gt; 2, 6"));
    EXPECT_TRUE(contains(log, "pooled 3 protocol versions of different designs")) << log;
}

// A CSV export holds the protocol's hash, not its text: versions only exports hold cannot be
// compared; a version a database holds too has that database's design.
TEST_F(AnalyzeIntegrityCli, AnExportsVersionsAreKnownByHash) {
    session("p.toml", "study.sqlite", "k1");
    session("p-text.toml", "study.sqlite", "k2");
    session("p.toml", "site-b.sqlite", "k3");
    std::string log;
    for (const char* name : {"study", "site-b"}) {
        ASSERT_EQ(monoplane({"study", "export", "--db", path(name + std::string(".sqlite")),
                             "--format", "csv", "--out", path(name + std::string(".csv"))},
                            &log),
                  0)
            << log;
    }
    EXPECT_EQ(analyze({{"--csv", "study.csv"}}, {}, &log), 1);
    EXPECT_TRUE(contains(log, ", design not known: 1 session in " + path("study.csv"))) << log;
    EXPECT_TRUE(contains(log, "give the study databases instead")) << log;

    ASSERT_EQ(analyze({{"--db", "study.sqlite"}, {"--csv", "site-b.csv"}}, {}, &log), 0) << log;
    const nlohmann::json s = summary();
    ASSERT_EQ(s.at("protocol_versions").size(), 2u);
    const nlohmann::json& first = s["protocol_versions"][0];
    EXPECT_EQ(first.at("sessions"), 2);
    EXPECT_EQ(first.at("sources"),
              nlohmann::json::array({path("study.sqlite"), path("site-b.csv")}));
    EXPECT_EQ(first.at("design"), 1);
    EXPECT_EQ(s["protocol_versions"][1].at("design"), 1);
    EXPECT_EQ(s.at("pooled_protocols"), false);
}

}  // namespace
}  // namespace monoplane
