// simxr's script (docs/simxr.md): which headset it simulates, the display rate, where to dump
// frames, when the session ends, and the head poses and button presses over time. A TOML file
// named by the SIMXR_SCRIPT environment variable; without it every key keeps its default.
//
// Script time is in seconds from frame 0's predicted display time (frame n = the n-th xrWaitFrame
// of the session, counting from 0).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "common/result.h"
#include "hmd/profile.h"
#include "rig/pose.h"
#include "simxr/gaze.h"

namespace monoplane::simxr {

// A head pose in LOCAL space at time t. Between keyframes position is interpolated linearly and
// orientation by slerp; before the first and after the last the nearest keyframe is held.
struct PoseKeyframe {
    double t = 0.0;
    glm::dvec3 position{0.0, 1.6, 0.0};
    // Yaw about +y (positive turns left), pitch about +x (positive looks up), roll about +z
    // (positive tilts the head to the left), applied in that order: R = Ry * Rx * Rz.
    glm::dvec3 yaw_pitch_roll_deg{0.0};
};

// Motion on top of the keyframes: none, or a seated person's small continuous movement (the head
// turns up to 9 degrees either way, at up to 10.9 degrees a second, nods up to 4.5, tilts 1,
// and moves up to 3 cm): sums of sines of incommensurate periods, so no two frames of a
// session see the same view. monoplane's simulated headset uses "seated", so every session test
// turns the head as participants do.
enum class HeadMotion { kStill, kSeated };

// A component held down during [t, t + duration).
struct InputPress {
    double t = 0.0;
    std::string path;       // "/user/hand/right/input/select/click"
    double duration = 0.0;  // seconds; 0 in the file means "one frame period" (resolved on parse)
};

struct Script {
    std::string source = "(defaults)";  // file path, for messages
    std::string hmd_name = "vive";      // as written (resolved path for files)
    hmd::HmdProfile hmd;
    double display_rate_hz = 90.0;
    // > 0: every missed_slot_every-th frame comes one display slot late, as when an application
    // misses its slot (the runtime repeats the previous frame); 0: never.
    std::int64_t missed_slot_every = 0;
    std::string physical_device;  // part of a Vulkan device name; "" = the first listed
    std::string interaction_profile = "/interaction_profiles/khr/simple_controller";
    std::filesystem::path dump_dir;  // empty: no dumps
    std::int64_t dump_every = 1;
    double exit_after_s = 0.0;       // > 0: runtime-initiated STOPPING at that time
    double lose_session_at_s = 0.0;  // > 0: LOSS_PENDING at that time
    // > 0: the instance is lost at that time, as when a runtime's service dies: an
    // XrEventDataInstanceLossPending is queued and every later call but the destroy functions
    // returns XR_ERROR_INSTANCE_LOST.
    double lose_instance_at_s = 0.0;
    std::vector<PoseKeyframe> poses;  // ascending t; empty: the default keyframe
    HeadMotion head_motion = HeadMotion::kStill;
    std::vector<InputPress> inputs;
    GazeScript gaze;  // [gaze], [[fixation]], [[blink]]

    std::int64_t frame_period_ns() const;
};

// Parses script text. source_path names the file in messages and is the folder relative paths
// (hmd, dump_dir) resolve against. Errors are "file:line:column: key 'k': ...", all at once.
Result<Script> parse_script(std::string_view toml_text, const std::filesystem::path& source_path);

// Reads and parses a script file.
Result<Script> load_script(const std::filesystem::path& path);

// The script SIMXR_SCRIPT names, or the defaults when it is unset or empty.
Result<Script> load_script_from_environment();

// The head pose in LOCAL space at script time t (seconds): the keyframes', then head_motion in
// that pose's frame.
rig::Pose head_pose_at(const Script& script, double t);

// Whether the component at this full path is held down at script time t_ns (nanoseconds; integer
// so that a frame exactly at t + duration is reliably outside the window).
bool input_pressed_at(const Script& script, std::string_view component_path, std::int64_t t_ns);

}  // namespace monoplane::simxr
