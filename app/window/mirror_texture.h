// The mirror of the participant's view: an image the app's frame commands blit into (scaled,
// aspect kept) and the window samples as an ImGui image.
#pragma once

#include "renderer/vk/context.h"
#include "renderer/vk/memory.h"

namespace monoplane::window {

class MirrorTexture {
  public:
    // `set_layout` is Dear ImGui's texture set layout (see imgui_backend_access.h); the set is
    // allocated from `pool`, which must allow freeing sets. Leaves the image cleared to dark grey,
    // ready to be sampled.
    MirrorTexture(const vk_core::Context& ctx, vk::Extent2D extent, vk::DescriptorPool pool,
                  vk::DescriptorSetLayout set_layout);

    vk::Extent2D extent() const { return extent_; }
    vk::DescriptorSet descriptor_set() const { return *set_; }

    // Records: `source` (in `source_layout`, TRANSFER_SRC usage, a format that supports linear
    // blits) scaled into the mirror with its aspect kept, letterboxed in black; `source` is left
    // in `source_layout` and the mirror ready to be sampled. Barriers included.
    void record_copy(const vk::raii::CommandBuffer& cmd, vk::Image source,
                     vk::ImageLayout source_layout, vk::Extent2D source_extent) const;

  private:
    vk::Extent2D extent_;
    vk::raii::Image image_{nullptr};
    vk_core::DeviceMemory memory_{nullptr};
    vk::raii::ImageView view_{nullptr};
    vk::raii::DescriptorSet set_{nullptr};
};

// The rectangle (offset, size) inside `outer` that shows `inner` with its aspect kept, centred.
struct FitRect {
    float x = 0, y = 0, width = 0, height = 0;
};
FitRect fit_aspect(float outer_width, float outer_height, float inner_width, float inner_height);

}  // namespace monoplane::window
