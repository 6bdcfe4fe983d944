// The export (docs/data.md): one row per trial, identity columns first,
// RFC 4180 CSV with '.' decimals whatever the locale, TRUE/FALSE for booleans and NA for missing
// values (what R's read.csv and pandas.read_csv take without options), and JSON with the same
// keys, numbers as numbers, true/false and null for NA. Exact text for known records.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <locale>
#include <sstream>
#include <string>

#include "study/export.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

const std::string kHeader =
    "participant,session,trial_index,block,scene,mono_plane,label1_mode,choice,chosen_mode,valid,"
    "switches,time_label1_s,time_label2_s,decision_time_s,practice,decided,label2_mode,"
    "participant_index,protocol,protocol_hash,observer,runtime,hmd,session_status,"
    "anti_aliasing,ssao,detail,procedure,staircase_threshold_m,staircase_lower_m,staircase_upper_"
    "m\n";
const std::string kPracticeRow =
    "P01,1,0,NA,landscape,5,stereo,NA,NA,NA,NA,NA,NA,NA,TRUE,FALSE,hybrid,0,fink2019,"
    "fnv1a64:cbf29ce484222325,default,none,vive,running,taa,off,low,constant,NA,NA,NA\n";
const std::string kDecidedRow =
    "P01,1,2,0,spheres,1.6,stereo,1,stereo,TRUE,2,1.5,1.600000001,3.100000001,FALSE,TRUE,hybrid,0,"
    "fink2019,fnv1a64:cbf29ce484222325,default,none,vive,running,taa,off,low,constant,NA,NA,NA\n";

SessionInfo known_session() {
    SessionInfo info;
    info.id = 1;
    info.participant_code = "P01";
    info.participant_index = 0;
    info.protocol_name = "fink2019";
    info.protocol_hash = 0xcbf29ce484222325ull;
    info.protocol_text = "name = \"fink2019\"\n";
    info.seed = 42;
    info.software_version = "0.1.0";
    info.hmd = "vive";
    info.runtime = "none";
    info.device = "simulated";
    info.observer = "default";
    info.started_utc = "2024-05-01T09:30:00Z";
    info.render = {"taa", "off", "low"};
    return info;
}

// The two kinds of row: an undecided practice trial and a decided data trial.
ExportData known_data() {
    ExportData data;
    data.sessions.emplace(1, known_session());
    TrialRecord practice;
    practice.session_id = 1;
    practice.participant_code = "P01";
    practice.trial = {0, true, -1, "landscape", 5.0, 0, RenderMode::Stereo, RenderMode::Hybrid};
    TrialRecord decided;
    decided.session_id = 1;
    decided.participant_code = "P01";
    decided.trial = {2, false, 0, "spheres", 1.6, 0, RenderMode::Stereo, RenderMode::Hybrid};
    decided.decided = true;
    decided.outcome.choice = 1;
    decided.outcome.chosen_mode = RenderMode::Stereo;
    decided.outcome.valid = true;
    decided.outcome.switches = 2;
    decided.outcome.time_on_label_ns[0] = 1'500'000'000;
    decided.outcome.time_on_label_ns[1] = 1'600'000'001;
    decided.outcome.decision_time_ns = 3'100'000'001;
    data.trials = {practice, decided};
    return data;
}

// A locale as a German analyst's machine might have: ',' decimal point, '.' thousands groups.
struct GermanNumbers : std::numpunct<char> {
    char do_decimal_point() const override { return ','; }
    char do_thousands_sep() const override { return '.'; }
    std::string do_grouping() const override { return "\3"; }
};

TEST(StudyExport, CsvHasTheHeaderAndExactRows) {
    std::ostringstream out;
    write_csv(known_data(), out);
    EXPECT_EQ(out.str(), kHeader + kPracticeRow + kDecidedRow);
}

TEST(StudyExport, CsvIgnoresTheStreamsLocale) {
    std::ostringstream out;
    out.imbue(std::locale(std::locale::classic(), new GermanNumbers));
    write_csv(known_data(), out);
    EXPECT_EQ(out.str(), kHeader + kPracticeRow + kDecidedRow);
}

