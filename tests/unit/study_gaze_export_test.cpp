// Eye gaze in the exports (issue 45): `study export --format gaze-csv` (one row per frame with a
// gaze sample, with its angles and gaze point, worked out by hand: (1, 0, -1)/sqrt(2) lies 45
// degrees right of the view axis; (0, 0.6, -0.8) atan(3/4) = 36.8698976 degrees above it), the
// trial export's gaze columns, and the roster's flag of the sessions that hold gaze.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "study/export.h"
#include "study/export_source.h"

namespace monoplane::study {
namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kPeriodNs = 11'111'111;  // 90 Hz
const std::array<double, 3> kRight45{std::sqrt(0.5), 0.0, -std::sqrt(0.5)};
const std::array<double, 3> kUp{0.0, 0.6, -0.8};
const std::array<double, 3> kAhead{0.0, 0.0, -1.0};
const std::string kGazeHeader =
    "participant,session,frame,trial_index,shown,display_time_s,shown_mode,gaze_valid,gaze_dir_x,"
    "gaze_dir_y,gaze_dir_z,gaze_yaw_deg,gaze_pitch_deg,gaze_eccentricity_deg,gaze_error_arcmin,"
    "gaze_depth_m,gaze_at_sky,gaze_mono_plane_m,gaze_beyond_m,session_id";

FrameRecord frame(std::int64_t index, std::optional<int> trial, const std::string& shown) {
    FrameRecord f;
    f.frame = index;
    f.trial_index = trial;
    f.shown = shown;
    f.display_time_ns = index * kPeriodNs;
    f.cpu_ms = 2.0;
    return f;
}

FrameRecord looking(std::int64_t index, std::optional<int> trial, const std::string& shown,
                    const std::array<double, 3>& dir,
                    std::optional<GazePointRecord> point = std::nullopt) {
    FrameRecord f = frame(index, trial, shown);
    f.gaze = GazeRecord{true, dir};
    f.gaze_point = point;
    return f;
}

FrameRecord blinking(std::int64_t index, std::optional<int> trial, const std::string& shown) {
    FrameRecord f = frame(index, trial, shown);
    f.gaze = GazeRecord{false, kAhead};
    return f;
}

// Session P01's gaze: trial 0 (stereo as label 1, hybrid as label 2, m = 1.6) shows label 1
// looking 45 degrees right at a point 12 m away (2.5 arcmin), a blink, label 2 looking ahead at
// a point 1 m away (0 arcmin) and up at the sky (7.25 arcmin), then a neutral frame; a frame
// without gaze; trial 1 shows label 1 for 12 frames (0.122 s) straight ahead without gaze points:
// one fixation.
std::vector<FrameRecord> gaze_log() {
    std::vector<FrameRecord> frames = {
        looking(0, 0, "label1", kRight45, GazePointRecord{2.5, 12.0, 1.6}),
        blinking(1, 0, "label1"),
        looking(2, 0, "label2", kAhead, GazePointRecord{0.0, 1.0, 1.6}),
        looking(3, 0, "label2", kUp, GazePointRecord{7.25, std::nullopt, 1.6}),
        looking(4, 0, "neutral", kAhead),
        frame(5, std::nullopt, "neutral"),
    };
    for (int i = 10; i < 22; ++i) frames.push_back(looking(i, 1, "label1", kAhead));
    return frames;
}

Schedule two_trials(int participant = 0) {
    Schedule schedule;
    schedule.seed = 42;
    schedule.participant_index = participant;
    schedule.block_order = {"spheres"};
    schedule.trials = {{0, false, 0, "spheres", 1.6, 0, RenderMode::Stereo, RenderMode::Hybrid},
                       {1, false, 0, "spheres", 5.0, 1, RenderMode::Hybrid, RenderMode::Stereo}};
    return schedule;
}

SessionInfo session_of(const std::string& code, int index) {
    SessionInfo info;
    info.participant_code = code;
    info.participant_index = index;
    info.participant_number = index;
    info.protocol_name = "gaze";
    info.protocol_hash = 0xcbf29ce484222325ull;
    info.protocol_text = "name = \"gaze\"\n";
    info.seed = 42;
    info.software_version = "0.1.0";
    info.hmd = "vive";
    info.runtime = "simulated";
    info.device = "simulated";
    info.observer = "default";
    info.render = {"taa", "off", "low"};
    return info;
}

ExportData data_by_hand() {
    ExportData data;
    SessionInfo info = session_of("P01", 0);
    info.id = 1;
    data.sessions.emplace(1, info);
    for (const ScheduledTrial& trial : two_trials().trials) {
        TrialRecord record;
        record.session_id = 1;
        record.participant_code = "P01";
        record.trial = trial;
        data.trials.push_back(record);
    }
    data.frames[1] = gaze_log();
    return data;
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> fields;
    std::stringstream in(line);
    for (std::string field; std::getline(in, field, ',');) fields.push_back(field);
    return fields;
}

std::vector<std::string> lines_of(const std::string& text) {
    std::vector<std::string> lines;
    std::stringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

double number(const std::string& field) {
    return std::stod(field);
}

TEST(GazeExport, OneRowPerFrameWithASample) {
    std::ostringstream out;
    write_gaze_csv(data_by_hand(), out);
    const std::vector<std::string> lines = lines_of(out.str());
    ASSERT_EQ(lines.size(), 1u + 5u + 12u) << out.str();  // the frame without gaze has no row
    EXPECT_EQ(lines[0], kGazeHeader);
    EXPECT_EQ(split(lines[0]).size(), gaze_export_columns().size());
    for (const std::string& line : lines) EXPECT_EQ(split(line).size(), 20u) << line;

    const std::vector<std::string> right = split(lines[1]);
    EXPECT_EQ(lines[1].substr(0, lines[1].find(",TRUE,")), "P01,1,0,0,label1,0.0,stereo");
    EXPECT_NEAR(number(right[8]), 0.70710678118654752, 1e-15);
    EXPECT_EQ(right[9], "0");
    EXPECT_NEAR(number(right[10]), -0.70710678118654752, 1e-15);
    EXPECT_NEAR(number(right[11]), 45.0, 1e-12);  // yaw
    EXPECT_EQ(right[12], "0");                    // pitch
    EXPECT_NEAR(number(right[13]), 45.0, 1e-12);  // eccentricity
    EXPECT_EQ(lines[1].substr(lines[1].find(",2.5,")), ",2.5,12,FALSE,1.6,TRUE,1");

    EXPECT_EQ(lines[2],
              "P01,1,1,0,label1,0.011111111,stereo,FALSE,NA,NA,NA,NA,NA,NA,NA,NA,NA,NA,NA,1");
    EXPECT_EQ(lines[3],
              "P01,1,2,0,label2,0.022222222,hybrid,TRUE,0,0,-1,0,0,0,0,1,FALSE,1.6,"
              "FALSE,1");
    const std::vector<std::string> up = split(lines[4]);
    EXPECT_EQ(up[6], "hybrid");
    EXPECT_EQ(up[11], "0");
    EXPECT_NEAR(number(up[12]), 36.869897645844021, 1e-12);  // pitch: atan(3/4)
    EXPECT_NEAR(number(up[13]), 36.869897645844021, 1e-12);  // as far from the view axis
    EXPECT_EQ(lines[4].substr(lines[4].find(",7.25,")), ",7.25,NA,TRUE,1.6,TRUE,1");
    EXPECT_EQ(lines[5], "P01,1,4,0,neutral,0.044444444,NA,TRUE,0,0,-1,0,0,0,NA,NA,NA,NA,NA,1");
    EXPECT_EQ(lines[6].substr(0, 30), "P01,1,10,1,label1,0.11111111,h");
}

// Through a database: P01's session holds gaze, P02's (no eye tracker) none. The roster says
// which; gaze-csv holds P01's samples only; the trial export carries P01's gaze per trial, and
// NA for P02's.
class GazeExportStore : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string pattern = (fs::path(::testing::TempDir()) / "gaze_export_XXXXXX").string();
        ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
        dir_ = pattern;
        Result<std::unique_ptr<StudyStore>> opened = StudyStore::open(dir_ / "study.db");
        ASSERT_TRUE(opened.ok()) << opened.error().message;
        store_ = std::move(opened).value();
        const Result<std::int64_t> with = store_->begin_session(session_of("P01", 0), two_trials());
        const Result<std::int64_t> without =
            store_->begin_session(session_of("P02", 1), two_trials(1));
        ASSERT_TRUE(with.ok()) << with.error().message;
        ASSERT_TRUE(without.ok()) << without.error().message;
        with_ = *with;
        without_ = *without;
        for (const FrameRecord& f : gaze_log()) store_->queue_frame(with_, f);
        store_->queue_frame(without_, frame(0, 0, "label1"));
        ASSERT_TRUE(store_->flush_frames().ok());
    }
    void TearDown() override {
        store_.reset();
        fs::remove_all(dir_);
    }

