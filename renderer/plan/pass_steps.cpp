#include "renderer/plan/pass_steps.h"

namespace monoplane::plan {
namespace {

// Resources carried from frame to frame: read before this frame writes them, or kept for the next.
graph::Lifetime lifetime_of(const ResourceKey& key) {
    // The culling pass reads each chunk's last level of detail before it writes this frame's.
    if (key.is_buffer) {
        return key.buffer == BufferRole::kLodState ? graph::Lifetime::kPersistent
                                                   : graph::Lifetime::kTransient;
    }
    switch (key.image) {
        case ImageRole::kShadowMap:        // kept while the light's region holds
        case ImageRole::kHistory:          // the next frame's history_previous
        case ImageRole::kHistoryPrevious:  // the previous frame's resolve
            return graph::Lifetime::kPersistent;
        default:
            return graph::Lifetime::kTransient;
    }
}

}  // namespace

std::uint16_t PlanResources::handle(const ResourceKey& key) {
    if (auto existing = plan_.handle(key)) return *existing;
    const std::string name = resource_name(key);
    const graph::Lifetime lifetime = lifetime_of(key);
    const std::uint16_t index = key.is_buffer ? plan_.resources.buffer(name, lifetime).index
                                              : plan_.resources.image(name, lifetime).index;
    plan_.keys.push_back(key);
    return index;
}

graph::ImageHandle PlanResources::image(ViewId view, ImageRole role) {
    return {handle({view, false, role, BufferRole::kDrawLists})};
}

graph::BufferHandle PlanResources::buffer(ViewId view, BufferRole role) {
    return {handle({view, true, ImageRole::kHdr, role})};
}

}  // namespace monoplane::plan