TEST(StudyExport, JsonHasTheSameKeysNumbersAndNulls) {
    std::ostringstream out;
    out.imbue(std::locale(std::locale::classic(), new GermanNumbers));
    write_json(known_data(), out);
    const std::string expected =
        "[\n"
        "  {\"participant\": \"P01\", \"session\": 1, \"trial_index\": 0, \"block\": null, "
        "\"scene\": \"landscape\", \"mono_plane\": 5, \"label1_mode\": \"stereo\", \"choice\": "
        "null, "
        "\"chosen_mode\": null, \"valid\": null, \"switches\": null, \"time_label1_s\": null, "
        "\"time_label2_s\": null, \"decision_time_s\": null, \"practice\": true, \"decided\": "
        "false, "
        "\"label2_mode\": \"hybrid\", \"participant_index\": 0, \"protocol\": \"fink2019\", "
        "\"protocol_hash\": \"fnv1a64:cbf29ce484222325\", \"observer\": \"default\", \"runtime\": "
        "\"none\", "
        "\"hmd\": \"vive\", \"session_status\": \"running\", \"anti_aliasing\": \"taa\", "
        "\"ssao\": \"off\", \"detail\": \"low\", \"procedure\": \"constant\", "
        "\"staircase_threshold_m\": null, \"staircase_lower_m\": null, "
        "\"staircase_upper_m\": null, \"scene_files\": [], \"session_notes\": []},\n"
        "  {\"participant\": \"P01\", \"session\": 1, \"trial_index\": 2, \"block\": 0, "
        "\"scene\": \"spheres\", \"mono_plane\": 1.6, \"label1_mode\": \"stereo\", \"choice\": 1, "
        "\"chosen_mode\": \"stereo\", \"valid\": true, \"switches\": 2, \"time_label1_s\": 1.5, "
        "\"time_label2_s\": 1.600000001, \"decision_time_s\": 3.100000001, \"practice\": false, "
        "\"decided\": true, \"label2_mode\": \"hybrid\", \"participant_index\": 0, "
        "\"protocol\": \"fink2019\", \"protocol_hash\": \"fnv1a64:cbf29ce484222325\", "
        "\"observer\": \"default\", "
        "\"runtime\": \"none\", \"hmd\": \"vive\", \"session_status\": \"running\", "
        "\"anti_aliasing\": \"taa\", \"ssao\": \"off\", \"detail\": \"low\", "
        "\"procedure\": \"constant\", \"staircase_threshold_m\": null, "
        "\"staircase_lower_m\": null, \"staircase_upper_m\": null, \"scene_files\": [], "
        "\"session_notes\": []}\n"
        "]\n";
    EXPECT_EQ(out.str(), expected);
}

// A staircase session's trial carries its scene's estimate after the trial's decision; the
// up-down rule has no interval (NA).
TEST(StudyExport, StaircaseTrialsCarryTheirStaircasesEstimate) {
    ExportData data = known_data();
    data.sessions.at(1).procedure = Procedure::Staircase;
    data.staircase_estimates[1][2] = ThresholdEstimate{6.25, 0.1, 3.0, 12.5, 7};
    std::ostringstream out;
    write_csv(data, out);
    const std::string staircase_row =
        "P01,1,2,0,spheres,1.6,stereo,1,stereo,TRUE,2,1.5,1.600000001,3.100000001,FALSE,TRUE,"
        "hybrid,0,fink2019,fnv1a64:cbf29ce484222325,default,none,vive,running,taa,off,low,"
        "staircase,6.25,3,12.5\n";
    const std::string practice_row =
        kPracticeRow.substr(0, kPracticeRow.size() - 18) + "staircase,NA,NA,NA\n";
    EXPECT_EQ(out.str(), kHeader + practice_row + staircase_row);

    data.staircase_estimates[1][2] =
        ThresholdEstimate{6.25, std::nullopt, std::nullopt, std::nullopt, 7};
    std::ostringstream up_down;
    write_csv(data, up_down);
    EXPECT_NE(up_down.str().find(",staircase,6.25,NA,NA\n"), std::string::npos);
}

