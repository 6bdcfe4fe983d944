// Eye gaze in a headset session (issue 45, part 1): `study run --headset simulated` with a
// protocol that asks for gaze ([gaze] record = true) on simxr, whose script fixates a point
// straight ahead of the still head and blinks every 2 s. Every logged frame holds the gaze: the
// valid ones along the head's -z (worked out by hand: the point lies on the view axis), the
// frames inside a blink invalid without a direction. On a runtime without an eye tracker
// (`[gaze] tracker = false`) the session says so, notes it in the database, and logs no gaze.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "study/study_store.h"
#include "tests/e2e/test_files.h"

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
                                            std::vector<study::SessionNote>* notes) {
        const fs::path script = dir_ / "script.toml";
        std::ofstream(script) << "hmd = \"vive\"\ndisplay_rate_hz = 5\n" << gaze;
        const fs::path db = dir_ / "gaze.sqlite";
        fs::remove(db);
        EXPECT_EQ(
            run(std::string(MONOPLANE_EXE) + " --validation study run --protocol " +
                    (dir_ / "gaze.toml").string() + " --participant G --db " + db.string() +
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
        EXPECT_FALSE(f.gaze_point) << "not derived yet";
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
