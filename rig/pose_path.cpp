#include "rig/pose_path.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/quaternion.hpp>

namespace monoplane::rig {
namespace {

glm::dquat turn_of(const PathKeyframe& keyframe) {
    return orientation_from_yaw_pitch(glm::radians(keyframe.yaw_deg),
                                      glm::radians(keyframe.pitch_deg));
}

}  // namespace

std::vector<std::string> builtin_pose_path_names() {
    return {"static", "sway", "turn", "walk"};
}

std::optional<PosePath> builtin_pose_path(const std::string& name) {
    if (name == "static") return PosePath{name, {{0.0, {}, 0.0, 0.0}}};
    if (name == "sway") {
        return PosePath{name,
                        {{0.0, {0.0, 0.0, 0.0}, 0.0, 0.0},
                         {0.5, {0.02, 0.0, 0.0}, -1.0, 0.0},
                         {1.0, {0.0, 0.0, 0.0}, 0.0, 0.0},
                         {1.5, {-0.02, 0.0, 0.0}, 1.0, 0.0},
                         {2.0, {0.0, 0.0, 0.0}, 0.0, 0.0}}};
    }
    if (name == "turn") {
        return PosePath{name,
                        {{0.0, {}, 0.0, 0.0},
                         {0.5, {}, 15.0, 0.0},
                         {1.5, {}, -15.0, 0.0},
                         {2.0, {}, 0.0, 0.0}}};
    }
    if (name == "walk") {
        return PosePath{name,
                        {{0.0, {0.0, 0.0, 0.0}, 0.0, 0.0}, {4.0, {0.0, 0.0, -2.0}, 0.0, 0.0}}};
    }
    return std::nullopt;
}

Pose pose_along(const PosePath& path, const Pose& start, double t) {
    const std::vector<PathKeyframe>& keys = path.keyframes;
    PathKeyframe at = keys.empty() ? PathKeyframe{} : keys.front();
    if (keys.size() > 1) {
        const double duration = keys.back().t - keys.front().t;
        const double local = keys.front().t + std::fmod(std::max(t, 0.0), duration);
        for (std::size_t i = 1; i < keys.size(); ++i) {
            if (local > keys[i].t) continue;
            const PathKeyframe& a = keys[i - 1];
            const PathKeyframe& b = keys[i];
            const double s = (local - a.t) / (b.t - a.t);
            const glm::dquat turn = glm::slerp(turn_of(a), turn_of(b), s);
            const glm::dvec3 offset = glm::mix(a.offset, b.offset, s);
            return {start.position + start.orientation * offset,
                    glm::normalize(start.orientation * turn)};
        }
    }
    return {start.position + start.orientation * at.offset,
            glm::normalize(start.orientation * turn_of(at))};
}

}  // namespace monoplane::rig
