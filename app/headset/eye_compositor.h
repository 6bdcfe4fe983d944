// Fills an eye's swapchain image for a frame: the renderer's tone-mapped eye (or the neutral
// screen between trials), then overlays — the small label of the alternative shown, the
// questionnaire — blitted at fixed directions of view, so they sit at the same place in both eyes
// (at infinite distance: no vergence cue to fight the scene's). Then, for the experimenter
// window, a copy of the finished image (the mirror). Transfer commands only: no pipeline, and the
// image is left as OpenXR wants it (COLOR_ATTACHMENT_OPTIMAL).
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "renderer/modes/view_setup.h"
#include "rig/tangents.h"
#include "renderer/vk/image.h"

namespace monoplane::headset {

// Where an overlay goes: its centre as a direction of view (tangents, +y up) and its height in
// tangent units; the width follows from the image's aspect.
struct OverlayPlacement {
    double tan_x = 0.0;
    double tan_y = 0.0;
    double tan_height = 0.05;
};

// The pixel rectangle [x0, x1) x [y0, y1) a placement covers in an eye of this frustum and size.
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};
PixelRect overlay_rect(const OverlayPlacement& placement, std::uint32_t image_width,
                       std::uint32_t image_height, const rig::Tangents& eye,
                       vk::Extent2D eye_extent);

class EyeCompositor {
  public:
    explicit EyeCompositor(const vk_core::Context& ctx);
    ~EyeCompositor();

    // Makes (once per distinct key) an overlay texture from an image; uploads and waits. A key set
    // again gets the new image: the upload waits for everything submitted to the queue before it,
    // so the frames that drew the old image are done when it goes (a countdown reuses one key).
    void set_overlay(const std::string& key, const modes::RgbaImage& image);
    bool has_overlay(const std::string& key) const;

    struct Overlay {
        std::string key;
        OverlayPlacement placement;
    };
    using MirrorRecorder = std::function<void(const vk::raii::CommandBuffer&, vk::Image,
                                              vk::ImageLayout, vk::Extent2D)>;

    // Records the eye into `target` (a swapchain image in COLOR_ATTACHMENT_OPTIMAL, left so).
    // source: the renderer's display image, as its frame left it (TRANSFER_SRC_OPTIMAL, visible
    // to transfers), or null for the neutral screen. mirror: called with the finished
    // image in TRANSFER_SRC_OPTIMAL (the left eye's, for the experimenter window).
    void record_eye(const vk::raii::CommandBuffer& cmd, vk::Image target, vk::Extent2D extent,
                    const rig::Tangents& tangents, const vk_core::Image* source,
                    const std::vector<Overlay>& overlays, const MirrorRecorder& mirror) const;

    // The pixel rectangles record_eye covers with these overlays in an eye of this frustum and
    // size (the eye depth writer puts them at infinity).
    std::vector<PixelRect> overlay_rects(const std::vector<Overlay>& overlays,
                                         const rig::Tangents& tangents, vk::Extent2D extent) const;

    // The neutral screen's colour (linear; a dark grey that neither dazzles nor hides the label).
    static constexpr float kNeutralGrey = 0.04f;

  private:
    struct Texture;
    const vk_core::Context& ctx_;
    std::map<std::string, std::unique_ptr<Texture>> textures_;
};

}  // namespace monoplane::headset
