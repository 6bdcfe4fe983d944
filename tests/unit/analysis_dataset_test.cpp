// read_export_csv() on hand-written exports in the column order of `monoplane study export
// --format csv` (docs/data.md), derive_session_fields() and merge().
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "analysis/csv.h"
#include "analysis/dataset.h"

namespace monoplane::analysis {
namespace {

const std::filesystem::path kFixtures = MONOPLANE_ANALYSIS_FIXTURES;

const std::string kHeader =
    "participant,session,trial_index,block,scene,mono_plane,label1_mode,choice,chosen_mode,valid,"
    "switches,time_label1_s,time_label2_s,decision_time_s,practice,decided,label2_mode,"
    "participant_index,protocol,protocol_hash,observer,runtime,hmd,session_status";

// A file in the test's temporary directory with the given text.
std::filesystem::path write_file(const std::string& name, const std::string& text) {
    const std::filesystem::path path = std::filesystem::path(testing::TempDir()) / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

TEST(ReadExportCsv, ReadsTheHandWrittenExport) {
    // tiny.csv: 2 sessions of 5 trials; quoted fields with commas and doubled quotes; practice
    // rows (block NA); an undecided trial whose outcome columns are all NA; a person (observer NA).
    const Result<Dataset> read = read_export_csv(kFixtures / "tiny.csv");
    ASSERT_TRUE(read.ok()) << read.error().message;
    const Dataset& data = *read;
    ASSERT_EQ(data.trials.size(), 10u);
    EXPECT_TRUE(data.answers.empty());
    ASSERT_EQ(data.sources.size(), 1u);
    EXPECT_EQ(data.sources[0], (kFixtures / "tiny.csv").string());

    const TrialRow& practice = data.trials[0];
    EXPECT_EQ(practice.source, data.sources[0]);
    EXPECT_EQ(practice.participant, "A1");
    EXPECT_EQ(practice.session_id, 1);
    EXPECT_EQ(practice.protocol, "pilot, v2");  // quoted, with a comma
    EXPECT_TRUE(practice.practice);
    EXPECT_EQ(practice.block, -1);
    EXPECT_EQ(practice.scene, "beams");

    const TrialRow& first = data.trials[1];
    EXPECT_EQ(first.trial_index, 1);
    EXPECT_EQ(first.block, 0);
    EXPECT_EQ(first.scene, "spheres");
    EXPECT_EQ(first.mono_plane, 3.0);
    EXPECT_EQ(first.label1_mode, "hybrid");
    EXPECT_EQ(first.label2_mode, "stereo");
    EXPECT_TRUE(first.decided);
    EXPECT_TRUE(first.valid);
    EXPECT_EQ(first.chosen_mode, "hybrid");
    EXPECT_EQ(first.switches, 4);
    EXPECT_DOUBLE_EQ(first.decision_time_s, 4.750000001);
    EXPECT_EQ(first.reference_mode, "stereo");
    EXPECT_EQ(first.test_mode, "hybrid");
    EXPECT_TRUE(first.chose_test);
    EXPECT_EQ(first.first_scene, "spheres");

    const TrialRow& invalid = data.trials[4];
    EXPECT_TRUE(invalid.decided);
    EXPECT_FALSE(invalid.valid);
    EXPECT_FALSE(invalid.chose_test);  // chose stereo

    const TrialRow& undecided = data.trials[9];
    EXPECT_EQ(undecided.participant, "B2");
    EXPECT_FALSE(undecided.decided);
    EXPECT_EQ(undecided.chosen_mode, "");
    EXPECT_FALSE(undecided.chose_test);
    EXPECT_EQ(undecided.first_scene, "beams");  // B2's block 0
    EXPECT_EQ(undecided.mono_plane, 3.0);
}

TEST(ReadExportCsv, ReadsTheGeneratedFixture) {
    // choices.csv (make_reference.py): 6 sessions x (2 practice + 12 data) trials.
    const Result<Dataset> read = read_export_csv(kFixtures / "choices.csv");
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(read->trials.size(), 84u);
    for (const TrialRow& t : read->trials) {
        EXPECT_EQ(t.reference_mode, "stereo");
        EXPECT_EQ(t.test_mode, "hybrid");
        EXPECT_FALSE(t.first_scene.empty());
    }
}

TEST(ReadExportCsv, AcceptsCrlfReorderedAndExtraColumnsAndOtherBooleanSpellings) {
    // As pandas or R may write the file back: another column order, an added column, CRLF,
    // TRUE/FALSE, integers as floats.
    const std::filesystem::path path = write_file(
        "roundtrip.csv",
        "\xEF\xBB\xBFscene,participant,session,trial_index,block,mono_plane,label1_mode,"
        "label2_mode,chosen_mode,valid,switches,decision_time_s,practice,decided,extra\r\n"
        "beams,P1,3.0,0,0.0,8.0,stereo,hybrid,hybrid,TRUE,2,1.5,FALSE,True,x\r\n"
        "\r\n"
        "beams,P1,3,1,0,3,hybrid,stereo,stereo,1,1,2,0,1,y\r\n");
    const Result<Dataset> read = read_export_csv(path);
    ASSERT_TRUE(read.ok()) << read.error().message;
    ASSERT_EQ(read->trials.size(), 2u);
    EXPECT_EQ(read->trials[0].session_id, 3);
    EXPECT_EQ(read->trials[0].block, 0);
    EXPECT_EQ(read->trials[0].mono_plane, 8.0);
    EXPECT_TRUE(read->trials[0].chose_test);
    EXPECT_FALSE(read->trials[1].chose_test);
    EXPECT_TRUE(read->trials[1].valid);
    EXPECT_EQ(read->trials[0].protocol, "");  // no protocol column: metadata only
}

TEST(ReadExportCsv, ReadsNaAndUpperCaseBooleansAsTheExportWritesThem) {
    // The export's own spelling (docs/data.md): NA for missing values, TRUE/FALSE.
    const std::filesystem::path path = write_file(
        "na.csv",
        kHeader + "\n" +
            "A,1,0,NA,beams,5,stereo,1,stereo,TRUE,2,1,1,2,TRUE,TRUE,hybrid,0,p,h,NA,none,vive,"
            "aborted\n"
            "A,1,1,0,spheres,3,hybrid,2,stereo,FALSE,0,1,0,1.5,FALSE,TRUE,stereo,0,p,h,NA,none,"
            "vive,aborted\n"
            "A,1,2,0,spheres,8,stereo,NA,NA,NA,NA,NA,NA,NA,FALSE,FALSE,hybrid,0,p,h,NA,none,vive,"
            "aborted\n");
    const Result<Dataset> read = read_export_csv(path);
    ASSERT_TRUE(read.ok()) << read.error().message;
    ASSERT_EQ(read->trials.size(), 3u);
    EXPECT_TRUE(read->trials[0].practice);
    EXPECT_EQ(read->trials[0].block, -1);
    EXPECT_TRUE(read->trials[0].valid);
    EXPECT_FALSE(read->trials[1].practice);
    EXPECT_EQ(read->trials[1].block, 0);
    EXPECT_TRUE(read->trials[1].decided);
    EXPECT_FALSE(read->trials[1].valid);
    EXPECT_EQ(read->trials[1].switches, 0);
    EXPECT_DOUBLE_EQ(read->trials[1].decision_time_s, 1.5);
    EXPECT_FALSE(read->trials[2].decided);
    EXPECT_EQ(read->trials[2].chosen_mode, "");
}

// The gaze columns of a headset session's export (docs/gaze.md): the mean error at gaze under
// each label becomes the error on the test alternative by which label showed it (hybrid: label 2
// in the first trial, label 1 in the second); NA leaves none. An export without the columns
// (every test above) reads with none.
TEST(ReadExportCsv, ReadsTheGazeColumnsByTheLabelThatShowedTheTestMode) {
    const std::filesystem::path path = write_file(
        "gaze.csv",
        kHeader +
            ",gaze_samples,gaze_share_beyond_m,gaze_error_mean_arcmin_1,"
            "gaze_error_mean_arcmin_2,gaze_error_max_arcmin_1,gaze_error_max_arcmin_2,"
            "gaze_fixations\n" +
            "A,1,0,0,beams,3,stereo,1,stereo,TRUE,2,1,1,2,FALSE,TRUE,hybrid,0,p,h,NA,none,vive,"
            "completed,40,0.25,0,7.5,0,9,3\n"
            "A,1,1,0,beams,8,hybrid,2,stereo,TRUE,1,1,1,2,FALSE,TRUE,stereo,0,p,h,NA,none,vive,"
            "completed,38,0.5,2.25,0,3,0,2\n"
            "A,1,2,0,beams,8,hybrid,2,stereo,TRUE,1,1,1,2,FALSE,TRUE,stereo,0,p,h,NA,none,vive,"
            "completed,0,NA,NA,NA,NA,NA,0\n");
    const Result<Dataset> read = read_export_csv(path);
    ASSERT_TRUE(read.ok()) << read.error().message;
    ASSERT_EQ(read->trials.size(), 3u);
    EXPECT_EQ(read->trials[0].test_mode, "hybrid");
    EXPECT_EQ(read->trials[0].gaze_error_test_arcmin, 7.5);
    EXPECT_EQ(read->trials[0].gaze_share_beyond_m, 0.25);
    EXPECT_EQ(read->trials[1].gaze_error_test_arcmin, 2.25);
    EXPECT_EQ(read->trials[1].gaze_share_beyond_m, 0.5);
    EXPECT_FALSE(read->trials[2].gaze_error_test_arcmin.has_value());
    EXPECT_FALSE(read->trials[2].gaze_share_beyond_m.has_value());

    const Result<Dataset> without = read_export_csv(kFixtures / "tiny.csv");
    ASSERT_TRUE(without.ok()) << without.error().message;
    for (const TrialRow& t : without->trials) {
        EXPECT_FALSE(t.gaze_error_test_arcmin.has_value());
        EXPECT_FALSE(t.gaze_share_beyond_m.has_value());
    }
}

TEST(ReadExportCsv, ABadGazeNumberNamesFileLineAndColumn) {
    const std::filesystem::path path = write_file(
        "bad_gaze.csv",
        kHeader + ",gaze_error_mean_arcmin_1\n" +
            "A,1,0,0,beams,3,stereo,1,stereo,TRUE,2,1,1,2,FALSE,TRUE,hybrid,0,p,h,NA,none,vive,"
            "completed,lots\n");
    const Result<Dataset> read = read_export_csv(path);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().message, path.string() +
                                        ":2: column 'gaze_error_mean_arcmin_1' (column 25): "
                                        "'lots' is not a number");
}

TEST(ReadExportCsv, ADecidedTrialWithNaOutcomeIsRefused) {
    const std::filesystem::path path = write_file(
        "na_outcome.csv",
        kHeader + "\n" +
            "A,1,0,0,beams,3,stereo,NA,NA,NA,NA,NA,NA,NA,FALSE,TRUE,hybrid,0,p,h,NA,none,vive,"
            "completed\n");
    const Result<Dataset> read = read_export_csv(path);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().message,
              path.string() + ":2: column 'chosen_mode' (column 9): 'NA' where a value is needed");
}

TEST(ReadExportCsv, AMissingColumnNamesFileLineAndColumn) {
    std::string header = kHeader;
    header.replace(header.find("mono_plane,"), 11, "");
    const std::filesystem::path path = write_file("missing.csv", header + "\n");
    const Result<Dataset> read = read_export_csv(path);
    ASSERT_FALSE(read.ok());
    EXPECT_NE(read.error().message.find(path.string() + ":1:"), std::string::npos)
        << read.error().message;
    EXPECT_NE(read.error().message.find("'mono_plane'"), std::string::npos);
}

TEST(ReadExportCsv, ABadNumberNamesFileLineAndColumn) {
    const std::filesystem::path path = write_file(
        "bad_number.csv",
        kHeader + "\n" +
            "A,1,0,0,beams,3,stereo,1,stereo,true,1,1,1,2,false,true,hybrid,0,p,h,,none,vive,"
            "completed\n"
            "A,1,1,0,beams,far,stereo,1,stereo,true,1,1,1,2,false,true,hybrid,0,p,h,,none,vive,"
            "completed\n");
    const Result<Dataset> read = read_export_csv(path);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().message,
              path.string() + ":3: column 'mono_plane' (column 6): 'far' is not a number");
}

