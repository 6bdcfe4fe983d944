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

// The known session's id (a store makes one when a session begins; the export copies it).
const std::string kUuid = "0b6e2c4a-5d1f-4e2a-9c3b-7a8d9e0f1a2b";
const std::string kHeader =
    "participant,session,trial_index,block,scene,mono_plane,label1_mode,choice,chosen_mode,valid,"
    "switches,time_label1_s,time_label2_s,decision_time_s,practice,decided,label2_mode,"
    "participant_index,protocol,protocol_hash,observer,runtime,hmd,session_status,"
    "anti_aliasing,ssao,detail,procedure,staircase_threshold_m,staircase_lower_m,staircase_upper_"
    "m,session_id,repetition,participant_number,runs,session_uuid,software_version,gaze_samples,"
    "gaze_share_beyond_m,gaze_error_mean_arcmin_1,gaze_error_mean_arcmin_2,"
    "gaze_error_max_arcmin_1,gaze_error_max_arcmin_2,gaze_fixations\n";
// The gaze columns of a session that recorded no gaze.
const std::string kNoGaze = ",NA,NA,NA,NA,NA,NA,NA";
const std::string kNoGazeJson =
    "\"gaze_samples\": null, \"gaze_share_beyond_m\": null, \"gaze_error_mean_arcmin_1\": null, "
    "\"gaze_error_mean_arcmin_2\": null, \"gaze_error_max_arcmin_1\": null, "
    "\"gaze_error_max_arcmin_2\": null, \"gaze_fixations\": null, ";
const std::string kPracticeRow =
    "P01,1,0,NA,landscape,5,stereo,NA,NA,NA,NA,NA,NA,NA,TRUE,FALSE,hybrid,0,fink2019,"
    "fnv1a64:cbf29ce484222325,default,none,vive,running,taa,off,low,constant,NA,NA,NA,1,1,1,NA," +
    kUuid + ",0.1.0" + kNoGaze + "\n";
const std::string kDecidedRow =
    "P01,1,2,0,spheres,1.6,stereo,1,stereo,TRUE,2,1.5,1.600000001,3.100000001,FALSE,TRUE,hybrid,0,"
    "fink2019,fnv1a64:cbf29ce484222325,default,none,vive,running,taa,off,low,constant,NA,NA,NA,1,"
    "1,1,2," +
    kUuid + ",0.1.0" + kNoGaze + "\n";

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
    info.session_uuid = kUuid;
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
    decided.outcome.runs = 2;  // interrupted once while shown
    data.trials = {practice, decided};
    return data;
}

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
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

