// simxr's script: values, defaults, located errors, pose interpolation, press windows.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <glm/gtc/quaternion.hpp>

#include "simxr/script.h"

namespace monoplane::simxr {
namespace {

const std::filesystem::path kSource = "/scripts/session.toml";

Script parse_ok(const std::string& text) {
    auto script = parse_script(text, kSource);
    EXPECT_TRUE(script.ok()) << (script.ok() ? "" : script.error().message);
    return script.ok() ? std::move(script).value() : Script{};
}

std::string parse_error(const std::string& text) {
    auto script = parse_script(text, kSource);
    EXPECT_FALSE(script.ok());
    return script.ok() ? "" : script.error().message;
}

TEST(SimxrScript, EmptyScriptKeepsEveryDefault) {
    const Script script = parse_ok("");
    EXPECT_EQ(script.hmd.ipd, 0.064);
    EXPECT_EQ(script.hmd.width, 1344);
    EXPECT_EQ(script.display_rate_hz, 90.0);
    EXPECT_EQ(script.physical_device, "");
    EXPECT_EQ(script.interaction_profile, "/interaction_profiles/khr/simple_controller");
    EXPECT_TRUE(script.dump_dir.empty());
    EXPECT_EQ(script.dump_every, 1);
    EXPECT_EQ(script.missed_slot_every, 0);
    EXPECT_EQ(script.exit_after_s, 0.0);
    EXPECT_EQ(script.lose_session_at_s, 0.0);
    EXPECT_EQ(script.lose_instance_at_s, 0.0);
    EXPECT_TRUE(script.poses.empty());
    EXPECT_TRUE(script.inputs.empty());
    EXPECT_EQ(script.frame_period_ns(), 11'111'111);
}

TEST(SimxrScript, ReadsEveryKey) {
    const Script script = parse_ok(R"(
hmd = "symmetric-90"
display_rate_hz = 120
physical_device = "llvmpipe"
interaction_profile = "/interaction_profiles/htc/vive_controller"
dump_dir = "frames"
dump_every = 5
missed_slot_every = 4
exit_after_s = 3.5
lose_session_at_s = 7
lose_instance_at_s = 8.5
[[pose]]
t = 0.0
position = [0.0, 1.7, 0.5]
yaw_pitch_roll_deg = [10, 0, 0]
[[input]]
t = 1.0
path = "/user/hand/right/input/trigger/click"
duration = 0.25
)");
    EXPECT_EQ(script.hmd_name, "symmetric-90");
    EXPECT_EQ(script.display_rate_hz, 120.0);
    EXPECT_EQ(script.physical_device, "llvmpipe");
    EXPECT_EQ(script.interaction_profile, "/interaction_profiles/htc/vive_controller");
    // Relative paths resolve against the script's folder.
    EXPECT_EQ(script.dump_dir, std::filesystem::path("/scripts/frames"));
    EXPECT_EQ(script.dump_every, 5);
    EXPECT_EQ(script.missed_slot_every, 4);
    EXPECT_EQ(script.exit_after_s, 3.5);
    EXPECT_EQ(script.lose_session_at_s, 7.0);
    EXPECT_EQ(script.lose_instance_at_s, 8.5);
    ASSERT_EQ(script.poses.size(), 1u);
    EXPECT_EQ(script.poses[0].position, glm::dvec3(0.0, 1.7, 0.5));
    EXPECT_EQ(script.poses[0].yaw_pitch_roll_deg, glm::dvec3(10.0, 0.0, 0.0));
    ASSERT_EQ(script.inputs.size(), 1u);
    EXPECT_EQ(script.inputs[0].path, "/user/hand/right/input/trigger/click");
    EXPECT_EQ(script.inputs[0].duration, 0.25);
}

TEST(SimxrScript, HmdFileResolvesAgainstTheScriptFolder) {
    const auto folder = std::filesystem::temp_directory_path() / "simxr_script_test_hmd";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "narrow.toml") << R"(name = "narrow"
ipd = 0.06
width = 640
height = 480
[left]
tan_left = -0.5
tan_right = 0.5
tan_up = 0.4
tan_down = -0.4
[right]
tan_left = -0.5
tan_right = 0.5
tan_up = 0.4
tan_down = -0.4
)";
    std::ofstream(folder / "script.toml") << "hmd = \"narrow.toml\"\n";
    auto script = load_script(folder / "script.toml");
    ASSERT_TRUE(script.ok()) << script.error().message;
    EXPECT_EQ(script->hmd.name, "narrow");
    EXPECT_EQ(script->hmd.width, 640);
    std::filesystem::remove_all(folder);
}