TEST(ReadExportCsv, ADecidedTrialNeedsItsOutcome) {
    const std::filesystem::path path = write_file(
        "no_outcome.csv",
        kHeader + "\n" +
            "A,1,0,0,beams,3,stereo,,,,,,,,false,true,hybrid,0,p,h,,none,vive,completed\n");
    const Result<Dataset> read = read_export_csv(path);
    ASSERT_FALSE(read.ok());
    EXPECT_EQ(read.error().message,
              path.string() +
                  ":2: column 'chosen_mode' (column 9): an empty field where a value is needed");
}

TEST(ReadExportCsv, OtherErrorsSayWhere) {
    const std::string row =
        "A,1,0,0,beams,3,stereo,1,stereo,true,1,1,1,2,false,true,hybrid,0,p,h,,none,vive,"
        "completed\n";
    {
        const auto path = write_file("short_row.csv", kHeader + "\n" + row + "A,1,1\n");
        const Result<Dataset> read = read_export_csv(path);
        ASSERT_FALSE(read.ok());
        EXPECT_EQ(read.error().message, path.string() + ":3: 3 fields, but the header has 24");
    }
    {
        const auto path = write_file("bad_bool.csv", kHeader + "\n" +
                                                         "A,1,0,0,beams,3,stereo,1,stereo,yes,1,1,"
                                                         "1,2,false,true,hybrid,0,p,h,,none,vive,"
                                                         "completed\n");
        const Result<Dataset> read = read_export_csv(path);
        ASSERT_FALSE(read.ok());
        EXPECT_EQ(read.error().message, path.string() +
                                            ":2: column 'valid' (column 10): 'yes' is not true "
                                            "or false");
    }
    {
        const auto path = write_file("open_quote.csv", kHeader + "\n" + row + "\"A,1\n");
        const Result<Dataset> read = read_export_csv(path);
        ASSERT_FALSE(read.ok());
        EXPECT_NE(read.error().message.find(path.string() + ":3: a quoted field is never closed"),
                  std::string::npos)
            << read.error().message;
    }
    {
        const auto path = write_file("empty.csv", "");
        const Result<Dataset> read = read_export_csv(path);
        ASSERT_FALSE(read.ok());
        EXPECT_NE(read.error().message.find(path.string() + ":1: the file is empty"),
                  std::string::npos);
    }
    {
        const auto path = std::filesystem::path(testing::TempDir()) / "does_not_exist.csv";
        const Result<Dataset> read = read_export_csv(path);
        ASSERT_FALSE(read.ok());
        EXPECT_NE(read.error().message.find(path.string() + ": cannot open"), std::string::npos);
    }
}

