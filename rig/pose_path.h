// Scripted head motion for renders and benchmarks: named paths of keyframes relative to a
// starting pose, so the same motion applies at every scene's viewpoint. TAA (Karis 2014) is only
// tested by motion: a static head hides ghosting and a history that fails to follow.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "rig/pose.h"

namespace monoplane::rig {

// A pose at time t relative to the path's start: an offset in the starting head frame (metres,
// +x right, +y up, -z forward) and a turn (yaw left, pitch up, degrees).
struct PathKeyframe {
    double t = 0.0;
    glm::dvec3 offset{0.0};
    double yaw_deg = 0.0;
    double pitch_deg = 0.0;
};

struct PosePath {
    std::string name;
    std::vector<PathKeyframe> keyframes;  // ascending t; after the last the path repeats
};

// "static" (no motion), "sway" (a seated participant's slow side-to-side sway, 4 cm and 2
// degrees of yaw over 2 s), "turn" (yaw 30 degrees/s back and forth), "walk" (0.5 m/s forward).
std::optional<PosePath> builtin_pose_path(const std::string& name);
std::vector<std::string> builtin_pose_path_names();

// The head pose t seconds along the path from `start`: position linear and orientation slerped
// between keyframes, the path's duration wrapping around.
Pose pose_along(const PosePath& path, const Pose& start, double t);

}  // namespace monoplane::rig