    std::string exported(ExportFormat format) {
        std::ostringstream out;
        const Result<void> written = export_trials(*store_, format, out);
        EXPECT_TRUE(written.ok()) << written.error().message;
        return out.str();
    }

    fs::path dir_;
    std::unique_ptr<StudyStore> store_;
    std::int64_t with_ = 0;
    std::int64_t without_ = 0;
};

TEST_F(GazeExportStore, TheRosterSaysWhichSessionsHoldGaze) {
    const Result<std::vector<RosterRow>> roster = store_->roster();
    ASSERT_TRUE(roster.ok()) << roster.error().message;
    ASSERT_EQ(roster->size(), 2u);
    EXPECT_EQ((*roster)[0].participant_code, "P01");
    EXPECT_TRUE((*roster)[0].gaze);
    EXPECT_EQ((*roster)[1].participant_code, "P02");
    EXPECT_FALSE((*roster)[1].gaze);
}

TEST_F(GazeExportStore, GazeCsvHoldsTheSessionsThatRecordedGaze) {
    const std::vector<std::string> lines = lines_of(exported(ExportFormat::GazeCsv));
    ASSERT_EQ(lines.size(), 1u + 5u + 12u);
    EXPECT_EQ(lines[0], kGazeHeader);
    for (std::size_t i = 1; i < lines.size(); ++i) {
        EXPECT_TRUE(lines[i].starts_with("P01,1,")) << lines[i];
        EXPECT_TRUE(lines[i].ends_with("," + std::to_string(with_))) << lines[i];
    }
    EXPECT_EQ(lines[3],
              "P01,1,2,0,label2,0.022222222,hybrid,TRUE,0,0,-1,0,0,0,0,1,FALSE,1.6,"
              "FALSE," +
                  std::to_string(with_));

    const fs::path out = dir_ / "gaze.csv";
    ASSERT_TRUE(export_trials(*store_, ExportFormat::GazeCsv, out).ok());
    const Result<ExportSource> source = read_export_source(export_source_path(out));
    ASSERT_TRUE(source.ok()) << source.error().message;
    EXPECT_EQ(source->format, "gaze-csv");
    // Replacing it with an export of another format is refused: told apart by its header.
    EXPECT_FALSE(export_trials(*store_, ExportFormat::FramesCsv, out).ok());
}

