// Eye gaze in a headset session (issue 45, part 1): `study run --headset simulated` with a
// protocol that asks for gaze ([gaze] record = true) on simxr, whose script fixates a point
// straight ahead of the still head and blinks every 2 s. Every logged frame holds the gaze: the
// valid ones along the head's -z (worked out by hand: the point lies on the view axis), the
// frames inside a blink invalid without a direction. On a runtime without an eye tracker
// (`[gaze] tracker = false`) the session says so, notes it in the database, and logs no gaze.
// Where the gaze rests on a wall at a known distance, the logged error is the geometry's.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "study/study_store.h"
#include "tests/e2e/test_files.h"
#include "tests/unit/gltf_test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

std::string source_dir() {
    const char* dir = std::getenv("MONOPLANE_SOURCE_DIR");
    return dir ? dir : ".";
}

int run(const std::string& command, std::string* output) {
    const std::string log = (test_folder() / "command.log").string();
    const int status = std::system((command + " > " + log + " 2>&1").c_str());
    std::ifstream in(log);
    std::stringstream text;
    text << in.rdbuf();
    *output = text.str();
    return WEXITSTATUS(status);
}

class HeadsetGazeTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = test_folder();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        // The demo protocol, asking for gaze.
        std::ifstream demo(source_dir() + "/protocols/demo.toml");
        std::stringstream text;
        text << demo.rdbuf() << "\n[gaze]\nrecord = true\n";
        std::ofstream(dir_ / "gaze.toml") << text.str();
    }

    // A session on simxr with `gaze` as the script's [gaze] table; its frames.
    std::vector<study::FrameRecord> session(const std::string& gaze, std::string* output,
                                            std::vector<study::SessionNote>* notes,
                                            const std::string& protocol = "gaze.toml") {
        const fs::path script = dir_ / "script.toml";
        std::ofstream(script) << "hmd = \"vive\"\ndisplay_rate_hz = 5\n" << gaze;
        const fs::path db = dir_ / "gaze.sqlite";
        fs::remove(db);
        EXPECT_EQ(
            run(std::string(MONOPLANE_EXE) + " --validation study run --protocol " +
                    (dir_ / protocol).string() + " --participant G --db " + db.string() +
                    " --headset simulated --observer default --sim-script " + script.string() +
                    " --window off --detail test --resolution-scale 0.1 --neutral-s 0.3 "
                    "--seed 5",
                output),
            0)
            << *output;
        auto store = study::StudyStore::open(db);
        EXPECT_TRUE(store) << store.error().message;
        if (!store) return {};
        *notes = (*store)->session(1).value_or_throw().notes;
        return (*store)->frames(1).value_or_throw();
    }

    fs::path dir_;
};

TEST_F(HeadsetGazeTest, EveryFrameLogsTheGazeAndBlinksAreInvalid) {
    std::string output;
    std::vector<study::SessionNote> notes;
    const std::vector<study::FrameRecord> frames = session(
        "[gaze]\nblink_every_s = 2\nblink_s = 0.15\n"
        "[[fixation]]\nt = 0\nduration = 1000\ntarget = [0.0, 1.6, -10.0]\n",
        &output, &notes);
    EXPECT_NE(output.find("eye gaze: recorded per frame"), std::string::npos) << output;
    ASSERT_GT(frames.size(), 50u);
    int valid = 0;
    int blinks = 0;
    for (const study::FrameRecord& f : frames) {
        ASSERT_TRUE(f.gaze) << "frame " << f.frame;
        // Gaze points for every frame that showed a trial's scene with a valid sample.
        const bool scene = f.shown == "label1" || f.shown == "label2";
        EXPECT_EQ(f.gaze_point.has_value(), scene && f.gaze->valid) << "frame " << f.frame;
        if (!f.gaze->valid) {
            ++blinks;
            continue;
        }
        ++valid;
        // The point lies on the head's view axis: the gaze is -z, to float precision.
        EXPECT_NEAR(f.gaze->direction[0], 0.0, 1e-6) << "frame " << f.frame;
        EXPECT_NEAR(f.gaze->direction[1], 0.0, 1e-6) << "frame " << f.frame;
        EXPECT_NEAR(f.gaze->direction[2], -1.0, 1e-6) << "frame " << f.frame;
    }
    // At 5 Hz a 0.15 s blink every 2 s covers one frame in ten.
    EXPECT_GT(blinks, 0);
    EXPECT_NEAR(static_cast<double>(blinks) / static_cast<double>(frames.size()), 0.1, 0.03);
    EXPECT_GT(valid, blinks);
}

