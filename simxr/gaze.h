// simxr's eye gaze (XR_EXT_eye_gaze_interaction; docs/simxr.md, "Eye gaze"): where the simulated
// eyes look over script time, as an eye tracker reports it. Fixations rest on a point in LOCAL
// space (the eyes follow it as the head moves) or on a direction in the head's view; the eyes
// move between fixations in saccades of a fixed duration; during a blink no sample is valid.
// Without scripted fixations a seeded default looks about the view's centre, where a study's
// scene lies, at a typical rate of fixations, and blinks at a typical rate.
//
// When may this be called: any time; pure.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "rig/pose.h"

namespace monoplane::simxr {

// The eyes rest from t for duration seconds on `target` (LOCAL space), or, without one, on the
// direction yaw_pitch_deg in the head's view (yaw about +y, positive left; pitch about +x,
// positive up; (0, 0) straight ahead).
struct GazeFixation {
    double t = 0.0;
    double duration = 0.3;
    std::optional<glm::dvec3> target;
    glm::dvec2 yaw_pitch_deg{0.0};
};

// No valid sample from t for duration seconds.
struct GazeBlink {
    double t = 0.0;
    double duration = 0.15;
};

struct GazeScript {
    // The system tracks the eyes (XrSystemEyeGazeInteractionPropertiesEXT): false simulates a
    // headset without an eye tracker.
    bool tracker = true;
    // The default's fixations: one every 1 / saccades_per_s seconds (about 3 a second when
    // viewing a scene), centre-biased within spread_deg of the view axis.
    double saccades_per_s = 3.0;
    double spread_deg = 12.0;
    std::uint64_t seed = 1;
    // How long the eyes take from one fixation to the next (a saccade of 10-15 degrees).
    double saccade_s = 0.04;
    // Blinks beside the scripted ones: one of blink_s every blink_every_s seconds (0: none),
    // the first at half the period.
    double blink_every_s = 4.0;
    double blink_s = 0.15;
    std::vector<GazeFixation> fixations;  // ascending t; empty: the default
    std::vector<GazeBlink> blinks;
};

// One gaze sample: the gaze direction in the head's space (a unit vector; -z is straight ahead),
// from the midpoint between the eyes; valid false during a blink (the runtime then reports no
// tracked pose).
struct GazeSample {
    bool valid = false;
    glm::dvec3 direction{0.0, 0.0, -1.0};
};

// The gaze at script time t (seconds) of a head at `head` (LOCAL space, as head_pose_at gives).
GazeSample gaze_at(const GazeScript& gaze, double t, const rig::Pose& head);

// The direction in the head's view of (yaw, pitch) degrees, as GazeFixation reads them.
glm::dvec3 view_direction(const glm::dvec2& yaw_pitch_deg);

}  // namespace monoplane::simxr
