// One descriptor set with a pool of its own: what a pass hands a view for the resources it binds
// (the pass's make_* functions write it), so that sets live and die with the view that owns them
// and no renderer keeps a shared pool sized by hand.
#pragma once

#include <span>

#include "renderer/vk/context.h"

namespace monoplane::vk_core {

class DescriptorSet {
  public:
    DescriptorSet() = default;
    // A set of `layout` from a pool holding exactly `sizes`.
    DescriptorSet(const Context& ctx, vk::DescriptorSetLayout layout,
                  std::span<const vk::DescriptorPoolSize> sizes);

    vk::DescriptorSet operator*() const { return *set_; }

  private:
    vk::raii::DescriptorPool pool_{nullptr};
    vk::raii::DescriptorSet set_{nullptr};  // after its pool: destroyed before it
};

// Image descriptors of one type, written into `set` at bindings 0, 1, ... in order.
void write_sampled_images(const Context& ctx, vk::DescriptorSet set,
                          std::span<const vk::DescriptorImageInfo> images,
                          std::uint32_t first_binding = 0);

}  // namespace monoplane::vk_core