// A session whose database records no build (made by hand, or by a tool that left it empty)
// exports "unknown", never an empty cell a reader would take for NA.
TEST(StudyExport, ASessionWithoutARecordedBuildSaysUnknown) {
    ExportData data = known_data();
    data.sessions.at(1).software_version.clear();
    std::ostringstream out;
    write_csv(data, out);
    const std::string text = out.str();
    EXPECT_EQ(text.find(",0.1.0,"), std::string::npos) << text;
    std::size_t rows = 0;
    for (std::size_t at = text.find(",unknown" + kNoGaze + "\n"); at != std::string::npos;
         at = text.find(",unknown" + kNoGaze + "\n", at + 1)) {
        ++rows;
    }
    EXPECT_EQ(rows, 2u) << text;
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
        "\"staircase_upper_m\": null, \"session_id\": 1, \"repetition\": 1, "
        "\"participant_number\": 1, \"runs\": null, \"session_uuid\": \"" +
        kUuid + "\", \"software_version\": \"0.1.0\", " + kNoGazeJson +
        "\"scene_files\": [], \"session_notes\": []},\n"
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
        "\"staircase_lower_m\": null, \"staircase_upper_m\": null, \"session_id\": 1, "
        "\"repetition\": 1, \"participant_number\": 1, \"runs\": 2, \"session_uuid\": \"" +
        kUuid + "\", \"software_version\": \"0.1.0\", " + kNoGazeJson +
        "\"scene_files\": [], \"session_notes\": []}\n"
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
        "staircase,6.25,3,12.5,1,1,1,2," +
        kUuid + ",0.1.0" + kNoGaze + "\n";
    const std::string practice_row = kPracticeRow.substr(0, kPracticeRow.find("constant,")) +
                                     "staircase,NA,NA,NA,1,1,1,NA," + kUuid + ",0.1.0" + kNoGaze +
                                     "\n";
    EXPECT_EQ(out.str(), kHeader + practice_row + staircase_row);

    data.staircase_estimates[1][2] =
        ThresholdEstimate{6.25, std::nullopt, std::nullopt, std::nullopt, 7};
    std::ostringstream up_down;
    write_csv(data, up_down);
    EXPECT_NE(up_down.str().find(",staircase,6.25,NA,NA,1,1,1,2," + kUuid + ",0.1.0,"),
              std::string::npos);
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
    session.notes = {{"2027-01-01T10:00:00Z", "study resume --accept-changed-scenes: ...",
                      NoteSource::Software, std::nullopt, std::nullopt}};
    data.trials[1].trial.scene = "models/room.gltf";
    std::ostringstream json;
    write_json(data, json);
    const std::string text = json.str();
    const std::string notes =
        "\"session_notes\": [{\"noted_utc\": \"2027-01-01T10:00:00Z\", \"note\": \"study resume "
        "--accept-changed-scenes: ...\", \"source\": \"software\", \"runtime_time_ns\": null, "
        "\"trial\": null}]}";
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

// Text is escaped by the project's JSON writer (common/json_writer.h): quotes, backslashes and
// control characters escaped, UTF-8 as typed.
TEST(StudyExport, JsonStringsAreEscaped) {
    ExportData data = known_data();
    data.trials.resize(1);
    data.trials[0].participant_code = "caf\xc3\xa9";
    data.sessions.at(1).notes = {
        {"2027-01-01T10:00:00Z", "say \"hi\" \\ l1\nl2\tx\r\x01", NoteSource::Window, 12, 0}};
    std::ostringstream json;
    write_json(data, json);
    EXPECT_NE(json.str().find("[\n  {\"participant\": \"caf\xc3\xa9\", \"session\": 1, "),
              std::string::npos)
        << json.str();
    EXPECT_NE(
        json.str().find("\"session_notes\": [{\"noted_utc\": \"2027-01-01T10:00:00Z\", "
                        "\"note\": \"say \\\"hi\\\" \\\\ l1\\nl2\\tx\\r\\u0001\", "
                        "\"source\": \"window\", \"runtime_time_ns\": 12, \"trial\": 0}]}\n]\n"),
        std::string::npos)
        << json.str();
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
    EXPECT_NE(bad.error().message.find("use csv, json, frames-csv"), std::string::npos);
    EXPECT_NE(bad.error().message.find("notes-csv"), std::string::npos);
    EXPECT_NE(bad.error().message.find("gaze-csv"), std::string::npos);
    EXPECT_EQ(export_format_name(ExportFormat::Json), "json");
    EXPECT_EQ(*parse_export_format("frames-csv"), ExportFormat::FramesCsv);
    EXPECT_EQ(export_format_name(ExportFormat::FramesCsv), "frames-csv");
    EXPECT_EQ(*parse_export_format("notes-csv"), ExportFormat::NotesCsv);
    EXPECT_EQ(export_format_name(ExportFormat::NotesCsv), "notes-csv");
    EXPECT_EQ(*parse_export_format("gaze-csv"), ExportFormat::GazeCsv);
    EXPECT_EQ(export_format_name(ExportFormat::GazeCsv), "gaze-csv");
    // The gaze columns came after software_version: every earlier column keeps its place.
    EXPECT_EQ(export_columns().size(), 44u);
    EXPECT_EQ(export_columns()[36], "software_version");
    EXPECT_EQ(export_columns().back(), "gaze_fixations");
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
              "driver_compiles,session_id\n"
              "P01,1,7,NA,neutral,1.5,0.25,NA,FALSE,NA,NA,NA,NA,NA,NA,NA,NA,NA,NA,1\n"
              "P01,1,8,2,label2,1.511111111,12.5,10.75,TRUE,0.5,1.6,-2,1,0,0,0,16.25,0,3,1\n");
}

