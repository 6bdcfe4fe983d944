#include "simxr/gaze.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

namespace monoplane::simxr {
namespace {

// A uniform number in [0, 1) from (seed, index, stream): splitmix64, so that fixation k of a
// seed is the same however the timeline is sampled.
double uniform(std::uint64_t seed, std::uint64_t index, std::uint64_t stream) {
    std::uint64_t z = seed * 0x9E3779B97F4A7C15ull + index * 0xBF58476D1CE4E5B9ull + stream;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
}

// The default's k-th fixation: eccentricity spread * u^2 (most fixations near the centre, as
// on a scene in front of the viewer), in a uniformly random direction, flattened vertically
// (scenes extend more to the sides than up and down).
glm::dvec2 default_fixation(const GazeScript& gaze, std::uint64_t k) {
    const double u = uniform(gaze.seed, k, 1);
    const double eccentricity = gaze.spread_deg * u * u;
    const double angle = 2.0 * glm::pi<double>() * uniform(gaze.seed, k, 2);
    return {eccentricity * std::cos(angle), 0.6 * eccentricity * std::sin(angle)};
}

// Where a fixation puts the eyes in the head's view at this head pose.
glm::dvec3 fixation_direction(const GazeFixation& fixation, const rig::Pose& head) {
    if (!fixation.target) return view_direction(fixation.yaw_pitch_deg);
    const glm::dvec3 to_target = *fixation.target - head.position;
    if (glm::length(to_target) < 1e-9) return {0.0, 0.0, -1.0};
    return glm::normalize(glm::inverse(head.orientation) * to_target);
}

// From `from` to `to` along the great circle, s in [0, 1].
glm::dvec3 saccade(const glm::dvec3& from, const glm::dvec3& to, double s) {
    const glm::dvec3 axis = glm::cross(from, to);
    const double sine = glm::length(axis);
    if (sine < 1e-12) return to;  // the same direction (a saccade never reverses the gaze)
    const double angle = std::atan2(sine, glm::dot(from, to));
    return glm::normalize(glm::angleAxis(angle * s, axis / sine) * from);
}

bool blinking(const GazeScript& gaze, double t) {
    for (const GazeBlink& blink : gaze.blinks) {
        if (t >= blink.t && t < blink.t + blink.duration) return true;
    }
    if (gaze.blink_every_s <= 0.0 || t < 0.0) return false;
    const double phase = std::fmod(t + 0.5 * gaze.blink_every_s, gaze.blink_every_s);
    return t >= 0.5 * gaze.blink_every_s && phase < gaze.blink_s;
}

glm::dvec3 default_direction(const GazeScript& gaze, double t) {
    const double period = 1.0 / gaze.saccades_per_s;
    const auto k = static_cast<std::uint64_t>(std::max(0.0, std::floor(t / period)));
    const glm::dvec3 now = view_direction(default_fixation(gaze, k));
    const double into = t - static_cast<double>(k) * period;
    if (k == 0 || into >= gaze.saccade_s) return now;
    return saccade(view_direction(default_fixation(gaze, k - 1)), now, into / gaze.saccade_s);
}

glm::dvec3 scripted_direction(const GazeScript& gaze, double t, const rig::Pose& head) {
    // The last fixation begun by t; before the first, the first.
    std::size_t i = 0;
    while (i + 1 < gaze.fixations.size() && gaze.fixations[i + 1].t <= t) ++i;
    const GazeFixation& fixation = gaze.fixations[i];
    const glm::dvec3 now = fixation_direction(fixation, head);
    const double into = t - fixation.t;
    if (i == 0 || into < 0.0 || into >= gaze.saccade_s) return now;
    return saccade(fixation_direction(gaze.fixations[i - 1], head), now, into / gaze.saccade_s);
}

}  // namespace

glm::dvec3 view_direction(const glm::dvec2& yaw_pitch_deg) {
    const glm::dvec2 rad = glm::radians(yaw_pitch_deg);
    // Ry(yaw) * Rx(pitch) applied to -z.
    return {-std::sin(rad.x) * std::cos(rad.y), std::sin(rad.y),
            -std::cos(rad.x) * std::cos(rad.y)};
}

GazeSample gaze_at(const GazeScript& gaze, double t, const rig::Pose& head) {
    GazeSample sample;
    sample.valid = !blinking(gaze, t);
    sample.direction =
        gaze.fixations.empty() ? default_direction(gaze, t) : scripted_direction(gaze, t, head);
    return sample;
}

}  // namespace monoplane::simxr
