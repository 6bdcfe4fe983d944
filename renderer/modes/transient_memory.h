// The renderer's transient images that share device memory: the render graph assigns them to
// shared allocations (graph::plan_aliasing) from their memory requirements and their lifetimes in
// every frame plan the renderer may execute, and each image of a group is bound at offset 0 of
// its group's memory. The executor orders the members' uses (graph::compile's aliasing).
//
// Which images are offered is the views' choice (mode_renderer_internals.h): never the display
// images a headset reads, TAA's history, the shadow map or anything else carried across frames
// (the plans say so, and the graph refuses them); and none of C's images that passes sample near
// the edge of its viewport, which may read texels outside it that no pass of the frame writes.
//
// When may this be called: when a renderer makes its views' images, before any frame uses them.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "renderer/plan/frame_plan.h"
#include "renderer/plan/pass_unit.h"
#include "renderer/vk/image.h"

namespace monoplane::modes {

// Every plan a renderer planned with `options` on `device`, with the pass units `units`, may
// execute: the frame's inputs vary (C skipped or drawn, its culling variant, the debug view, the
// units' debug views included, the shadow map drawn or reused, the read-back on or off).
std::vector<plan::FramePlan> possible_plans(const plan::PlanOptions& options,
                                            const plan::PlanDevice& device,
                                            const std::vector<plan::PassUnitDeclaration>& units);

// An image a view may place in shared memory.
struct TransientImage {
    plan::ResourceKey key;
    vk_core::ImageDesc desc;
};

class TransientMemory {
  public:
    TransientMemory() = default;
    // Plans the groups of `images` over `plans` and allocates one memory for each group of two
    // or more; the others get memory of their own when made.
    TransientMemory(const vk_core::Context& ctx, const std::vector<TransientImage>& images,
                    const std::vector<plan::FramePlan>& plans);
    TransientMemory(TransientMemory&&) = default;
    TransientMemory& operator=(TransientMemory&&) = default;

    // The memory the image of `key` shares with others, or nullptr.
    const vk_core::DeviceMemory* memory_for(const plan::ResourceKey& key) const;
    // The image of `key` with `desc`, in its shared memory or in its own.
    vk_core::Image make(const vk_core::Context& ctx, const plan::ResourceKey& key,
                        const vk_core::ImageDesc& desc) const;

  private:
    std::vector<vk_core::DeviceMemory> memories_;
    std::vector<std::pair<plan::ResourceKey, std::size_t>> placement_;  // key -> memories_
};

// An image of `key`: in `memory`'s shared memory when it places it there, else in its own.
vk_core::Image make_view_image(const vk_core::Context& ctx, const TransientMemory* memory,
                               plan::ViewId view, plan::ImageRole role,
                               const vk_core::ImageDesc& desc);

}  // namespace monoplane::modes