// `session` is the participant's session number; the database's session id, the repetition
// and the 1-based participant number (--participant-number) come after the older columns.
TEST(StudyExport, SessionIsTheParticipantsNumberAndTheIdFollows) {
    ExportData data = known_data();
    SessionInfo second = known_session();
    second.id = 7;
    second.session_number = 2;
    second.participant_number = 4;
    data.sessions.emplace(7, second);
    data.trials[1].session_id = 7;
    data.trials[1].session_number = 2;
    data.trials[1].trial.repetition = 3;
    std::ostringstream csv;
    write_csv(data, csv);
    EXPECT_NE(csv.str().find("\nP01,2,2,0,spheres,1.6,"), std::string::npos) << csv.str();
    EXPECT_NE(csv.str().find(",constant,NA,NA,NA,7,3,5,2," + kUuid + ",0.1.0,"), std::string::npos)
        << csv.str();
    EXPECT_NE(csv.str().find(",constant,NA,NA,NA,1,1,1,NA," + kUuid + ",0.1.0,"), std::string::npos)
        << csv.str();
    std::ostringstream json;
    write_json(data, json);
    EXPECT_NE(json.str().find("{\"participant\": \"P01\", \"session\": 2, \"trial_index\": 2, "),
              std::string::npos)
        << json.str();
    EXPECT_NE(json.str().find("\"session_id\": 7, \"repetition\": 3, \"participant_number\": 5, "),
              std::string::npos)
        << json.str();
}

// Two participants of two protocol versions: one var_ column per variable any of them
// declares, in first-seen declaration order, NA where a participant has none; numbers stay
// numbers (also negative ones), choices and text are text, in JSON too.
ExportData data_with_variables() {
    ExportData data = known_data();
    data.variable_names = {"age", "vision", "remark"};
    data.sessions.at(1).variables = {{"age", VariableType::Integer, "34"},
                                     {"vision", VariableType::Choice, "corrected"},
                                     {"remark", VariableType::Text, "=1+1"}};
    SessionInfo other = known_session();
    other.id = 2;
    other.participant_code = "P02";
    other.participant_index = 1;
    other.participant_number = 1;
    other.session_uuid.clear();  // a session made by hand: NA
    other.variables = {{"vision", VariableType::Choice, "-"},
                       {"offset_db", VariableType::Number, "-5.5"}};
    data.sessions.emplace(2, other);
    TrialRecord trial = data.trials[0];
    trial.session_id = 2;
    trial.participant_code = "P02";
    data.trials.push_back(trial);
    return data;
}

TEST(StudyExport, EveryParticipantVariableIsAColumn) {
    const ExportData data = data_with_variables();
    EXPECT_EQ(variable_columns(data),
              (std::vector<std::string>{"var_age", "var_vision", "var_remark", "var_offset_db"}));
    std::ostringstream csv;
    write_csv(data, csv);
    const std::string text = csv.str();
    EXPECT_EQ(
        text.substr(0, text.find('\n') + 1),
        kHeader.substr(0, kHeader.size() - 1) + ",var_age,var_vision,var_remark,var_offset_db\n");
    EXPECT_NE(text.find("\nP01,1,0,NA,landscape,5,"), std::string::npos);
    EXPECT_NE(text.find(",1,1,1,NA," + kUuid + ",0.1.0" + kNoGaze +
                        ",34,corrected,\"'=1+1\",NA\nP01,1,2,"),
              std::string::npos)
        << text;
    EXPECT_NE(text.find(",2,1,2,NA,NA,0.1.0" + kNoGaze + ",NA,\"'-\",NA,-5.5\n"), std::string::npos)
        << text;

    std::ostringstream json;
    write_json(data, json);
    EXPECT_NE(json.str().find("\"participant_number\": 1, \"runs\": null, \"session_uuid\": \"" +
                              kUuid + "\", \"software_version\": \"0.1.0\", " + kNoGazeJson +
                              "\"var_age\": 34, "
                              "\"var_vision\": "
                              "\"corrected\", \"var_remark\": \"=1+1\", \"var_offset_db\": null, "
                              "\"scene_files\""),
              std::string::npos)
        << json.str();
    EXPECT_NE(json.str().find("\"participant_number\": 2, \"runs\": null, \"session_uuid\": null, "
                              "\"software_version\": \"0.1.0\", " +
                              kNoGazeJson +
                              "\"var_age\": null, "
                              "\"var_vision\": "
                              "\"-\", \"var_remark\": null, \"var_offset_db\": -5.5, "),
              std::string::npos)
        << json.str();
}

