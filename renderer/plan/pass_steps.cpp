#include "renderer/plan/pass_steps.h"

namespace monoplane::plan {
namespace {

using graph::Step;
using graph::StepBuilder;
using graph::Use;

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

Step& add_step(std::vector<Step>& steps, std::string name, bool repeats = false) {
    Step& step = steps.emplace_back();
    step.name = std::move(name);
    step.repeats = repeats;
    return step;
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

std::vector<Step> forward_steps(PlanResources& r, const ForwardUses& uses) {
    std::vector<Step> steps;
    StepBuilder step(add_step(steps, "draw"));
    // The draw lists' commands and counts (the counts share the predicates' buffer).
    step.use(r.shared(BufferRole::kDrawLists), Use::kIndirectArgs)
        .use(r.shared(BufferRole::kPredicates), Use::kIndirectArgs)
        .use(r.shared(ImageRole::kShadowMap), Use::kSampledFragment);
    if (uses.masks_hidden) step.use(r.shared(ImageRole::kMergedDepth), Use::kGeneralSampled);
    for (ViewId view : uses.views) {
        if (uses.multisampled) {
            step.use(r.image(view, ImageRole::kHdrSamples), Use::kColorWrite)
                .use(r.image(view, ImageRole::kLinearDepthSamples), Use::kColorWrite)
                .use(r.image(view, ImageRole::kDepthSamples), Use::kDepthWrite);
        } else {
            step.use(r.image(view, ImageRole::kDepth), Use::kDepthWrite);
        }
        // Drawn, or resolved into from the samples.
        step.use(r.image(view, ImageRole::kHdr), Use::kColorWrite)
            .use(r.image(view, ImageRole::kLinearDepth), Use::kColorWrite);
        if (uses.velocity) step.use(r.image(view, ImageRole::kVelocity), Use::kColorWrite);
    }
    return steps;
}

std::vector<Step> transparency_steps(PlanResources& r, ViewId eye) {
    std::vector<Step> steps;
    StepBuilder(add_step(steps, "draw"))
        .use(r.shared(BufferRole::kDrawLists), Use::kIndirectArgs)
        .use(r.shared(BufferRole::kPredicates), Use::kIndirectArgs)
        .use(r.shared(ImageRole::kShadowMap), Use::kSampledFragment)
        .use(r.image(eye, ImageRole::kLinearDepth), Use::kSampledFragment)
        .use(r.image(eye, ImageRole::kHdr), Use::kColorBlend);
    return steps;
}

}  // namespace monoplane::plan