TEST(Csv, QuotedFieldsSpanSeparatorsQuotesAndLines) {
    const Result<std::vector<CsvRecord>> records =
        parse_csv("a,\"b,\"\"c\"\"\nd\",\n\"\",x\n", "mem.csv");
    ASSERT_TRUE(records.ok()) << records.error().message;
    ASSERT_EQ(records->size(), 2u);
    EXPECT_EQ((*records)[0].line, 1);
    ASSERT_EQ((*records)[0].fields.size(), 3u);
    EXPECT_EQ((*records)[0].fields[1], "b,\"c\"\nd");
    EXPECT_EQ((*records)[0].fields[2], "");
    EXPECT_EQ((*records)[1].line, 3);  // the quoted line break moved it
    EXPECT_EQ((*records)[1].fields, (std::vector<std::string>{"", "x"}));

    const Result<std::vector<CsvRecord>> bad = parse_csv("a,\"b\"c\n", "mem.csv");
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message, "mem.csv:1: text after the closing quote of a quoted field");
}

TrialRow row(std::string source, std::int64_t session, std::string label1, std::string label2,
             int block, std::string scene, std::string chosen) {
    TrialRow t;
    t.source = std::move(source);
    t.session_id = session;
    t.label1_mode = std::move(label1);
    t.label2_mode = std::move(label2);
    t.block = block;
    t.scene = std::move(scene);
    t.decided = !chosen.empty();
    t.valid = t.decided;
    t.chosen_mode = std::move(chosen);
    return t;
}