// Without declarations (hand-built data), the sessions' values make the columns, sessions in id
// order; a stored number that does not read as one stays text rather than break the JSON.
TEST(StudyExport, StoredValuesMakeColumnsInFirstSeenOrder) {
    ExportData data = data_with_variables();
    data.variable_names.clear();
    data.sessions.at(1).variables = {{"age", VariableType::Integer, "thirty"}};
    EXPECT_EQ(variable_columns(data),
              (std::vector<std::string>{"var_age", "var_vision", "var_offset_db"}));
    std::ostringstream json;
    write_json(data, json);
    EXPECT_NE(json.str().find("\"var_age\": \"thirty\", \"var_vision\": null, "), std::string::npos)
        << json.str();
}

// Only a number as JSON writes one is written as a number; anything else stays text.
TEST(StudyExport, NumericVariablesAreNumbersOnlyWhenTheyReadAsOne) {
    ExportData data = known_data();
    data.trials.resize(1);
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"0", "0"},       {"-0.5", "-0.5"},   {"1e+20", "1e+20"}, {"34", "34"},
        {"5.", "\"5.\""}, {".5", "\".5\""},   {"007", "\"007\""}, {"+1", "\"+1\""},
        {"1e", "\"1e\""}, {"inf", "\"inf\""}, {"", "\"\""}};
    for (const auto& [stored, json_value] : cases) {
        data.sessions.at(1).variables = {{"x", VariableType::Number, stored}};
        std::ostringstream json;
        write_json(data, json);
        EXPECT_NE(json.str().find("\"var_x\": " + json_value + ", "), std::string::npos)
            << stored << ": " << json.str();
    }
}

// OWASP's advice on CSV injection: a text cell that a spreadsheet would evaluate gets a leading
// apostrophe inside quotes; everything else is written as RFC 4180 says, and the original comes
// back exactly, also for text that itself begins with apostrophes.
TEST(StudyExport, FormulaLikeTextIsGuardedAndReversible) {
    EXPECT_EQ(csv_text("=1+1"), "\"'=1+1\"");
    EXPECT_EQ(csv_text("-5 dB"), "\"'-5 dB\"");
    EXPECT_EQ(csv_text("+49 30"), "\"'+49 30\"");
    EXPECT_EQ(csv_text("@home"), "\"'@home\"");
    EXPECT_EQ(csv_text("\ttab"), "\"'\ttab\"");
    EXPECT_EQ(csv_text("\rcr"), "\"'\rcr\"");
    EXPECT_EQ(csv_text("=HYPERLINK(\"x\")"), "\"'=HYPERLINK(\"\"x\"\")\"");
    EXPECT_EQ(csv_text("'=x"), "\"''=x\"");
    EXPECT_EQ(csv_text("a,\"b\"\nc"), "\"a,\"\"b\"\"\nc\"");
    EXPECT_EQ(csv_text("'quoted'"), "'quoted'");
    EXPECT_EQ(csv_text("1+1="), "1+1=");
    EXPECT_EQ(csv_text(""), "");
    EXPECT_EQ(csv_text("P-01"), "P-01");
    for (const std::string original : {"=1+1", "-5 dB", "@home", "+", "-", "\tx", "\rx", "'=x",
                                       "''-x", "'", "'plain", "plain", "a,\"b\"\nc", ""}) {
        std::string cell = csv_text(original);
        if (cell.size() >= 2 && cell.front() == '"') {  // the cell's value: quotes removed
            std::string value;
            for (std::size_t i = 1; i + 1 < cell.size(); ++i) {
                value += cell[i];
                if (cell[i] == '"') ++i;
            }
            cell = value;
        }
        EXPECT_EQ(csv_text_original(cell), original) << cell;
    }
}