// P01's trial 0: three valid samples with points, two beyond m (12 m and the sky): share 2/3;
// label 1 2.5 arcmin, label 2 0 and 7.25 (mean 3.625); too short for a fixation. Trial 1: twelve
// samples without points, one fixation. P02: NA throughout.
TEST_F(GazeExportStore, TrialRowsCarryTheirGaze) {
    const std::string csv = exported(ExportFormat::Csv);
    const std::vector<std::string> lines = lines_of(csv);
    ASSERT_EQ(lines.size(), 5u) << csv;
    EXPECT_TRUE(
        lines[0].ends_with(",software_version,gaze_samples,gaze_share_beyond_m,"
                           "gaze_error_mean_arcmin_1,gaze_error_mean_arcmin_2,"
                           "gaze_error_max_arcmin_1,gaze_error_max_arcmin_2,gaze_fixations"));
    EXPECT_TRUE(lines[1].ends_with(",0.1.0,3,0.6666666666666666,2.5,3.625,2.5,7.25,0")) << lines[1];
    EXPECT_TRUE(lines[2].ends_with(",0.1.0,12,NA,NA,NA,NA,NA,1")) << lines[2];
    EXPECT_TRUE(lines[3].starts_with("P02,")) << lines[3];
    EXPECT_TRUE(lines[3].ends_with(",0.1.0,NA,NA,NA,NA,NA,NA,NA")) << lines[3];
    EXPECT_TRUE(lines[4].ends_with(",0.1.0,NA,NA,NA,NA,NA,NA,NA")) << lines[4];

    const std::string json = exported(ExportFormat::Json);
    EXPECT_NE(json.find("\"gaze_samples\": 3, \"gaze_share_beyond_m\": 0.6666666666666666, "
                        "\"gaze_error_mean_arcmin_1\": 2.5, \"gaze_error_mean_arcmin_2\": 3.625, "
                        "\"gaze_error_max_arcmin_1\": 2.5, \"gaze_error_max_arcmin_2\": 7.25, "
                        "\"gaze_fixations\": 0, "),
              std::string::npos)
        << json;
    EXPECT_NE(json.find("\"gaze_samples\": null, \"gaze_share_beyond_m\": null, "),
              std::string::npos)
        << json;
}

// A session with gaze whose trial showed no label (never started): no samples, no fixations.
TEST(GazeExport, ATrialOfAGazeSessionThatShowedNothingHasNoSamples) {
    ExportData data = data_by_hand();
    data.frames.clear();
    data.trial_gaze[1][0] = summarize_trial_gaze(gaze_log())[0];
    std::ostringstream csv;
    write_csv(data, csv);
    const std::vector<std::string> lines = lines_of(csv.str());
    ASSERT_EQ(lines.size(), 3u);
    EXPECT_TRUE(lines[1].ends_with(",3,0.6666666666666666,2.5,3.625,2.5,7.25,0")) << lines[1];
    EXPECT_TRUE(lines[2].ends_with(",0.1.0,0,NA,NA,NA,NA,NA,0")) << lines[2];
}

}  // namespace
}  // namespace monoplane::study
