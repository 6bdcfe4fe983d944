// The script's values over time: head pose keyframes and button presses.
#include <cmath>

#include <glm/ext/quaternion_trigonometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include "app/headset/simxr/script.h"

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

}  // namespace

rig::Pose head_pose_at(const Script& script, double t) {
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

bool input_pressed_at(const Script& script, std::string_view component_path, std::int64_t t_ns) {
    for (const InputPress& press : script.inputs) {
        if (press.path != component_path) continue;
        const std::int64_t start = to_ns(press.t);
        if (t_ns >= start && t_ns < start + to_ns(press.duration)) return true;
    }
    return false;
}

}  // namespace monoplane::simxr