TEST(DeriveSessionFields, ReferenceIsStereoElseAlphabeticallyFirstElseWhatTheReaderSet) {
    std::vector<TrialRow> trials = {
        row("a.db", 1, "hybrid", "stereo", 1, "beams", "hybrid"),
        row("a.db", 1, "stereo", "hybrid", 0, "spheres", "stereo"),
        // Same session id, other source: another session.
        row("b.db", 1, "hybrid-farfield", "hybrid", 0, "landscape", "hybrid-farfield"),
        row("b.db", 2, "stereo-multiview", "hybrid", 0, "beams", "hybrid"),
    };
    trials[3].reference_mode = "stereo-multiview";  // the protocol's first alternative
    derive_session_fields(trials);
    EXPECT_EQ(trials[0].reference_mode, "stereo");
    EXPECT_EQ(trials[0].test_mode, "hybrid");
    EXPECT_TRUE(trials[0].chose_test);
    EXPECT_FALSE(trials[1].chose_test);
    EXPECT_EQ(trials[0].first_scene, "spheres");
    EXPECT_EQ(trials[1].first_scene, "spheres");
    EXPECT_EQ(trials[2].reference_mode, "hybrid");
    EXPECT_EQ(trials[2].test_mode, "hybrid-farfield");
    EXPECT_TRUE(trials[2].chose_test);
    EXPECT_EQ(trials[2].first_scene, "landscape");
    EXPECT_EQ(trials[3].reference_mode, "stereo-multiview");
    EXPECT_EQ(trials[3].test_mode, "hybrid");
    EXPECT_TRUE(trials[3].chose_test);
}

TEST(Merge, AppendsTrialsAnswersAndSources) {
    Dataset a;
    a.trials = {row("a.db", 1, "stereo", "hybrid", 0, "beams", "hybrid")};
    a.sources = {"a.db"};
    Dataset b;
    b.trials = {row("b.db", 1, "stereo", "hybrid", 0, "spheres", "stereo")};
    b.answers = {AnswerRow{"b.db", 1, "P1", 0, "I noticed differences", 5, 7}};
    b.sources = {"b.db"};
    merge(a, std::move(b));
    ASSERT_EQ(a.trials.size(), 2u);
    ASSERT_EQ(a.answers.size(), 1u);
    EXPECT_EQ(a.sources, (std::vector<std::string>{"a.db", "b.db"}));
    derive_session_fields(a.trials);
    EXPECT_EQ(a.trials[0].first_scene, "beams");    // (a.db, 1)
    EXPECT_EQ(a.trials[1].first_scene, "spheres");  // (b.db, 1): kept apart
}

}  // namespace
}  // namespace monoplane::analysis
