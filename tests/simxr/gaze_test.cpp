// simxr's eye gaze (simxr/gaze.h): the script's [gaze], [[fixation]] and [[blink]], and the
// gaze over time, checked against directions worked out here by hand: a fixation on a known
// point while the head turns, angles in the head's view, saccades between fixations, blinks as
// invalid samples, and the default's rate and spread.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "simxr/gaze.h"
#include "simxr/script.h"

namespace monoplane::simxr {
namespace {

const std::filesystem::path kSource = "/scripts/gaze.toml";

Script parse_ok(const std::string& text) {
    auto script = parse_script(text, kSource);
    EXPECT_TRUE(script.ok()) << (script.ok() ? "" : script.error().message);
    return script.ok() ? std::move(script).value() : Script{};
}

// The angle between two directions, in degrees.
double degrees_between(const glm::dvec3& a, const glm::dvec3& b) {
    return glm::degrees(
        std::acos(std::clamp(glm::dot(glm::normalize(a), glm::normalize(b)), -1.0, 1.0)));
}

const rig::Pose kAhead{{0.0, 1.6, 0.0}, glm::dquat(1.0, 0.0, 0.0, 0.0)};

TEST(SimxrGaze, ScriptReadsEveryKeyAndKeepsDefaultsOtherwise) {
    const Script plain = parse_ok("");
    EXPECT_TRUE(plain.gaze.tracker);
    EXPECT_TRUE(plain.gaze.fixations.empty());
    EXPECT_EQ(plain.gaze.saccades_per_s, 3.0);
    const Script script = parse_ok(R"(
[gaze]
tracker = false
saccades_per_s = 4
spread_deg = 8
seed = 7
saccade_s = 0.05
blink_every_s = 0
blink_s = 0.1

[[fixation]]
t = 0.5
duration = 0.4
target = [1.0, 1.6, -4.0]

[[fixation]]
t = 1.0
yaw_pitch_deg = [10, -5]

[[blink]]
t = 2
duration = 0.2
)");
    EXPECT_FALSE(script.gaze.tracker);
    EXPECT_EQ(script.gaze.saccades_per_s, 4.0);
    EXPECT_EQ(script.gaze.spread_deg, 8.0);
    EXPECT_EQ(script.gaze.seed, 7u);
    EXPECT_EQ(script.gaze.saccade_s, 0.05);
    EXPECT_EQ(script.gaze.blink_every_s, 0.0);
    ASSERT_EQ(script.gaze.fixations.size(), 2u);
    EXPECT_EQ(*script.gaze.fixations[0].target, glm::dvec3(1.0, 1.6, -4.0));
    EXPECT_EQ(script.gaze.fixations[0].duration, 0.4);
    EXPECT_FALSE(script.gaze.fixations[1].target);
    EXPECT_EQ(script.gaze.fixations[1].yaw_pitch_deg, glm::dvec2(10.0, -5.0));
    ASSERT_EQ(script.gaze.blinks.size(), 1u);
    EXPECT_EQ(script.gaze.blinks[0].duration, 0.2);
}

TEST(SimxrGaze, WrongValuesAreReportedWithTheirKeysAllAtOnce) {
    auto script = parse_script(R"(
[gaze]
saccades_per_s = 0
blink_s = 5
colour = 1

[[fixation]]
t = 1
target = [0, 0, -1]
yaw_pitch_deg = [1, 2]

[[fixation]]
t = 0.5
yaw_pitch_deg = [1, 2, 3]
)",
                               kSource);
    ASSERT_FALSE(script.ok());
    const std::string message = script.error().message;
    for (const char* expected : {"gaze.saccades_per_s", "must lie in (0, 20]", "gaze.blink_s",
                                 "gaze.colour", "give target or this, not both",
                                 "ascending order of t", "must be an array of 2 numbers"}) {
        EXPECT_NE(message.find(expected), std::string::npos) << expected << " in:\n" << message;
    }
}

// Straight ahead is -z; yaw turns left (-x), pitch up (+y), as the head's keyframes do.
TEST(SimxrGaze, AnglesInTheViewFollowTheHeadsConventions) {
    EXPECT_LT(glm::length(view_direction({0.0, 0.0}) - glm::dvec3(0.0, 0.0, -1.0)), 1e-12);
    EXPECT_LT(glm::length(view_direction({90.0, 0.0}) - glm::dvec3(-1.0, 0.0, 0.0)), 1e-12);
    EXPECT_LT(glm::length(view_direction({0.0, 90.0}) - glm::dvec3(0.0, 1.0, 0.0)), 1e-12);
    // 30 degrees left and 20 up: (-sin 30 cos 20, sin 20, -cos 30 cos 20).
    const glm::dvec3 d = view_direction({30.0, 20.0});
    EXPECT_NEAR(d.x, -0.5 * 0.9396926207859084, 1e-12);
    EXPECT_NEAR(d.y, 0.3420201433256687, 1e-12);
    EXPECT_NEAR(d.z, -0.8660254037844386 * 0.9396926207859084, 1e-12);
}

// A beam 4 m ahead and 1 m to the right: the eyes stay on it while the head turns 20 degrees to
// the left, so in the head's view the point moves 20 degrees further right.
TEST(SimxrGaze, AFixationOnAPointFollowsItAsTheHeadTurns) {
    GazeScript gaze;
    gaze.blink_every_s = 0.0;
    gaze.fixations.push_back({0.0, 10.0, glm::dvec3(1.0, 1.6, -4.0), {}});
    const GazeSample ahead = gaze_at(gaze, 1.0, kAhead);
    ASSERT_TRUE(ahead.valid);
    EXPECT_LT(glm::length(ahead.direction - glm::normalize(glm::dvec3(1.0, 0.0, -4.0))), 1e-12);
    const double right_deg = glm::degrees(std::atan2(1.0, 4.0));  // 14.04 degrees
    const rig::Pose turned{kAhead.position,
                           glm::angleAxis(glm::radians(20.0), glm::dvec3(0.0, 1.0, 0.0))};
    const GazeSample after = gaze_at(gaze, 2.0, turned);
    // In the turned head's view: yaw -(14.04 + 20) degrees (right is negative), no pitch.
    EXPECT_LT(degrees_between(after.direction, view_direction({-(right_deg + 20.0), 0.0})), 1e-9);
}

// Two fixations in the view 20 degrees apart: the eyes are on the first, then reach the second
// within saccade_s, halfway (10 degrees from each) at half of it.
TEST(SimxrGaze, ASaccadeCarriesTheEyesFromOneFixationToTheNext) {
    GazeScript gaze;
    gaze.blink_every_s = 0.0;
    gaze.saccade_s = 0.04;
    gaze.fixations.push_back({0.0, 0.5, std::nullopt, {-10.0, 0.0}});
    gaze.fixations.push_back({0.5, 0.5, std::nullopt, {10.0, 0.0}});
    const glm::dvec3 first = view_direction({-10.0, 0.0});
    const glm::dvec3 second = view_direction({10.0, 0.0});
    EXPECT_LT(degrees_between(gaze_at(gaze, 0.3, kAhead).direction, first), 1e-9);
    EXPECT_LT(degrees_between(gaze_at(gaze, 0.5, kAhead).direction, first), 1e-9);
    const glm::dvec3 halfway = gaze_at(gaze, 0.52, kAhead).direction;
    EXPECT_NEAR(degrees_between(halfway, first), 10.0, 1e-6);
    EXPECT_NEAR(degrees_between(halfway, second), 10.0, 1e-6);
    EXPECT_LT(degrees_between(gaze_at(gaze, 0.54, kAhead).direction, second), 1e-9);
    // After the last fixation's end the eyes stay where it left them.
    EXPECT_LT(degrees_between(gaze_at(gaze, 5.0, kAhead).direction, second), 1e-9);
}

// Blinks, scripted and periodic, are the only invalid samples.
TEST(SimxrGaze, BlinksAreInvalidSamples) {
    GazeScript gaze;
    gaze.blink_every_s = 4.0;
    gaze.blink_s = 0.15;
    gaze.blinks.push_back({1.0, 0.2});
    EXPECT_TRUE(gaze_at(gaze, 0.0, kAhead).valid);
    EXPECT_FALSE(gaze_at(gaze, 1.1, kAhead).valid);  // scripted
    EXPECT_TRUE(gaze_at(gaze, 1.2, kAhead).valid);
    EXPECT_FALSE(gaze_at(gaze, 2.05, kAhead).valid);  // periodic: 2.0, 6.0, ...
    EXPECT_TRUE(gaze_at(gaze, 2.15, kAhead).valid);
    EXPECT_FALSE(gaze_at(gaze, 6.1, kAhead).valid);
    // Over a minute at 90 Hz: 15 periodic blinks (at 2, 6, ..., 58 s), each starting on a frame
    // and covering ceil(0.15 * 90) = 14 frames, and the scripted 0.2 s, 18 frames: 228, give or
    // take a frame where a blink's end falls on a frame's time.
    int invalid = 0;
    const int frames = 60 * 90;
    for (int f = 0; f < frames; ++f) invalid += gaze_at(gaze, f / 90.0, kAhead).valid ? 0 : 1;
    EXPECT_NEAR(invalid, 15 * 14 + 18, 2);
}

// The default looks about the view's centre: a new fixation every 1 / saccades_per_s seconds,
// each within spread_deg, most of them near the centre; the same seed gives the same gaze.
TEST(SimxrGaze, TheDefaultFixatesNearTheCentreAtItsRate) {
    GazeScript gaze;
    gaze.blink_every_s = 0.0;
    std::set<std::pair<long, long>> fixations;
    int within_half = 0;
    const int samples = 300;
    for (int k = 0; k < samples; ++k) {
        // Mid-fixation, past the saccade.
        const double t = (k + 0.5) / gaze.saccades_per_s;
        const glm::dvec3 d = gaze_at(gaze, t, kAhead).direction;
        const double eccentricity = degrees_between(d, {0.0, 0.0, -1.0});
        EXPECT_LE(eccentricity, gaze.spread_deg + 1e-9);
        if (eccentricity <= 0.5 * gaze.spread_deg) ++within_half;
        fixations.insert({std::lround(d.x * 1e6), std::lround(d.y * 1e6)});
        // Constant within the fixation.
        EXPECT_LT(degrees_between(gaze_at(gaze, t + 0.1, kAhead).direction, d), 1e-12);
    }
    EXPECT_EQ(static_cast<int>(fixations.size()), samples);
    // The model: (yaw, pitch) = spread u^2 (cos a, 0.6 sin a), u and a uniform. Its eccentricity
    // spread u^2 r(a), r(a) = sqrt(cos^2 a + 0.36 sin^2 a), is within half the spread for
    // u <= sqrt(1 / (2 r(a))): the share expected is that bound's mean over a (about 0.80),
    // integrated here on a fine grid of a. 300 fixations: a standard error of 0.023.
    double expected = 0.0;
    const int steps = 100000;
    for (int i = 0; i < steps; ++i) {
        const double a = 2.0 * 3.141592653589793 * (i + 0.5) / steps;
        const double r = std::sqrt(std::cos(a) * std::cos(a) + 0.36 * std::sin(a) * std::sin(a));
        expected += std::min(1.0, std::sqrt(1.0 / (2.0 * r))) / steps;
    }
    EXPECT_NEAR(within_half / static_cast<double>(samples), expected, 0.08);
    GazeScript same = gaze;
    EXPECT_EQ(gaze_at(same, 12.34, kAhead).direction, gaze_at(gaze, 12.34, kAhead).direction);
    same.seed = 2;
    EXPECT_NE(gaze_at(same, 12.34, kAhead).direction, gaze_at(gaze, 12.34, kAhead).direction);
}

}  // namespace
}  // namespace monoplane::simxr