// Every text cell is guarded (a code or scene may begin with '-'); numbers never are.
TEST(StudyExport, CsvGuardsTextCellsButNotNumbers) {
    ExportData data = known_data();
    data.sessions.at(1).participant_code = "-P1";
    data.trials[1].participant_code = "-P1";
    data.trials[1].trial.scene = "@scene.glb";
    data.trials[1].trial.mono_plane = -1.5;  // impossible, but a number: never altered
    std::ostringstream csv;
    write_csv(data, csv);
    EXPECT_NE(csv.str().find("\n\"'-P1\",1,2,0,\"'@scene.glb\",-1.5,stereo,"), std::string::npos)
        << csv.str();
    data.frames[1] = {FrameRecord{}};
    std::ostringstream frames;
    write_frames_csv(data, frames);
    EXPECT_NE(frames.str().find("\n\"'-P1\",1,0,NA,"), std::string::npos) << frames.str();
}

// The notes of every session in id order, each with its session number, the trial it was
// written in, its clock time and source; NA where none. Text is guarded as in the trials CSV.
ExportData data_with_notes() {
    ExportData data;
    SessionInfo first = known_session();
    first.notes = {{"2027-01-01T10:00:00Z", "resumed with changed scenes", NoteSource::Software,
                    std::nullopt, std::nullopt},
                   {"2027-01-01T10:05:00Z", "=1+1", NoteSource::Window, 12'345'678'901, 3}};
    SessionInfo second = known_session();
    second.id = 4;
    second.participant_code = "P02";
    second.session_number = 2;
    second.notes = {
        {"2027-01-02T09:00:00Z", "a,\"b\"\nc", NoteSource::Command, std::nullopt, std::nullopt},
        {"2027-01-02T09:01:00Z", "-5 dB", NoteSource::Window, 0, 0}};
    SessionInfo silent = known_session();
    silent.id = 3;
    silent.participant_code = "P03";
    data.sessions = {{4, second}, {1, first}, {3, silent}};
    return data;
}

TEST(StudyExport, NotesCsvHasOneExactRowPerNote) {
    std::ostringstream out;
    out.imbue(std::locale(std::locale::classic(), new GermanNumbers));
    write_notes_csv(data_with_notes(), out);
    EXPECT_EQ(out.str(),
              "participant,session,trial,noted_utc,runtime_time_ns,source,note\n"
              "P01,1,NA,2027-01-01T10:00:00Z,NA,software,resumed with changed scenes\n"
              "P01,1,3,2027-01-01T10:05:00Z,12345678901,window,\"'=1+1\"\n"
              "P02,2,NA,2027-01-02T09:00:00Z,NA,command,\"a,\"\"b\"\"\nc\"\n"
              "P02,2,0,2027-01-02T09:01:00Z,0,window,\"'-5 dB\"\n");
    std::ostringstream empty;
    write_notes_csv(ExportData{}, empty);
    EXPECT_EQ(empty.str(), "participant,session,trial,noted_utc,runtime_time_ns,source,note\n");
}

// JSON keeps every note's fields and its text exactly as typed.
TEST(StudyExport, JsonNotesHaveEveryFieldAndTheTextAsTyped) {
    ExportData data = known_data();
    data.sessions.at(1).notes = data_with_notes().sessions.at(1).notes;
    std::ostringstream json;
    write_json(data, json);
    EXPECT_NE(
        json.str().find("\"session_notes\": [{\"noted_utc\": \"2027-01-01T10:00:00Z\", \"note\": "
                        "\"resumed with changed scenes\", \"source\": \"software\", "
                        "\"runtime_time_ns\": null, \"trial\": null}, {\"noted_utc\": "
                        "\"2027-01-01T10:05:00Z\", \"note\": \"=1+1\", \"source\": \"window\", "
                        "\"runtime_time_ns\": 12345678901, \"trial\": 3}]}"),
        std::string::npos)
        << json.str();
}

// An earlier export is told by its first bytes: each format knows its own and no other's.
TEST(StudyExport, EachFormatRecognisesItsOwnEarlierExports) {
    const ExportData data = data_with_variables();
    ExportData with_frames = data;
    with_frames.frames[1] = {FrameRecord{}};
    const std::vector<std::pair<ExportFormat, std::string>> outputs = [&] {
        std::vector<std::pair<ExportFormat, std::string>> all;
        std::ostringstream csv, json, frames, notes, gaze, empty_json;
        write_csv(data, csv);
        write_json(data, json);
        write_frames_csv(with_frames, frames);
        write_notes_csv(data_with_notes(), notes);
        write_gaze_csv(with_frames, gaze);
        write_json(ExportData{}, empty_json);
        return std::vector<std::pair<ExportFormat, std::string>>{
            {ExportFormat::Csv, csv.str()},          {ExportFormat::Json, json.str()},
            {ExportFormat::FramesCsv, frames.str()}, {ExportFormat::NotesCsv, notes.str()},
            {ExportFormat::GazeCsv, gaze.str()},     {ExportFormat::Json, empty_json.str()}};
    }();
    // gaze-csv's first columns are frames-csv's: each still tells the other's exports apart.
    for (ExportFormat format : {ExportFormat::Csv, ExportFormat::Json, ExportFormat::FramesCsv,
                                ExportFormat::NotesCsv, ExportFormat::GazeCsv}) {
        const OutputKind kind = export_output_kind(format);
        for (const auto& [written_as, text] : outputs) {
            const std::string head = text.substr(0, kOutputHeadBytes);
            EXPECT_EQ(kind.is_earlier_output(head), written_as == format)
                << kind.name << " on " << export_format_name(written_as);
        }
        for (const std::string other :
             {"", "name = \"fink2019\"\n", "participant,session\n", "[1, 2]\n",
              "{\"participant\": 1}\n", "participant;session;trial_index\n"}) {
            EXPECT_FALSE(kind.is_earlier_output(other)) << kind.name << " on " << other;
        }
    }
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
        const Result<void> written = export_trials(**store, ExportFormat::Csv, csv);
        ASSERT_TRUE(written.ok()) << written.error().message;
        std::ifstream in(csv, std::ios::binary);
        const std::string text((std::istreambuf_iterator<char>(in)),
                               std::istreambuf_iterator<char>());
        const std::string beams =
            "P01,1,1,NA,beams,3,hybrid,NA,NA,NA,NA,NA,NA,NA,TRUE,FALSE,stereo,0,fink2019,"
            "fnv1a64:cbf29ce484222325,default,none,vive,running,taa,off,low,constant,NA,NA,NA,1,"
            "1,1,NA," +
            kUuid + ",0.1.0" + kNoGaze + "\n";
        EXPECT_EQ(text, kHeader + kPracticeRow + beams + kDecidedRow);
        for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
            EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos)
                << "a temporary file is left beside the export: " << entry.path();
        }

        std::ostringstream json;
        ASSERT_TRUE(export_trials(**store, ExportFormat::Json, json).ok());
        EXPECT_EQ(json.str().substr(0, 4), "[\n  ");

        const Result<void> nowhere =
            export_trials(**store, ExportFormat::Csv, dir / "missing" / "t.csv");
        ASSERT_FALSE(nowhere.ok());
        EXPECT_NE(
            nowhere.error().message.find("'" + (dir / "missing").string() + "' for the output"),
            std::string::npos)
            << nowhere.error().message;
    }
    fs::remove_all(dir);
}

