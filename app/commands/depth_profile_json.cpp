#include "app/commands/depth_profile_json.h"

#include <algorithm>
#include <cstdint>

#include "renderer/passes/shared/view_constants.h"
#include "scenes/depth_profile.h"

namespace monoplane::app {
namespace {

void write_array(JsonWriter& j, std::string_view key, const std::vector<double>& values) {
    j.begin_array(key);
    for (const double v : values) j.value({}, v);
    j.end_array();
}

}  // namespace

void write_depth_profile_json(JsonWriter& j, std::string_view key, const DepthProfileInputs& in,
                              const std::vector<float>& left_linear_depth) {
    scenes::DepthProfileView view;
    view.eye = scenes::eye_pose(in.head, glm::dvec3(-0.5 * in.ipd, 0.0, 0.0));
    view.tangents = in.left;
    view.near = in.near;
    view.far = in.far;
    const scenes::PrimitiveDepthProfile primitives =
        scenes::primitive_depth_profile(*in.scene, view, in.mono_planes);
    const std::vector<double> pixels =
        scenes::pixel_fraction_nearer(left_linear_depth, in.mono_planes);
    // The sky is cleared to MONOPLANE_SKY_LINEAR_DEPTH; half of it is the shaders' test too.
    constexpr float kSkyFrom = static_cast<float>(0.5 * MONOPLANE_SKY_LINEAR_DEPTH);
    const auto sky = std::count_if(left_linear_depth.begin(), left_linear_depth.end(),
                                   [](float d) { return d >= kSkyFrom; });

    j.begin_object(key);
    write_array(j, "mono_planes", in.mono_planes);
    write_array(j, "primitives_nearer", primitives.fraction_nearer);
    write_array(j, "pixels_nearer", pixels);
    j.value("triangles_in_view", static_cast<std::uint64_t>(primitives.triangles_in_view));
    j.value("pixels", static_cast<std::uint64_t>(left_linear_depth.size()));
    j.value("sky_fraction",
            left_linear_depth.empty()
                ? 0.0
                : static_cast<double>(sky) / static_cast<double>(left_linear_depth.size()));
    j.end_object();
}

}  // namespace monoplane::app
