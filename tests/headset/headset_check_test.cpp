// The launcher's headset step against simxr through the real OpenXR loader, with the Vulkan and
// OpenXR validation layers on (any message fails): the probe (instance and system only) and the
// headset check (a session showing the calibration screen), ended by the scripted controller's
// CONFIRM, the experimenter, the timeout, or the runtime ending or losing the session; both say
// whether the headset tracks the eyes.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <stb/stb_image.h>

#include "app/commands/headset_check.h"
#include "hmd/profile.h"

namespace monoplane::app {
namespace {

namespace fs = std::filesystem;

fs::path test_folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path dir =
        fs::temp_directory_path() /
        ("monoplane_headset_check_" + std::string(info->test_suite_name()) + "_" + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

hmd::HmdProfile vive() {
    return hmd::load_hmd_profile("vive").value_or_throw();
}

// A still head (the eyes' distance is then exact to float precision), HTC Vive controllers and
// the given extra lines (inputs, the runtime's exit or loss).
std::string write_script(const fs::path& dir, const std::string& extra) {
    const fs::path path = dir / "check.toml";
    std::ofstream out(path);
    out << "hmd = \"vive\"\n"
        << "display_rate_hz = 72\n"
        << "head_motion = \"still\"\n"
        << "interaction_profile = \"/interaction_profiles/htc/vive_controller\"\n"
        << extra;
    return path.string();
}

HeadsetCheckOptions check_options(const std::string& script) {
    HeadsetCheckOptions options;
    options.headset.headset = "simulated";
    options.headset.sim_script = script;
    options.global.validation = true;
    options.timeout_s = 60.0;
    return options;
}

TEST(HeadsetProbeTest, SimulatedReportsRuntimeSystemAndRecommendedSize) {
    HeadsetStudyOptions simulation;
    simulation.hmd = "vive";
    const headset::HeadsetProbe probe =
        probe_headset(true, simulation, /*validation=*/true).value_or_throw();
    EXPECT_TRUE(probe.runtime_available) << probe.message;
    EXPECT_EQ(probe.runtime.rfind("monoplane simxr ", 0), 0u) << probe.runtime;
    EXPECT_EQ(probe.system, "monoplane simxr: " + vive().name);
    EXPECT_EQ(probe.width, vive().width);
    EXPECT_EQ(probe.height, vive().height);
    // Only a session knows these.
    EXPECT_EQ(probe.refresh_hz, 0.0);
    EXPECT_FALSE(probe.ipd_m.has_value());
    EXPECT_EQ(probe.interaction_profile, "");
    EXPECT_EQ(probe.message, "");
}

// simxr offers eye gaze; its script decides whether the headset has an eye tracker.
TEST(HeadsetProbeTest, SimulatedSaysWhetherTheEyesAreTracked) {
    HeadsetStudyOptions simulation;
    EXPECT_EQ(probe_headset(true, simulation, true).value_or_throw().eye_gaze,
              headset::EyeGaze::Tracked);
    simulation.sim_script = write_script(test_folder(), "[gaze]\ntracker = false\n");
    const headset::HeadsetProbe probe = probe_headset(true, simulation, true).value_or_throw();
    EXPECT_EQ(probe.eye_gaze, headset::EyeGaze::NotTracked);
    EXPECT_TRUE(probe.runtime_available) << probe.message;
}

TEST(HeadsetProbeTest, MissingRuntimeSaysSoAndOffersSimulated) {
    // A simulated probe first: it must not leave the loader pointed at simxr.
    ASSERT_TRUE(probe_headset(true, {}, true).value_or_throw().runtime_available);
    const fs::path missing = test_folder() / "no_such_runtime.json";
    setenv("XR_RUNTIME_JSON", missing.c_str(), 1);
    const headset::HeadsetProbe probe = probe_headset(false, {}, true).value_or_throw();
    EXPECT_FALSE(probe.runtime_available);
    EXPECT_NE(probe.message.find("no OpenXR runtime"), std::string::npos) << probe.message;
    EXPECT_NE(probe.message.find("simulated"), std::string::npos) << probe.message;
    EXPECT_EQ(probe.eye_gaze, headset::EyeGaze::Unknown);  // no runtime to ask
    EXPECT_EQ(std::string(std::getenv("XR_RUNTIME_JSON")), missing.string());
    unsetenv("XR_RUNTIME_JSON");
}

TEST(HeadsetProbeTest, BadSimulatedScriptIsAnError) {
    HeadsetStudyOptions simulation;
    simulation.sim_script = (test_folder() / "missing.toml").string();
    const Result<headset::HeadsetProbe> probe = probe_headset(true, simulation);
    ASSERT_FALSE(probe.ok());
    EXPECT_NE(probe.error().message.find("no such file"), std::string::npos);
}

// Frame 0's display time is the script's zero: at 72 Hz the press at 0.3 s falls on frame 22.
TEST(HeadsetCheckTest, ScriptedConfirmEndsItWithTheRuntimesMeasurements) {
    const fs::path dir = test_folder();
    const std::string script = write_script(
        dir, "dump_dir = \"" + (dir / "frames").string() + "\"\ndump_every = 10\n" +
                 "[[input]]\nt = 0.3\npath = \"/user/hand/right/input/trackpad/click\"\n"
                 "duration = 0.05\n");
    int turns = 0;
    HeadsetCheckOptions options = check_options(script);
    options.on_turn = [&turns](const HeadsetCheckProgress&) {
        ++turns;
        return CheckRequest::Continue;
    };
    const HeadsetCheck check = run_headset_check(options).value_or_throw();
    EXPECT_EQ(check.end, CheckEnd::Confirmed) << check.message;
    EXPECT_NE(check.message.find("CONFIRM"), std::string::npos) << check.message;
    ASSERT_TRUE(check.ipd_m.has_value());
    EXPECT_NEAR(*check.ipd_m, vive().ipd, 1e-6);
    EXPECT_NEAR(check.refresh_hz, 72.0, 1e-3);
    EXPECT_EQ(check.interaction_profile, "/interaction_profiles/htc/vive_controller");
    EXPECT_GE(check.frames_shown, 20);
    EXPECT_LT(check.frames_shown, 40);
    EXPECT_GT(turns, 0);
    EXPECT_EQ(check.runtime.rfind("monoplane simxr ", 0), 0u) << check.runtime;
    EXPECT_EQ(check.system, "monoplane simxr: " + vive().name);
    EXPECT_EQ(check.width, vive().width);
    EXPECT_EQ(check.height, vive().height);

    // Both eyes showed the calibration screen: the grey, and the grid's bright centre cross
    // straight ahead, somewhere near the middle of the image.
    for (const char* eye : {"left", "right"}) {
        const fs::path png = dir / "frames" / ("frame_000010_" + std::string(eye) + ".png");
        int w = 0, h = 0, channels = 0;
        unsigned char* rgba = stbi_load(png.c_str(), &w, &h, &channels, 4);
        ASSERT_NE(rgba, nullptr) << png;
        int bright = 0, dark = 0;
        for (int y = h / 2 - h / 8; y < h / 2 + h / 8; ++y) {
            for (int x = w / 2 - w / 8; x < w / 2 + w / 8; ++x) {
                const unsigned char v = rgba[(std::size_t(y) * w + x) * 4];
                bright += v > 200;
                dark += v < 100;
            }
        }
        stbi_image_free(rgba);
        EXPECT_GT(bright, 100) << eye;
        EXPECT_GT(dark, 100) << eye;
    }
}

// The check asks for eye gaze: with simxr's tracker on it is tracked, and every frame shown has a
// valid sample (no blink scripted); with the eyes closed all along (a tracker that cannot see
// them) it is tracked in none; without a tracker it is not tracked.
TEST(HeadsetCheckTest, SaysWhetherTheEyeTrackerSeesTheEyes) {
    const fs::path dir = test_folder();
    const auto check = [&](const std::string& gaze) {
        HeadsetCheckOptions options = check_options(write_script(dir, gaze));
        options.on_turn = [](const HeadsetCheckProgress& progress) {
            return progress.frames_shown >= 10 ? CheckRequest::Confirm : CheckRequest::Continue;
        };
        return run_headset_check(options).value_or_throw();
    };
    HeadsetCheck seen = check("[gaze]\nblink_every_s = 0\n");
    EXPECT_EQ(seen.end, CheckEnd::Confirmed) << seen.message;
    EXPECT_EQ(seen.eye_gaze, headset::EyeGaze::Tracked);
    EXPECT_GE(seen.frames_shown, 10);
    EXPECT_EQ(seen.gaze_frames, seen.frames_shown);

    const HeadsetCheck closed = check("[[blink]]\nt = 0\nduration = 1000\n");
    EXPECT_EQ(closed.eye_gaze, headset::EyeGaze::Tracked);
    EXPECT_GE(closed.frames_shown, 10);
    EXPECT_EQ(closed.gaze_frames, 0);

    const HeadsetCheck none = check("[gaze]\ntracker = false\n");
    EXPECT_EQ(none.eye_gaze, headset::EyeGaze::NotTracked);
    EXPECT_EQ(none.gaze_frames, 0);
    EXPECT_GE(none.frames_shown, 10);
}

// The words the launcher shows for each answer.
TEST(HeadsetCheckTest, EyeGazeNamesAndSentences) {
    EXPECT_STREQ(headset::eye_gaze_name(headset::EyeGaze::Tracked), "tracked");
    EXPECT_STREQ(headset::eye_gaze_name(headset::EyeGaze::NotTracked), "not tracked");
    EXPECT_STREQ(headset::eye_gaze_name(headset::EyeGaze::NotOffered), "not offered");
    EXPECT_STREQ(headset::eye_gaze_name(headset::EyeGaze::Unknown), "");
    EXPECT_NE(headset::eye_gaze_text(headset::EyeGaze::NotTracked).find("no eye tracker"),
              std::string::npos);
    EXPECT_NE(headset::eye_gaze_text(headset::EyeGaze::NotOffered).find("runtime"),
              std::string::npos);
    EXPECT_EQ(headset::eye_gaze_text(headset::EyeGaze::Unknown), "");
}

TEST(HeadsetCheckTest, RuntimeEndingTheSessionMidCheckIsAnOutcome) {
    const fs::path dir = test_folder();
    const HeadsetCheck check =
        run_headset_check(check_options(write_script(dir, "exit_after_s = 0.2\n")))
            .value_or_throw();
    EXPECT_EQ(check.end, CheckEnd::RuntimeEnded) << check.message;
    EXPECT_NE(check.message.find("ended the session"), std::string::npos) << check.message;
    EXPECT_GT(check.frames_shown, 0);
}

TEST(HeadsetCheckTest, LostSessionMidCheckIsAnOutcome) {
    const fs::path dir = test_folder();
    const HeadsetCheck check =
        run_headset_check(check_options(write_script(dir, "lose_session_at_s = 0.2\n")))
            .value_or_throw();
    EXPECT_EQ(check.end, CheckEnd::RuntimeLost) << check.message;
    EXPECT_NE(check.message.find("lost"), std::string::npos) << check.message;
}

TEST(HeadsetCheckTest, ExperimenterCancelsOrConfirms) {
    const fs::path dir = test_folder();
    HeadsetCheckOptions options = check_options(write_script(dir, ""));
    options.on_turn = [](const HeadsetCheckProgress& progress) {
        return progress.frames_shown >= 5 ? CheckRequest::Cancel : CheckRequest::Continue;
    };
    HeadsetCheck check = run_headset_check(options).value_or_throw();
    EXPECT_EQ(check.end, CheckEnd::Cancelled) << check.message;
    EXPECT_GE(check.frames_shown, 5);

    options.on_turn = [](const HeadsetCheckProgress& progress) {
        return progress.ipd_m ? CheckRequest::Confirm : CheckRequest::Continue;
    };
    check = run_headset_check(options).value_or_throw();
    EXPECT_EQ(check.end, CheckEnd::Confirmed) << check.message;
    EXPECT_NE(check.message.find("experimenter"), std::string::npos) << check.message;
}

TEST(HeadsetCheckTest, NoConfirmTimesOut) {
    const fs::path dir = test_folder();
    HeadsetCheckOptions options = check_options(write_script(dir, ""));
    options.timeout_s = 0.5;
    const HeadsetCheck check = run_headset_check(options).value_or_throw();
    EXPECT_EQ(check.end, CheckEnd::TimedOut) << check.message;
    EXPECT_NE(check.message.find("no CONFIRM"), std::string::npos) << check.message;
}

TEST(HeadsetCheckTest, UnknownHeadsetIsAnError) {
    HeadsetCheckOptions options;
    options.headset.headset = "oculus";
    const Result<HeadsetCheck> check = run_headset_check(options);
    ASSERT_FALSE(check.ok());
    EXPECT_NE(check.error().message.find("simulated or openxr"), std::string::npos);
}

}  // namespace
}  // namespace monoplane::app
