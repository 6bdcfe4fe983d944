// The gaze marker in a whole session (issue 45): `study run --headset simulated` with a protocol
// that records gaze, the experimenter window on a virtual X server, simxr's canted headset
// (canted-15: the Vive's asymmetric frusta, each display turned 15 degrees outwards) and a script
// that fixates 15 degrees left and 20 degrees up. That direction is the left eye's own axis
// pitched up by 20 degrees, so in the mirrored left eye's image the gaze lies where its frustum
// puts the axis across, u = -tan_left / (tan_right - tan_left), and tan 20 degrees up,
// v = (tan_up - tan 20) / (tan_up - tan_down), worked out by hand from the profile's tangents.
// The --screenshot's state dump must put the marker there and the screenshot must show it; a
// blink shows no gaze point, a headset without an eye tracker no marker. Run under xvfb-run by
// ctest, with the OpenXR and Vulkan validation layers on.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <stb/stb_image.h>
#include <nlohmann/json.hpp>

#include "tests/e2e/test_files.h"

namespace monoplane {
namespace {

namespace fs = std::filesystem;

// canted-15's left eye (hmd/profiles/canted-15.toml): tan_left -1.391937, tan_right 1.247409,
// tan_up 1.464287, tan_down -1.468819; tan 20 degrees = 0.3639702343.
// u = 1.391937 / 2.639346 = 0.5273795099, v = (1.464287 - 0.3639702343) / 2.933106 = 0.3751370614.
constexpr double kExpectedU = 0.5273795099;
constexpr double kExpectedV = 0.3751370614;
// simxr hands the views' poses, field of view angles and the gaze pose to OpenXR as floats: each
// angle and tangent is off by up to a few 1e-8 relative, which moves the point by under 1e-6 of
// the image. 1e-5 leaves room for that (and the constants' 10 digits) while staying a
// hundredth of a pixel of even a 1344-pixel eye image: any error of the geometry (a cant
// ignored: 0.13 in u; the tangents' sign: 0.05) fails.
constexpr double kUvTolerance = 1e-5;

int run(const std::string& command, std::string* output) {
    const std::string log = (test_folder() / "command.log").string();
    const int status = std::system((command + " > " + log + " 2>&1").c_str());
    *output = read_file(log);
    return WEXITSTATUS(status);
}

struct Rgb {
    int r = 0, g = 0, b = 0;
};

// The screenshot's pixel at (x, y) (black outside it or when it cannot be read).
Rgb pixel(const fs::path& png, double x, double y) {
    int width = 0, height = 0, channels = 0;
    unsigned char* rgb = stbi_load(png.c_str(), &width, &height, &channels, 3);
    const int px = static_cast<int>(std::lround(x)), py = static_cast<int>(std::lround(y));
    Rgb c;
    if (rgb != nullptr && px >= 0 && py >= 0 && px < width && py < height) {
        const unsigned char* p = rgb + (static_cast<std::size_t>(py) * width + px) * 3;
        c = {p[0], p[1], p[2]};
    }
    stbi_image_free(rgb);
    return c;
}

class GazeMarkerSession : public ::testing::Test {
  protected:
    void SetUp() override {
        if (std::getenv("DISPLAY") == nullptr) GTEST_SKIP() << "no X server (run xvfb-run)";
        dir_ = test_folder();
        fs::remove_all(dir_);
        fs::create_directories(dir_);
        // One trial, gaze recorded.
        std::ofstream(dir_ / "gaze.toml") << "name = \"gaze\"\nscenes = [\"spheres\"]\n"
                                             "mono_planes = [3]\nalternatives = [\"stereo\", "
                                             "\"hybrid\"]\npractice_trials = 0\n"
                                             "[gaze]\nrecord = true\n";
    }

