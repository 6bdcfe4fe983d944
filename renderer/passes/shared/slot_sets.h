// A pass unit's descriptor sets: one per frame slot and view, made on first use and rewritten by
// the recording that asks for it. The slot's last frame has completed before the slot is recorded
// again, so its set is free to rewrite, and the images it names may have been remade (or, like
// TAA's history, swap roles) since.
//
// When may this be called: on the thread that records the frame.
#pragma once

#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

#include "renderer/plan/frame_resources.h"
#include "renderer/vk/descriptor_set.h"

namespace monoplane::passes {

class SlotSets {
  public:
    // Sets of `layout`, each from a pool holding `sizes`; ctx and layout must outlive this.
    SlotSets(const vk_core::Context& ctx, vk::DescriptorSetLayout layout,
             std::vector<vk::DescriptorPoolSize> sizes)
        : ctx_(ctx), layout_(layout), sizes_(std::move(sizes)) {}

    // The set of `view` in frame slot `slot`, for the caller to write this frame.
    vk::DescriptorSet at(std::uint32_t slot, plan::ViewId view) {
        auto [entry, added] = sets_.try_emplace({slot, view});
        if (added) entry->second = vk_core::DescriptorSet(ctx_, layout_, sizes_);
        return *entry->second;
    }

  private:
    const vk_core::Context& ctx_;
    vk::DescriptorSetLayout layout_;
    std::vector<vk::DescriptorPoolSize> sizes_;
    std::map<std::pair<std::uint32_t, plan::ViewId>, vk_core::DescriptorSet> sets_;
};

}  // namespace monoplane::passes