// Through the database, a study day: a participant's second session, their variables (one the
// protocol declares but nobody was given: NA), repetitions and the notes of both sessions.
TEST(StudyExport, ExportsSessionsVariablesAndNotesFromTheStore) {
    std::string pattern = (fs::path(::testing::TempDir()) / "study_export_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    const fs::path dir = pattern;
    {
        Result<std::unique_ptr<StudyStore>> opened = StudyStore::open(dir / "study.db");
        ASSERT_TRUE(opened.ok()) << opened.error().message;
        StudyStore& store = **opened;
        SessionInfo info = known_session();
        info.session_uuid.clear();  // begin_session makes each session its own
        info.protocol_text =
            "name = \"fink2019\"\nscenes = [\"spheres\"]\nmono_planes = [1.6, 5]\n"
            "alternatives = [\"stereo\", \"hybrid\"]\n"
            "[[variables]]\nname = \"age\"\ntype = \"integer\"\n"
            "[[variables]]\nname = \"handedness\"\ntype = \"choice\"\n"
            "choices = [\"left\", \"right\"]\n";
        ASSERT_TRUE(parse_protocol(info.protocol_text, "test").ok());
        info.variables = {{"age", VariableType::Integer, "34"}};
        Schedule schedule;
        schedule.seed = 42;
        schedule.block_order = {"spheres"};
        schedule.trials = {
            {0, false, 0, "spheres", 1.6, 0, RenderMode::Stereo, RenderMode::Hybrid},
            {1, false, 0, "spheres", 1.6, 1, RenderMode::Hybrid, RenderMode::Stereo}};
        schedule.trials[1].repetition = 2;
        const Result<std::int64_t> first = store.begin_session(info, schedule);
        ASSERT_TRUE(first.ok()) << first.error().message;
        // A participant's next session begins once the earlier one has ended.
        ASSERT_TRUE(store.set_status(*first, SessionStatus::Completed).ok());
        info.session_number = schedule.session_number = 2;
        const Result<std::int64_t> second = store.begin_session(info, schedule);
        ASSERT_TRUE(second.ok()) << second.error().message;
        ASSERT_TRUE(store
                        .add_note(*first, {"2027-01-01T10:00:00Z", "=1+1", NoteSource::Window,
                                           5'000'000'000, 1})
                        .ok());
        ASSERT_TRUE(store
                        .add_note(*second, {"2027-01-02T10:00:00Z", "-5 dB", NoteSource::Command,
                                            std::nullopt, std::nullopt})
                        .ok());

        ASSERT_TRUE(export_trials(store, ExportFormat::Csv, dir / "trials.csv").ok());
        const std::string csv = read_file(dir / "trials.csv");
        EXPECT_NE(csv.find(",gaze_error_max_arcmin_2,gaze_fixations,var_age,var_handedness\n"),
                  std::string::npos)
            << csv;
        const auto uuid = [&](std::int64_t id) { return store.session(id).value().session_uuid; };
        EXPECT_NE(uuid(*first), uuid(*second));
        EXPECT_NE(csv.find("\nP01,1,1,0,spheres,1.6,hybrid,"), std::string::npos) << csv;
        EXPECT_NE(csv.find(",NA,NA,NA," + std::to_string(*first) + ",2,1,NA," + uuid(*first) +
                           ",0.1.0" + kNoGaze + ",34,NA\n"),
                  std::string::npos)
            << csv;
        EXPECT_NE(csv.find("\nP01,2,1,0,spheres,1.6,hybrid,"), std::string::npos) << csv;
        EXPECT_NE(csv.find(",NA,NA,NA," + std::to_string(*second) + ",2,1,NA," + uuid(*second) +
                           ",0.1.0" + kNoGaze + ",34,NA\n"),
                  std::string::npos)
            << csv;

        ASSERT_TRUE(export_trials(store, ExportFormat::NotesCsv, dir / "notes.csv").ok());
        EXPECT_EQ(read_file(dir / "notes.csv"),
                  "participant,session,trial,noted_utc,runtime_time_ns,source,note\n"
                  "P01,1,1,2027-01-01T10:00:00Z,5000000000,window,\"'=1+1\"\n"
                  "P01,2,NA,2027-01-02T10:00:00Z,NA,command,\"'-5 dB\"\n");

        std::ostringstream json;
        ASSERT_TRUE(export_trials(store, ExportFormat::Json, json).ok());
        EXPECT_NE(json.str().find("\"var_age\": 34, \"var_handedness\": null, "), std::string::npos)
            << json.str();
        EXPECT_NE(json.str().find("\"note\": \"=1+1\", \"source\": \"window\", "
                                  "\"runtime_time_ns\": 5000000000, \"trial\": 1}"),
                  std::string::npos)
            << json.str();
    }
    fs::remove_all(dir);
}

}  // namespace
}  // namespace monoplane::study
