// ModeRenderer::eye_linear_depth_image: the layout is the one the last frame's render graph left
// the image in (every frame exports the eyes' linear depth shader-readable for a headset's depth
// layer: renderer/plan/frame_plan.cpp, add_exports).
#include "renderer/modes/mode_renderer_internals.h"

namespace monoplane::modes {

EyeDepthImage ModeRenderer::eye_linear_depth_image(Eye eye) const {
    const auto& view = *eyes_[static_cast<int>(eye)];
    return {&view.linear_depth, executor_.layout_of(view.linear_depth.range())};
}

}  // namespace monoplane::modes
