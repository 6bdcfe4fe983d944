// The command line's words for the libraries' refusals (app/commands/option_wording.h): the
// libraries say what is wrong in their own terms, and the commands' users read the same
// messages as before, naming --out, --force, --var, --session, --participant-number and --codes.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "app/commands/option_wording.h"
#include "study/participant_variables.h"
#include "study/session_start.h"

namespace monoplane::app {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

class OutputOption : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "cli_wording_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string refusal(const fs::path& out, const std::vector<fs::path>& inputs, bool force) {
        const Result<void> checked =
            check_output_option(out, export_option_kind(study::ExportFormat::Csv), inputs, force);
        return checked ? std::string("(allowed)") : checked.error().message;
    }

    fs::path dir_;
};

TEST_F(OutputOption, EachRefusalNamesTheOptionsAsBefore) {
    EXPECT_EQ(refusal("", {}, false), "the output file name (--out) is empty");
    const fs::path db = dir_ / "s.sqlite";
    std::ofstream(db) << "x";
    EXPECT_EQ(refusal(db, {db}, true),
              "'" + db.string() +
                  "' is a file this command reads: writing there would destroy it; choose "
                  "another --out (--force never allows this). Nothing was written.");
    const fs::path protocol = dir_ / "day.toml";
    std::ofstream(protocol) << "name = \"day\"\n";
    EXPECT_EQ(refusal(protocol, {}, false),
              "'" + protocol.string() +
                  "' exists and is not an earlier export of --format csv: it begins with 'name = "
                  "\"day\"'. Give --force to replace it, or choose another --out. Nothing was "
                  "written.");
    EXPECT_EQ(refusal(protocol, {}, true), "(allowed)");
    EXPECT_EQ(refusal(dir_, {}, true), "'" + dir_.string() +
                                           "' exists and is a folder; --out must name a file. "
                                           "Nothing was written.");
    const fs::path missing = dir_ / "results" / "trials.csv";
    EXPECT_EQ(refusal(missing, {}, false),
              "the folder '" + (dir_ / "results").string() + "' for the output '" +
                  missing.string() +
                  "' does not exist; create it first or choose another --out. Nothing was "
                  "written.");
    const study::OutputProblem database{study::OutputRefusal::IsADatabase, "'x' is an SQLite"};
    EXPECT_EQ(output_option_error(database).message,
              "'x' is an SQLite, also with --force; choose another --out. Nothing was written.");
}

const std::vector<study::ParticipantVariable> kDeclarations = {
    {"age", study::VariableType::Integer, 18.0, 99.0, {}, true, "Age in years"},
    {"vision",
     study::VariableType::Choice,
     std::nullopt,
     std::nullopt,
     {"normal", "other"},
     true,
     ""},
};

TEST(StudyRunOptions, VariablesAreNamedByTheirOption) {
    const Result<std::vector<study::VariableValue>> values = study::check_variables(
        kDeclarations, {"age=17", "agee=3", "vision"}, study_run_option_names());
    ASSERT_FALSE(values.ok());
    EXPECT_EQ(values.error().message,
              "--var age=17: out of range; age must be an integer from 18 to 99\n"
              "--var agee=3: unknown variable 'agee'; did you mean 'age'?\n"
              "--var vision: expected NAME=VALUE (the protocol declares: age, vision)\n"
              "variable 'vision' is required: give --var vision=VALUE, one of normal, other");
    EXPECT_EQ(study::check_variable_value(kDeclarations[1], "Normal", study_run_option_names())
                  .error()
                  .message,
              "--var vision=Normal: not one of normal, other; did you mean 'normal'?");
}

TEST(StudyRunOptions, SessionAndParticipantNumbersAreNamedByTheirOptions) {
    const Result<study::Protocol> protocol = study::parse_protocol(
        "name = \"plain\"\nscenes = [\"beams\"]\nmono_planes = [3, 8]\n"
        "alternatives = [\"stereo\", \"hybrid\"]\n",
        "plain.toml");
    ASSERT_TRUE(protocol.ok()) << protocol.error().message;
    study::SessionRequest request;
    request.participant_code = "P1";
    request.session_number = 0;
    request.participant_number = 0;
    const Result<study::SessionStart> start =
        study::plan_session(nullptr, *protocol, request, study_run_option_names());
    ASSERT_FALSE(start.ok());
    EXPECT_EQ(start.error().message,
              "--session 0: sessions are numbered from 1\n"
              "--participant-number 0: participants are numbered from 1");
    request.session_number = 2;
    request.participant_number.reset();
    const Result<study::SessionStart> later =
        study::plan_session(nullptr, *protocol, request, study_run_option_names());
    ASSERT_FALSE(later.ok());
    EXPECT_TRUE(contains(later.error().message,
                         "--session 2: participant P1 has no session in DATABASE yet; to "
                         "continue sessions run on another PC, also give --participant-number "
                         "(their number there)"))
        << later.error().message;
}

TEST(AnalyzeOptions, SharedCodesNameTheCodesOption) {
    analysis::Dataset d;
    d.sources = {"a/site-a.sqlite", "b/site-b.sqlite"};
    for (const std::string& source : d.sources) {
        analysis::TrialRow t;
        t.source = source;
        t.participant = "a1";
        d.trials.push_back(t);
    }
    const Result<void> refused =
        analysis::join_participant_codes(d, analysis::SharedCodes::Refuse, codes_option_names());
    ASSERT_FALSE(refused.ok());
    const std::string& message = refused.error().message;
    EXPECT_TRUE(contains(message,
                         "\nanalyze does not merge participants from different files without "
                         "being told who they are; run it again with one of:"
                         "\n  --codes same-person   they are the same people (e.g. sessions run "
                         "on two lab PCs)"))
        << message;
    EXPECT_TRUE(contains(message,
                         "\n  --codes per-database  each file's codes are its own (e.g. two "
                         "sites): every code is prefixed with its file's name (site-a/a1, "
                         "site-b/a1)"))
        << message;
}

}  // namespace
}  // namespace monoplane::app
