// A gaze direction (a vector in the head's frame: -z ahead, +x right, +y up) as angles of visual
// angle in degrees, the way the fixation detector (gaze_summary.h) and the gaze export read it.
// The direction need not be of unit length: every angle is a ratio of its components.
#pragma once

#include <array>
#include <cmath>
#include <numbers>

namespace monoplane::study {

inline constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

// Horizontal angle: to the right of straight ahead positive, -180 to 180.
inline double gaze_yaw_deg(const std::array<double, 3>& d) {
    return std::atan2(d[0], -d[2]) * kDegreesPerRadian;
}

// Vertical angle: above the horizontal plane of the head positive, -90 to 90.
inline double gaze_pitch_deg(const std::array<double, 3>& d) {
    return std::atan2(d[1], std::hypot(d[0], d[2])) * kDegreesPerRadian;
}

// The angle from the view axis (-z), 0 to 180: atan2 rather than acos, which loses precision
// near the axis where most gaze lies.
inline double gaze_eccentricity_deg(const std::array<double, 3>& d) {
    return std::atan2(std::hypot(d[0], d[1]), -d[2]) * kDegreesPerRadian;
}

}  // namespace monoplane::study
