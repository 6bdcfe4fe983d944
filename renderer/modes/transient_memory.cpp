#include "renderer/modes/transient_memory.h"

#include "renderer/graph/transient_aliasing.h"

namespace monoplane::modes {

std::vector<plan::FramePlan> possible_plans(const plan::PlanOptions& options,
                                            const plan::PlanDevice& device,
                                            const std::vector<plan::PassUnitDeclaration>& units) {
    // The built-in debug views, then the units' (each beside no built-in one).
    std::vector<std::pair<plan::DebugView, std::string>> debug_views;
    for (const plan::DebugView debug :
         {plan::DebugView::kNone, plan::DebugView::kTintMono, plan::DebugView::kStereoOnly,
          plan::DebugView::kMonoOnly, plan::DebugView::kRouting}) {
        debug_views.emplace_back(debug, "");
    }
    for (const plan::PassUnitDeclaration& unit : units) {
        if (unit.debug_view) debug_views.emplace_back(plan::DebugView::kNone, *unit.debug_view);
    }
    std::vector<plan::FramePlan> plans;
    plan::PlanOptions o = options;
    for (const bool read_back : {true, false}) {
        o.read_back = read_back;
        for (const bool mono_skipped : {false, true}) {
            for (const plan::MonoCulling culling :
                 {plan::MonoCulling::kNoOpt, plan::MonoCulling::kDiscard,
                  plan::MonoCulling::kOcclusionCull}) {
                for (const auto& [debug, unit_debug_view] : debug_views) {
                    for (const bool shadow_needed : {true, false}) {
                        const plan::PlanFrame frame{mono_skipped, culling, debug, shadow_needed,
                                                    unit_debug_view};
                        plans.push_back(plan::plan_frame(o, frame, device, units));
                    }
                }
            }
        }
    }
    return plans;
}

TransientMemory::TransientMemory(const vk_core::Context& ctx,
                                 const std::vector<TransientImage>& images,
                                 const std::vector<plan::FramePlan>& plans) {
    std::vector<graph::AliasCandidate> candidates;
    for (const TransientImage& image : images) {
        const vk::MemoryRequirements needs = vk_core::Image::memory_requirements(ctx, image.desc);
        graph::AliasCandidate& candidate = candidates.emplace_back();
        candidate.bytes = needs.size;
        candidate.memory_type_bits = needs.memoryTypeBits;
    }
    for (const plan::FramePlan& plan : plans) {
        const std::vector<graph::FrameLifetime> lifetimes =
            graph::frame_lifetimes(plan.resources, plan.graph_passes(), plan.exports);
        for (std::size_t i = 0; i < images.size(); ++i) {
            const auto handle = plan.handle(images[i].key);
            candidates[i].lifetimes.push_back(handle ? lifetimes[*handle] : graph::FrameLifetime{});
        }
    }
    for (const graph::AliasGroup& group : graph::plan_aliasing(candidates)) {
        if (group.members.size() < 2) continue;
        // Every member at offset 0: any alignment holds.
        memories_.push_back(vk_core::allocate_memory(
            ctx, vk::MemoryRequirements(group.bytes, 1, group.memory_type_bits),
            vk::MemoryPropertyFlagBits::eDeviceLocal, vk_core::MemoryKind::kImage));
        for (std::size_t member : group.members) {
            placement_.emplace_back(images[member].key, memories_.size() - 1);
        }
    }
}

const vk_core::DeviceMemory* TransientMemory::memory_for(const plan::ResourceKey& key) const {
    for (const auto& [placed, memory] : placement_) {
        if (placed == key) return &memories_[memory];
    }
    return nullptr;
}

vk_core::Image TransientMemory::make(const vk_core::Context& ctx, const plan::ResourceKey& key,
                                     const vk_core::ImageDesc& desc) const {
    const vk_core::DeviceMemory* shared = memory_for(key);
    return shared ? vk_core::Image(ctx, desc, *shared) : vk_core::Image(ctx, desc);
}

vk_core::Image make_view_image(const vk_core::Context& ctx, const TransientMemory* memory,
                               plan::ViewId view, plan::ImageRole role,
                               const vk_core::ImageDesc& desc) {
    if (memory == nullptr) return vk_core::Image(ctx, desc);
    return memory->make(ctx, plan::ResourceKey{view, false, role, plan::BufferRole::kDrawLists},
                        desc);
}

}  // namespace monoplane::modes