TEST(SimxrScript, ErrorsNameFileLineAndKey) {
    const std::string message = parse_error("dump_every = 1\ndisplay_rate_hz = \"fast\"\n");
    EXPECT_NE(message.find("/scripts/session.toml:2:"), std::string::npos) << message;
    EXPECT_NE(message.find("display_rate_hz"), std::string::npos) << message;
}

TEST(SimxrScript, AMissedSlotEveryFrameIsRefused) {
    const std::string message = parse_error("missed_slot_every = 1\n");
    EXPECT_NE(message.find("/scripts/session.toml:1:"), std::string::npos) << message;
    EXPECT_NE(message.find("missed_slot_every"), std::string::npos) << message;
    EXPECT_NE(message.find("at least 2"), std::string::npos) << message;
}

TEST(SimxrScript, ReportsAllProblemsAtOnce) {
    const std::string message = parse_error(R"(hmd = "no-such-headset"
dispay_rate_hz = 90
dump_every = 0
[[input]]
t = 1.0
path = "/user/hand/right/input/trigger/click"
)");
    EXPECT_NE(message.find(":1:"), std::string::npos) << message;
    EXPECT_NE(message.find("'hmd'"), std::string::npos) << message;
    EXPECT_NE(message.find("did you mean 'display_rate_hz'"), std::string::npos) << message;
    EXPECT_NE(message.find(":3:"), std::string::npos) << message;
    // simple_controller has no trigger.
    EXPECT_NE(message.find(":6:"), std::string::npos) << message;
    EXPECT_NE(message.find("input[0].path"), std::string::npos) << message;
}

TEST(SimxrScript, RefusesBadRangesAndOrder) {
    EXPECT_NE(parse_error("display_rate_hz = 0").find("display_rate_hz"), std::string::npos);
    EXPECT_NE(parse_error("exit_after_s = -1").find("exit_after_s"), std::string::npos);
    EXPECT_NE(parse_error("lose_instance_at_s = -1").find("lose_instance_at_s"), std::string::npos);
    // Found by the fuzzer (tests/fuzz): 1e9 / rate ns and times in ns must fit the int64 clock.
    EXPECT_NE(parse_error("display_rate_hz = 5e-324").find("display_rate_hz"), std::string::npos);
    EXPECT_NE(parse_error("exit_after_s = 1e300").find("exit_after_s"), std::string::npos);
    EXPECT_NE(parse_error("[[input]]\nt = 9e9\npath = \"/user/hand/left/input/menu/click\"\n"
                          "duration = 9e9\n")
                  .find("input[0].duration"),
              std::string::npos);
    EXPECT_NE(parse_error("interaction_profile = \"/interaction_profiles/acme/stick\"")
                  .find("interaction_profile"),
              std::string::npos);
    EXPECT_NE(parse_error("[[pose]]\nt = 1\n[[pose]]\nt = 0.5\n").find("pose[1].t"),
              std::string::npos);
    EXPECT_NE(parse_error("[[pose]]\nt = 0\nposition = [0, 1]\n").find("pose[0].position"),
              std::string::npos);
    EXPECT_NE(parse_error("[pose]\nt = 0\n").find("[[pose]]"), std::string::npos);
    EXPECT_NE(
        parse_error("[[input]]\npath = \"/user/hand/left/input/menu/click\"\n").find("input[0].t"),
        std::string::npos);
    EXPECT_NE(parse_error("[[input]]\nt = 0\npath = \"/user/hand/left/input/grip/pose\"\n")
                  .find("no button"),
              std::string::npos);
}