// An imported scene's trial lists the files the scene was read from (only its own scene's), and
// every trial of a session its notes; the CSV keeps the scene's label and has no such columns.
TEST(StudyExport, JsonListsTheTrialsSceneFilesAndTheSessionsNotes) {
    ExportData data = known_data();
    const std::string digest = "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad";
    SessionInfo& session = data.sessions.at(1);
    session.scene_files = {{"models/room.gltf", 0, "/s/models/room.gltf", {120, digest}},
                           {"models/room.gltf", 1, "/s/models/room \"1\".bin", {36, digest}},
                           {"hall.glb", 0, "/s/hall.glb", {7, digest}}};
    session.notes = {{"2027-01-01T10:00:00Z", "study resume --accept-changed-scenes: ..."}};
    data.trials[1].trial.scene = "models/room.gltf";
    std::ostringstream json;
    write_json(data, json);
    const std::string text = json.str();
    const std::string notes =
        "\"session_notes\": [{\"noted_utc\": \"2027-01-01T10:00:00Z\", \"note\": \"study resume "
        "--accept-changed-scenes: ...\"}]}";
    EXPECT_NE(text.find("\"scene_files\": [], " + notes + ",\n"), std::string::npos) << text;
    EXPECT_NE(text.find("\"scene\": \"models/room.gltf\", "), std::string::npos) << text;
    EXPECT_NE(text.find("\"scene_files\": [{\"file_index\": 0, \"path\": \"/s/models/room.gltf\", "
                        "\"size_bytes\": 120, \"sha256\": \"" +
                        digest +
                        "\"}, {\"file_index\": 1, \"path\": \"/s/models/room \\\"1\\\".bin\", "
                        "\"size_bytes\": 36, \"sha256\": \"" +
                        digest + "\"}], " + notes + "\n]"),
              std::string::npos)
        << text;
    EXPECT_EQ(text.find("hall.glb"), std::string::npos) << "no trial shows hall.glb";
    std::ostringstream csv;
    write_csv(data, csv);
    EXPECT_NE(csv.str().find(",models/room.gltf,1.6,"), std::string::npos) << csv.str();
    EXPECT_EQ(csv.str().find("sha256"), std::string::npos);
    EXPECT_EQ(csv.str().find(digest), std::string::npos);
}

TEST(StudyExport, EmptyExportsAreStillValid) {
    std::ostringstream csv;
    std::ostringstream json;
    write_csv(ExportData{}, csv);
    write_json(ExportData{}, json);
    EXPECT_EQ(csv.str(), kHeader);
    EXPECT_EQ(json.str(), "[]\n");
}

TEST(StudyExport, AnObserverlessSessionIsNa) {
    ExportData data = known_data();
    data.sessions.at(1).observer.clear();  // a person
    std::ostringstream out;
    write_csv(data, out);
    EXPECT_NE(out.str().find(",fnv1a64:cbf29ce484222325,NA,none,"), std::string::npos) << out.str();
}

TEST(StudyExport, AnInvalidDecisionIsFalseInCsvAndJson) {
    ExportData data = known_data();
    data.trials[1].outcome.valid = false;
    std::ostringstream csv;
    write_csv(data, csv);
    EXPECT_NE(csv.str().find("\nP01,1,2,0,spheres,1.6,stereo,1,stereo,FALSE,2,"), std::string::npos)
        << csv.str();
    std::ostringstream json;
    write_json(data, json);
    EXPECT_NE(json.str().find("\"chosen_mode\": \"stereo\", \"valid\": false, "), std::string::npos)
        << json.str();
}

TEST(StudyExport, CsvFieldsFollowRfc4180) {
    EXPECT_EQ(csv_field("spheres"), "spheres");
    EXPECT_EQ(csv_field(""), "");
    EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
    EXPECT_EQ(csv_field("say \"hi\""), "\"say \"\"hi\"\"\"");
    EXPECT_EQ(csv_field("two\nlines"), "\"two\nlines\"");
    EXPECT_EQ(csv_field("cr\r"), "\"cr\r\"");
    EXPECT_EQ(csv_field("caf\xc3\xa9"), "caf\xc3\xa9");  // UTF-8 unchanged
}

TEST(StudyExport, JsonStringsAreEscaped) {
    EXPECT_EQ(json_string("plain"), "\"plain\"");
    EXPECT_EQ(json_string("a\"b\\c"), "\"a\\\"b\\\\c\"");
    EXPECT_EQ(json_string("l1\nl2\tx\r"), "\"l1\\nl2\\tx\\r\"");
    EXPECT_EQ(json_string(std::string("\x01", 1)), "\"\\u0001\"");
    EXPECT_EQ(json_string("caf\xc3\xa9"), "\"caf\xc3\xa9\"");
}

