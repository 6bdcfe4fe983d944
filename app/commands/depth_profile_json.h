// The "depth_profile" object of `render --json --depth-profile` (docs/scenes.md): per mono-plane
// distance m, the fraction of the triangles in the left eye's view and of the left eye's pixels
// nearer than m, so readers see what a scene offers hybrid rendering.
#pragma once

#include <string_view>
#include <vector>

#include "common/json_writer.h"
#include "rig/pose.h"
#include "rig/tangents.h"
#include "scenes/scene.h"

namespace monoplane::app {

// The ten mono-plane distances of protocols/fink2019.toml (papers/000 Sect. 6), in metres. A
// constant rather than a parse of the file, so that `render` does not depend on the working
// directory; keep it in step with the protocol.
inline const std::vector<double> kDepthProfileMonoPlanes = {1.6,  3.0,  5.0,  8.0,  12.0,
                                                            16.0, 20.0, 25.0, 31.0, 39.5};

struct DepthProfileInputs {
    const scenes::Scene* scene = nullptr;
    rig::Pose head;      // the viewpoint's head pose
    double ipd = 0.064;  // the left eye sits at (-ipd / 2, 0, 0) in the head frame
    rig::Tangents left;  // the left eye's frustum (the HMD profile's)
    double near = 0.1;   // the eyes' clip range
    double far = 1000.0;
    std::vector<double> mono_planes = kDepthProfileMonoPlanes;
};

// Writes, under key (empty: as an array element or the document), the object
// {"mono_planes":[...], "primitives_nearer":[...], "pixels_nearer":[...], "triangles_in_view": N,
// "sky_fraction": f}. left_linear_depth is the left eye's linear depth read back from the
// renderer (metres in front of the eye plane, MONOPLANE_SKY_LINEAR_DEPTH for the sky), one value
// per pixel.
void write_depth_profile_json(JsonWriter& j, std::string_view key, const DepthProfileInputs& in,
                              const std::vector<float>& left_linear_depth);

}  // namespace monoplane::app