// Any OpenXR 1.0 profile may be the simulated one, hands or not (spec 6.4).
TEST(SimxrScript, AnyCoreProfileWithItsOwnButtonsAndAxes) {
    const Script gamepad = parse_ok(R"(
interaction_profile = "/interaction_profiles/microsoft/xbox_controller"
[[input]]
t = 0.5
path = "/user/gamepad/input/a/click"
[[input]]
t = 0.5
path = "/user/gamepad/input/trigger_left/value"
)");
    EXPECT_EQ(gamepad.interaction_profile, "/interaction_profiles/microsoft/xbox_controller");
    ASSERT_EQ(gamepad.inputs.size(), 2u);
    EXPECT_EQ(gamepad.inputs[1].path, "/user/gamepad/input/trigger_left/value");
    const Script head = parse_ok(R"(
interaction_profile = "/interaction_profiles/htc/vive_pro"
[[input]]
t = 0.5
path = "/user/head/input/volume_down/click"
)");
    ASSERT_EQ(head.inputs.size(), 1u);
    const Script motion = parse_ok(R"(
interaction_profile = "/interaction_profiles/microsoft/motion_controller"
[[input]]
t = 0.5
path = "/user/hand/left/input/thumbstick/x"
)");
    ASSERT_EQ(motion.inputs.size(), 1u);
    // The gamepad has no hands, and its haptics are outputs; the hint names a gamepad button.
    const std::string message = parse_error(R"(
interaction_profile = "/interaction_profiles/microsoft/xbox_controller"
[[input]]
t = 0.5
path = "/user/hand/right/input/a/click"
[[input]]
t = 0.5
path = "/user/gamepad/output/haptic_left"
)");
    EXPECT_NE(message.find("input[0].path"), std::string::npos) << message;
    EXPECT_NE(message.find("input[1].path"), std::string::npos) << message;
    EXPECT_NE(message.find("e.g. /user/gamepad/input/"), std::string::npos) << message;
}