// Issue 45, part 3: the error where the eye rests, at a known point. A scene of one wall, 12 m
// ahead of its camera (the default viewpoint) at eye height, and the eyes fixed straight ahead:
// every trial frame's gaze point lies on the wall at depth 12 m, in hybrid and in stereo frames.
// Hybrid at m = 3 shows it where C's ray meets the plane, straight ahead at (0, 0, -3), so each
// eye's error is atan(d / 2m) - atan(d / 2z) with the Vive's d = 0.064 m, whatever C's offset.
TEST_F(HeadsetGazeTest, TheErrorAtAGazeOnAWallTwelveMetresAheadIsTheGeometrys) {
    scenes::testing::TestGltf wall;
    const int positions =
        wall.add_positions({{-6, 0, -12}, {6, 0, -12}, {6, 4, -12}, {-6, 4, -12}});
    wall.add_node(
        {{"mesh", wall.add_mesh({{"POSITION", positions}}, wall.add_indices({0, 1, 2, 0, 2, 3}))}});
    wall.json["cameras"] = {
        {{"type", "perspective"}, {"perspective", {{"yfov", 1.5}, {"znear", 0.1}}}}};
    wall.add_node({{"camera", 0}, {"translation", {0.0, 1.7, 0.0}}});
    wall.write_gltf(dir_ / "wall.gltf");
    std::ofstream(dir_ / "wall.toml")
        << "name = \"wall\"\nscenes = [\"wall.gltf\"]\nmono_planes = [3]\n"
           "alternatives = [\"stereo\", \"hybrid\"]\npractice_trials = 0\n[gaze]\nrecord = true\n";
    std::string output;
    std::vector<study::SessionNote> notes;
    const std::vector<study::FrameRecord> frames = session(
        "[gaze]\nblink_every_s = 1000\n[[fixation]]\nt = 0\nduration = 1000\n"
        "yaw_pitch_deg = [0, 0]\n",
        &output, &notes, "wall.toml");
    constexpr double kArcmin = 60.0 * 180.0 / 3.14159265358979323846;
    const double expected = (std::atan(0.032 / 3.0) - std::atan(0.032 / 12.0)) * kArcmin;
    int points = 0;
    for (const study::FrameRecord& f : frames) {
        if (!f.gaze_point) continue;
        ++points;
        ASSERT_TRUE(f.gaze_point->depth_m) << "frame " << f.frame;
        EXPECT_NEAR(*f.gaze_point->depth_m, 12.0, 1e-3) << "frame " << f.frame;
        EXPECT_EQ(f.gaze_point->mono_plane_m, 3.0);
        EXPECT_NEAR(f.gaze_point->error_arcmin, expected, 0.01) << "frame " << f.frame;
    }
    EXPECT_GT(points, 10) << output;
}

TEST_F(HeadsetGazeTest, ARuntimeWithoutAnEyeTrackerSaysSoAndLogsNoGaze) {
    std::string output;
    std::vector<study::SessionNote> notes;
    const std::vector<study::FrameRecord> frames =
        session("[gaze]\ntracker = false\n", &output, &notes);
    EXPECT_NE(output.find("no eye gaze on this runtime"), std::string::npos) << output;
    bool noted = false;
    for (const study::SessionNote& note : notes) {
        noted = noted || note.text.find("no eye gaze on this runtime") != std::string::npos;
    }
    EXPECT_TRUE(noted);
    ASSERT_GT(frames.size(), 50u);
    for (const study::FrameRecord& f : frames) EXPECT_FALSE(f.gaze) << "frame " << f.frame;
}

}  // namespace
}  // namespace monoplane
