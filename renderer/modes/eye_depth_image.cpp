// ModeRenderer::eye_linear_depth_image, apart from mode_renderer.cpp and frame_recording.cpp:
// which layout the last frame left an eye's linear depth in follows from its plan, by the rules
// the executor applies (frame_recording.cpp: record_pass, record_readback).
#include <algorithm>
#include <string>

#include "renderer/modes/mode_renderer_internals.h"

namespace monoplane::modes {

EyeDepthImage ModeRenderer::eye_linear_depth_image(Eye eye) const {
    const int e = static_cast<int>(eye);
    const std::string name = std::string(e == 0 ? "left" : "right") + ".linear_depth";
    const auto names = [&name](const std::vector<std::string>& list) {
        return std::find(list.begin(), list.end(), name) != list.end();
    };
    // A pass that writes it (forward, composite) leaves it a colour attachment; the first later
    // pass that reads it (SSAO, TAA, read-back) makes it shader-readable first; the read-back
    // then copies it out of TRANSFER_SRC. Before the first frame there is no plan: undefined.
    vk::ImageLayout layout = vk::ImageLayout::eUndefined;
    for (const PlannedPass* pass : last_plan_.executed()) {
        if (names(pass->reads)) {
            if (layout == vk::ImageLayout::eColorAttachmentOptimal) {
                layout = vk::ImageLayout::eShaderReadOnlyOptimal;
            }
            if (pass->kind == PassKind::kReadback) layout = vk::ImageLayout::eTransferSrcOptimal;
        }
        if (names(pass->writes)) layout = vk::ImageLayout::eColorAttachmentOptimal;
    }
    return {&eyes_[e]->linear_depth, layout};
}

}  // namespace monoplane::modes