TEST(SimxrScript, PoseInterpolatesAndHolds) {
    const Script script = parse_ok(R"(
[[pose]]
t = 1.0
position = [0.0, 1.6, 0.0]
[[pose]]
t = 2.0
position = [1.0, 1.6, -2.0]
yaw_pitch_roll_deg = [90, 0, 0]
)");
    // Before the first keyframe: held.
    EXPECT_EQ(head_pose_at(script, 0.0).position, glm::dvec3(0.0, 1.6, 0.0));
    const rig::Pose middle = head_pose_at(script, 1.5);
    EXPECT_NEAR(middle.position.x, 0.5, 1e-12);
    EXPECT_NEAR(middle.position.z, -1.0, 1e-12);
    // Yaw 45 degrees to the left: forward (-z) turns towards -x.
    const glm::dvec3 forward = middle.orientation * glm::dvec3(0.0, 0.0, -1.0);
    EXPECT_NEAR(forward.x, -std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(forward.z, -std::sqrt(0.5), 1e-12);
    // After the last keyframe: held.
    const rig::Pose after = head_pose_at(script, 10.0);
    EXPECT_EQ(after.position, glm::dvec3(1.0, 1.6, -2.0));
    const glm::dvec3 after_forward = after.orientation * glm::dvec3(0.0, 0.0, -1.0);
    EXPECT_NEAR(after_forward.x, -1.0, 1e-12);
}

TEST(SimxrScript, PitchLooksUpAndRollTiltsLeft) {
    const Script script = parse_ok("[[pose]]\nt = 0\nyaw_pitch_roll_deg = [0, 90, 0]\n");
    const glm::dvec3 forward = head_pose_at(script, 0.0).orientation * glm::dvec3(0, 0, -1);
    EXPECT_NEAR(forward.y, 1.0, 1e-12);
    const Script rolled = parse_ok("[[pose]]\nt = 0\nyaw_pitch_roll_deg = [0, 0, 90]\n");
    const glm::dvec3 right = head_pose_at(rolled, 0.0).orientation * glm::dvec3(1, 0, 0);
    EXPECT_NEAR(right.y, 1.0, 1e-12);
}

// head_motion = "seated": a seated person's small continuous motion on top of the keyframes.
// Checked against its stated envelope (yaw up to 9 degrees at up to about 11 degrees a second,
// pitch 4.5, roll 1, position 3 cm) over ten minutes of 90 Hz frames, independently of its
// formula: angles from the forward and right vectors, rates from consecutive frames.
TEST(SimxrScript, SeatedMotionTurnsTheHeadSmallAndContinuously) {
    EXPECT_EQ(parse_ok("").head_motion, HeadMotion::kStill);
    const Script script = parse_ok(
        "head_motion = \"seated\"\n[[pose]]\nt = 0\n"
        "position = [0.5, 1.2, 0.0]\nyaw_pitch_roll_deg = [90, 0, 0]\n");
    ASSERT_EQ(script.head_motion, HeadMotion::kSeated);
    const double frame = 1.0 / 90.0;
    double max_yaw = 0.0, max_pitch = 0.0, max_roll = 0.0, max_offset = 0.0, max_rate = 0.0;
    double previous_yaw = 0.0;
    std::size_t distinct = 0;
    glm::dquat previous_orientation{1.0, 0.0, 0.0, 0.0};
    for (int i = 0; i < 90 * 600; ++i) {
        const rig::Pose pose = head_pose_at(script, i * frame);
        // In the keyframe's frame: the keyframe turned the head 90 degrees left.
        const glm::dquat keyed = glm::angleAxis(glm::radians(90.0), glm::dvec3(0, 1, 0));
        const glm::dquat motion = glm::inverse(keyed) * pose.orientation;
        const glm::dvec3 forward = motion * glm::dvec3(0, 0, -1);
        const glm::dvec3 right = motion * glm::dvec3(1, 0, 0);
        const double yaw = glm::degrees(std::atan2(-forward.x, -forward.z));
        max_yaw = std::max(max_yaw, std::abs(yaw));
        max_pitch = std::max(max_pitch, std::abs(glm::degrees(std::asin(forward.y))));
        max_roll = std::max(max_roll, std::abs(glm::degrees(std::asin(right.y))));
        max_offset = std::max(max_offset, glm::length(pose.position - glm::dvec3(0.5, 1.2, 0.0)));
        if (i > 0) max_rate = std::max(max_rate, std::abs(yaw - previous_yaw) / frame);
        if (i > 0 && pose.orientation != previous_orientation) ++distinct;
        previous_yaw = yaw;
        previous_orientation = pose.orientation;
    }
    EXPECT_GT(max_yaw, 6.0);  // it does turn, within its envelope
    EXPECT_LE(max_yaw, 9.0 + 1e-6);
    EXPECT_GT(max_pitch, 2.0);
    EXPECT_LE(max_pitch, 4.5 + 0.1);  // pitch measured after yaw: within a tenth of a degree
    EXPECT_LE(max_roll, 1.0 + 0.1);
    EXPECT_GT(max_offset, 0.01);
    EXPECT_LE(max_offset, std::sqrt(0.02 * 0.02 + 0.01 * 0.01 + 0.015 * 0.015) + 1e-12);
    // The yaw's rate is at most 2 pi (6 * 0.11 + 3 * 0.22 golden) degrees a second: 10.9.
    EXPECT_LE(max_rate,
              2.0 * 3.14159265358979 * (6.0 * 0.11 + 3.0 * 0.11 * (1.0 + std::sqrt(5.0))));
    EXPECT_EQ(distinct, 90u * 600u - 1u);  // every frame a new view
    // And no view comes back: 100 s later (the period rational frequencies would give) the head
    // is elsewhere.
    EXPECT_GT(
        glm::length(head_pose_at(script, 110.0).position - head_pose_at(script, 10.0).position),
        1e-4);
    EXPECT_NE(parse_error("head_motion = \"wobbly\"\n").find("still"), std::string::npos);
}

TEST(SimxrScript, PressWindowIsHalfOpen) {
    const Script script = parse_ok(R"(
display_rate_hz = 100
[[input]]
t = 1.0
path = "/user/hand/right/input/select/click"
duration = 0.05
[[input]]
t = 2.0
path = "/user/hand/left/input/menu/click"
)");
    const std::string select = "/user/hand/right/input/select/click";
    EXPECT_FALSE(input_pressed_at(script, select, 999'999'999));
    EXPECT_TRUE(input_pressed_at(script, select, 1'000'000'000));
    EXPECT_TRUE(input_pressed_at(script, select, 1'049'999'999));
    EXPECT_FALSE(input_pressed_at(script, select, 1'050'000'000));
    EXPECT_FALSE(input_pressed_at(script, "/user/hand/left/input/select/click", 1'000'000'000));
    // No duration: one frame period (10 ms at 100 Hz).
    const std::string menu = "/user/hand/left/input/menu/click";
    EXPECT_TRUE(input_pressed_at(script, menu, 2'000'000'000));
    EXPECT_TRUE(input_pressed_at(script, menu, 2'009'999'999));
    EXPECT_FALSE(input_pressed_at(script, menu, 2'010'000'000));
}

}  // namespace
}  // namespace monoplane::simxr
