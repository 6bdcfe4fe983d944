// How a scene's geometry spreads over the mono-plane distances seen from one eye (docs/scenes.md,
// papers/000 Sect. 6: "geometry which is uniformly distributed across space"): for
// each distance m, the fraction of the triangles in view, and of the pixels, nearer than m.
// Pure CPU math on the scene model: no Vulkan, no I/O.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/ext/vector_double3.hpp>

#include "rig/pose.h"
#include "rig/tangents.h"
#include "scenes/scene.h"

namespace monoplane::scenes {

// One eye's view: its pose (world frame, looking down its local -z) and its frustum as tangents
// (rig/tangents.h; tan_left < tan_right, tan_down < tan_up), clipped at near and far (metres
// along the view axis, in front of the eye).
struct DepthProfileView {
    rig::Pose eye;
    rig::Tangents tangents;
    double near = 0.1;
    double far = 1000.0;
};

// The pose of an eye displaced by offset_in_head (head frame; the left eye sits at
// (-ipd / 2, 0, 0)) from the head pose: same orientation, shifted position.
rig::Pose eye_pose(const rig::Pose& head, const glm::dvec3& offset_in_head);

struct PrimitiveDepthProfile {
    // Triangles whose centroid lies inside the view's frustum (near <= depth <= far and within
    // the four tangents), each counted once however large it is on screen.
    std::size_t triangles_in_view = 0;
    // Per distance m (in the order given): of those triangles, the fraction whose centroid depth
    // along the eye's view axis is below m. NaN for every m when no triangle is in view.
    std::vector<double> fraction_nearer;
};

// Every triangle of the scene (all chunks), its centroid taken in the eye's frame.
PrimitiveDepthProfile primitive_depth_profile(const Scene& scene, const DepthProfileView& view,
                                              std::span<const double> distances);

// Per distance m: the fraction of all pixels whose linear depth (metres in front of the eye's
// plane) is below m. The sky, stored as a huge depth, is beyond every m and counts in the
// denominator. NaN for every m when there are no pixels.
std::vector<double> pixel_fraction_nearer(std::span<const float> linear_depth,
                                          std::span<const double> distances);

}  // namespace monoplane::scenes
