#include "app/commands/ao_consistency.h"

#include <algorithm>
#include <cmath>

#include "app/png.h"

namespace monoplane::app {
namespace {

quality::StereoAoView ao_view(const modes::ModeRenderer& renderer, modes::Eye eye,
                              vk::Extent2D extent) {
    quality::StereoAoView view;
    view.width = extent.width;
    view.height = extent.height;
    view.view_proj = renderer.eye_geometry(eye).view_proj;
    view.camera_position = renderer.eye_geometry(eye).position;
    view.linear_depth = renderer.eye_linear_depth(eye);
    view.ao = renderer.eye_ao(eye);
    return view;
}

modes::RgbaImage grey_image(const std::vector<float>& values, std::uint32_t width,
                            std::uint32_t height) {
    modes::RgbaImage image{width, height, std::vector<std::uint8_t>(values.size() * 4, 255)};
    for (std::size_t i = 0; i < values.size(); ++i) {
        const auto grey =
            static_cast<std::uint8_t>(std::lround(std::clamp(values[i], 0.0f, 1.0f) * 255.0f));
        image.pixels[i * 4] = image.pixels[i * 4 + 1] = image.pixels[i * 4 + 2] = grey;
    }
    return image;
}

}  // namespace

quality::InconsistencyMap ao_inconsistency(const modes::ModeRenderer& renderer,
                                           const modes::FrameInputs& inputs) {
    const modes::RgbaImage& left = renderer.eye_image(modes::Eye::kLeft);
    const vk::Extent2D extent(left.width, left.height);
    const rig::Pose& head = inputs.views.head;
    const quality::StereoHead stereo_head{
        head.position, glm::normalize(head.orientation * glm::dvec3(0.0, 0.0, -1.0))};
    return quality::stereo_inconsistency(ao_view(renderer, modes::Eye::kLeft, extent),
                                         ao_view(renderer, modes::Eye::kRight, extent), stereo_head)
        .value_or_throw();
}

void write_ao_pictures(const modes::ModeRenderer& renderer, const quality::InconsistencyMap& map,
                       const std::filesystem::path& out) {
    for (modes::Eye eye : {modes::Eye::kLeft, modes::Eye::kRight}) {
        const modes::RgbaImage& image = renderer.eye_image(eye);
        write_png(out / (std::string("ao_") + modes::eye_name(eye) + ".png"),
                  grey_image(renderer.eye_ao(eye), image.width, image.height))
            .value_or_throw();
    }
    write_png(out / "ao_inconsistency.png",
              modes::RgbaImage{map.width, map.height, quality::inconsistency_heat_map_rgba(map)})
        .value_or_throw();
}

}  // namespace monoplane::app