    // A session on simxr's canted headset at 5 Hz with `gaze` as the script's eye gaze; the
    // state the window dumped beside its screenshot after frame 8 (1.6 s on the script's clock).
    nlohmann::json session(const std::string& gaze) {
        std::ofstream(dir_ / "script.toml") << "hmd = \"canted-15\"\ndisplay_rate_hz = 5\n" << gaze;
        std::string output;
        EXPECT_EQ(run(std::string(MONOPLANE_EXE) + " --validation study run --protocol " +
                          (dir_ / "gaze.toml").string() + " --participant G --db " +
                          (dir_ / "gaze.sqlite").string() +
                          " --headset simulated --observer default --sim-script " +
                          (dir_ / "script.toml").string() +
                          " --window on --detail test --resolution-scale 0.1 --neutral-s 0.3 "
                          "--end-s 0 --seed 5 --screenshot " +
                          shot().string() + " --screenshot-frame 8",
                      &output),
                  0)
            << output;
        std::ifstream in(dir_ / "window.json");
        EXPECT_TRUE(in) << "no state beside the screenshot\n" << output;
        if (!in) return {};
        const nlohmann::json state = nlohmann::json::parse(in);
        EXPECT_EQ(state["frame_index"], 8) << state;
        return state;
    }

    fs::path shot() const { return dir_ / "window.png"; }

    fs::path dir_;
};

// The fixation along the left eye's axis, pitched 20 degrees up: the marker where the profile's
// tangents put it, drawn there.
TEST_F(GazeMarkerSession, TheMarkerIsWhereTheScriptPutsTheGaze) {
    const nlohmann::json state = session(
        "[gaze]\nblink_every_s = 0\n"
        "[[fixation]]\nt = 0\nduration = 1000\nyaw_pitch_deg = [15.0, 20.0]\n");
    const nlohmann::json gaze = state["gaze"];
    EXPECT_EQ(gaze["tracked"], true) << state;
    EXPECT_EQ(gaze["shown"], "point") << state;
    ASSERT_TRUE(gaze["uv"].is_array()) << state;
    EXPECT_NEAR(gaze["uv"][0].get<double>(), kExpectedU, kUvTolerance) << state;
    EXPECT_NEAR(gaze["uv"][1].get<double>(), kExpectedV, kUvTolerance) << state;

    // Drawn there: the marker's centre over the mirror where the uv says, its ring in the
    // marker's green on either side.
    const nlohmann::json& mirror = state["mirror"];
    const double x = mirror["x"].get<double>() + kExpectedU * mirror["width"].get<double>();
    const double y = mirror["y"].get<double>() + kExpectedV * mirror["height"].get<double>();
    ASSERT_TRUE(gaze["marker"].is_array()) << state;
    EXPECT_NEAR(gaze["marker"][0].get<double>(), x, 0.01) << state;
    EXPECT_NEAR(gaze["marker"][1].get<double>(), y, 0.01) << state;
    const double radius = gaze["radius"];
    for (const double dx : {-radius, radius}) {
        const Rgb ring = pixel(shot(), x + dx, y);
        EXPECT_TRUE(ring.g > 180 && ring.r < 160 && ring.b < 190)
            << ring.r << " " << ring.g << " " << ring.b << " at " << x + dx << ", " << y;
    }
}

// Frame 8 (1.6 s) inside a scripted blink: no gaze point, the faded ring where frame 7 saw it.
TEST_F(GazeMarkerSession, ABlinkShowsNoGazePoint) {
    const nlohmann::json state = session(
        "[gaze]\nblink_every_s = 0\n"
        "[[fixation]]\nt = 0\nduration = 1000\nyaw_pitch_deg = [15.0, 20.0]\n"
        "[[blink]]\nt = 1.5\nduration = 0.2\n");
    const nlohmann::json gaze = state["gaze"];
    EXPECT_EQ(gaze["tracked"], true) << state;
    EXPECT_TRUE(gaze["uv"].is_null()) << state;
    EXPECT_EQ(gaze["shown"], "lost") << state;
    const nlohmann::json& mirror = state["mirror"];
    ASSERT_TRUE(gaze["marker"].is_array()) << state;
    EXPECT_NEAR(gaze["marker"][0].get<double>(),
                mirror["x"].get<double>() + kExpectedU * mirror["width"].get<double>(), 0.01);
}

// A headset without an eye tracker: no gaze, no marker.
TEST_F(GazeMarkerSession, NoEyeTrackerNoMarker) {
    const nlohmann::json state = session("[gaze]\ntracker = false\n");
    EXPECT_EQ(state["gaze"]["tracked"], false) << state;
    EXPECT_TRUE(state["gaze"]["uv"].is_null()) << state;
    EXPECT_EQ(state["gaze"]["shown"], "none") << state;
    EXPECT_TRUE(state["gaze"]["marker"].is_null()) << state;
}

}  // namespace
}  // namespace monoplane
