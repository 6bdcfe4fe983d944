// The script's values over time: head pose keyframes and button presses.
#include <cmath>

#include <glm/ext/quaternion_trigonometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include "simxr/script.h"

namespace monoplane::simxr {
namespace {

glm::dquat orientation_of(const glm::dvec3& yaw_pitch_roll_deg) {
    const glm::dvec3 rad = glm::radians(yaw_pitch_roll_deg);
    const glm::dquat yaw = glm::angleAxis(rad.x, glm::dvec3(0.0, 1.0, 0.0));
    const glm::dquat pitch = glm::angleAxis(rad.y, glm::dvec3(1.0, 0.0, 0.0));
    const glm::dquat roll = glm::angleAxis(rad.z, glm::dvec3(0.0, 0.0, 1.0));
    return yaw * pitch * roll;
}

rig::Pose pose_of(const PoseKeyframe& keyframe) {
    return {keyframe.position, orientation_of(keyframe.yaw_pitch_roll_deg)};
}

std::int64_t to_ns(double seconds) {
    return std::llround(seconds * 1e9);
}

rig::Pose keyframe_pose_at(const Script& script, double t) {
    if (script.poses.empty()) return pose_of(PoseKeyframe{});
    if (t <= script.poses.front().t) return pose_of(script.poses.front());
    for (std::size_t i = 1; i < script.poses.size(); ++i) {
        const PoseKeyframe& a = script.poses[i - 1];
        const PoseKeyframe& b = script.poses[i];
        if (t >= b.t) continue;
        const double s = (t - a.t) / (b.t - a.t);
        // glm::slerp takes the shorter arc, so a keyframe pair never spins the long way round.
        return {glm::mix(a.position, b.position, s),
                glm::normalize(glm::slerp(pose_of(a).orientation, pose_of(b).orientation, s))};
    }
    return pose_of(script.poses.back());
}

double wave(double amplitude, double hz, double phase, double t) {
    return amplitude * std::sin(2.0 * glm::pi<double>() * hz * t + phase);
}

// HeadMotion::kSeated at time t, in the head's own frame. The frequencies are irrational
// multiples of the slowest (0.11 Hz, a 9 s look around): with rational ones the motion would
// repeat (every 100 s for multiples of 0.01 Hz) and a long session would see old views again.
rig::Pose seated_motion(double t) {
    constexpr double f = 0.11;
    const double golden = (1.0 + std::sqrt(5.0)) / 2.0;
    const glm::dvec3 yaw_pitch_roll_deg{
        wave(6.0, f, 0.0, t) + wave(3.0, 2.0 * golden * f, 1.3, t),
        wave(3.0, std::sqrt(3.0) * f, 0.4, t) + wave(1.5, std::sqrt(23.0) * f, 0.0, t),
        wave(1.0, std::sqrt(4.4) * f, 2.0, t)};
    const glm::dvec3 offset{wave(0.02, std::sqrt(1.4) * f, 0.7, t),
                            wave(0.01, std::sqrt(7.0) * f, 0.0, t),
                            wave(0.015, std::sqrt(2.4) * f, 1.1, t)};
    return {offset, orientation_of(yaw_pitch_roll_deg)};
}

}  // namespace

rig::Pose head_pose_at(const Script& script, double t) {
    const rig::Pose keyed = keyframe_pose_at(script, t);
    if (script.head_motion == HeadMotion::kStill) return keyed;
    const rig::Pose motion = seated_motion(t);
    return {keyed.position + keyed.orientation * motion.position,
            glm::normalize(keyed.orientation * motion.orientation)};
}

bool input_pressed_at(const Script& script, std::string_view component_path, std::int64_t t_ns) {
    for (const InputPress& press : script.inputs) {
        if (press.path != component_path) continue;
        const std::int64_t start = to_ns(press.t);
        if (t_ns >= start && t_ns < start + to_ns(press.duration)) return true;
    }
    return false;
}

}  // namespace monoplane::simxr