TEST(StudyExport, SecondsAreExactDecimals) {
    EXPECT_EQ(seconds_text(0), "0.0");
    EXPECT_EQ(seconds_text(1), "0.000000001");
    EXPECT_EQ(seconds_text(1'500'000'000), "1.5");
    EXPECT_EQ(seconds_text(12'000'000'000), "12.0");
    EXPECT_EQ(seconds_text(123'456'789'012), "123.456789012");
    EXPECT_EQ(seconds_text(-250'000'000), "-0.25");
    EXPECT_EQ(seconds_text(9'223'372'036'854'775'807), "9223372036.854775807");
}

TEST(StudyExport, NumbersAreShortestRoundTrips) {
    EXPECT_EQ(number_text(8.0), "8");
    EXPECT_EQ(number_text(1.6), "1.6");
    EXPECT_EQ(number_text(39.5), "39.5");
    EXPECT_EQ(number_text(0.1), "0.1");
}

TEST(StudyExport, FormatNames) {
    EXPECT_EQ(*parse_export_format("csv"), ExportFormat::Csv);
    EXPECT_EQ(*parse_export_format("json"), ExportFormat::Json);
    const Result<ExportFormat> bad = parse_export_format("xlsx");
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message.find("use csv, json or frames-csv"), std::string::npos);
    EXPECT_EQ(export_format_name(ExportFormat::Json), "json");
    EXPECT_EQ(*parse_export_format("frames-csv"), ExportFormat::FramesCsv);
    EXPECT_EQ(export_format_name(ExportFormat::FramesCsv), "frames-csv");
    EXPECT_EQ(export_columns().size(), 31u);
    EXPECT_EQ(export_columns().front(), "participant");
}

TEST(StudyExport, FramesCsvHasOneExactRowPerFrame) {
    ExportData data = known_data();
    FrameRecord neutral;
    neutral.frame = 7;
    neutral.shown = "neutral";
    neutral.display_time_ns = 1'500'000'000;
    neutral.cpu_ms = 0.25;
    FrameRecord shown;
    shown.frame = 8;
    shown.trial_index = 2;
    shown.shown = "label2";
    shown.display_time_ns = 1'511'111'111;
    shown.cpu_ms = 12.5;
    shown.gpu_ms = 10.75;
    shown.missed = true;
    shown.head = std::array<double, 7>{0.5, 1.6, -2, 1, 0, 0, 0};
    shown.mono_plane = 16.25;
    shown.pipelines_created = 0;
    shown.driver_compiles = 3;
    data.frames[1] = {neutral, shown};
    std::ostringstream out;
    out.imbue(std::locale(std::locale::classic(), new GermanNumbers));
    write_frames_csv(data, out);
    EXPECT_EQ(out.str(),
              "participant,session,frame,trial_index,shown,display_time_s,cpu_ms,gpu_ms,missed,"
              "head_x,head_y,head_z,head_qw,head_qx,head_qy,head_qz,mono_plane,pipelines_created,"
              "driver_compiles\n"
              "P01,1,7,NA,neutral,1.5,0.25,NA,FALSE,NA,NA,NA,NA,NA,NA,NA,NA,NA,NA\n"
              "P01,1,8,2,label2,1.511111111,12.5,10.75,TRUE,0.5,1.6,-2,1,0,0,0,16.25,0,3\n");
}

// Through the database: the same rows come out of a real store, and the file form is complete.
TEST(StudyExport, ExportsFromTheStoreToAFile) {
    std::string pattern = (fs::path(::testing::TempDir()) / "study_export_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    const fs::path dir = pattern;
    {
        Result<std::unique_ptr<StudyStore>> store = StudyStore::open(dir / "study.db");
        ASSERT_TRUE(store.ok()) << store.error().message;
        const ExportData known = known_data();
        Schedule schedule;
        schedule.seed = 42;
        schedule.block_order = {"spheres"};
        schedule.trials = {known.trials[0].trial,
                           {1, true, -1, "beams", 3.0, 1, RenderMode::Hybrid, RenderMode::Stereo},
                           known.trials[1].trial};
        const Result<std::int64_t> id = (*store)->begin_session(known_session(), schedule);
        ASSERT_TRUE(id.ok()) << id.error().message;
        ASSERT_TRUE((*store)->record_outcome(*id, 2, known.trials[1].outcome).ok());

        const fs::path csv = dir / "trials.csv";
        const Result<bool> written = export_trials(**store, ExportFormat::Csv, csv);
        ASSERT_TRUE(written.ok()) << written.error().message;
        std::ifstream in(csv, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        const std::string beams =
            "P01,1,1,NA,beams,3,hybrid,NA,NA,NA,NA,NA,NA,NA,TRUE,FALSE,stereo,0,fink2019,"
            "fnv1a64:cbf29ce484222325,default,none,vive,running,taa,off,low,constant,NA,NA,NA\n";
        EXPECT_EQ(text, kHeader + kPracticeRow + beams + kDecidedRow);
        EXPECT_FALSE(fs::exists(dir / "trials.csv.tmp"));

        std::ostringstream json;
        ASSERT_TRUE(export_trials(**store, ExportFormat::Json, json).ok());
        EXPECT_EQ(json.str().substr(0, 4), "[\n  ");

        const Result<bool> nowhere =
            export_trials(**store, ExportFormat::Csv, dir / "missing" / "t.csv");
        ASSERT_FALSE(nowhere.ok());
        EXPECT_NE(nowhere.error().message.find("cannot write export file"), std::string::npos)
            << nowhere.error().message;
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace monoplane::study
