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

// One compute step of SSAO over `views`: the estimates and filters read the views' linear depth
// and rewrite their scratch and AO images.
void add_ssao_compute(PlanResources& r, std::vector<Step>& steps, std::string name,
                      std::initializer_list<ViewId> views) {
    StepBuilder step(add_step(steps, std::move(name)));
    for (ViewId view : views) {
        step.use(r.image(view, ImageRole::kLinearDepth), Use::kSampledCompute)
            .use(r.image(view, ImageRole::kAoScratch), Use::kStorageWrite)
            .use(r.image(view, ImageRole::kAo), Use::kStorageWrite);
    }
}

void add_ssao_apply(PlanResources& r, std::vector<Step>& steps, ViewId view, bool near_only) {
    StepBuilder step(add_step(steps, view_name(view) + ".apply"));
    step.use(r.image(view, ImageRole::kAo), Use::kSampledFragment)
        .use(r.image(view, ImageRole::kHdr), Use::kColorBlend);
    if (near_only) step.use(r.image(view, ImageRole::kDepth), Use::kDepthTest);
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

std::vector<Step> culling_steps(PlanResources& r) {
    std::vector<Step> steps;
    StepBuilder(add_step(steps, "frustum"))
        .use(r.shared(BufferRole::kDrawLists), Use::kStorageWrite)
        .use(r.shared(BufferRole::kPredicates), Use::kStorageWrite)
        .use(r.shared(BufferRole::kLodState), Use::kStorageWrite);
    return steps;
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

std::vector<Step> depth_pyramid_steps(PlanResources& r) {
    std::vector<Step> steps;
    StepBuilder blocks(add_step(steps, "blocks"));
    for (ViewId eye : kEyeViews)
        blocks.use(r.image(eye, ImageRole::kDepth), Use::kDepthSampledCompute);
    blocks.use(r.shared(ImageRole::kPyramidBlocks), Use::kStorageWrite);
    StepBuilder(add_step(steps, "merge"))
        .use(r.shared(ImageRole::kPyramidBlocks), Use::kStorageRead)
        .use(r.shared(ImageRole::kMergedDepth), Use::kStorageWrite);
    StepBuilder(add_step(steps, "reduce", true))
        .use(r.shared(ImageRole::kMergedDepth), Use::kStorageWrite);
    return steps;
}

std::vector<Step> occlusion_culling_steps(PlanResources& r) {
    std::vector<Step> steps;
    StepBuilder(add_step(steps, "occlusion"))
        .use(r.shared(ImageRole::kMergedDepth), Use::kGeneralSampled)
        .use(r.shared(BufferRole::kDrawLists), Use::kStorageWrite)
        .use(r.shared(BufferRole::kPredicates), Use::kStorageWrite)
        .use(r.shared(BufferRole::kLodState), Use::kStorageRead);
    return steps;
}

std::vector<Step> mono_ssao_steps(PlanResources& r) {
    std::vector<Step> steps;
    for (const char* name : {"estimate", "filter-x", "filter-y"}) {
        add_ssao_compute(r, steps, name, {ViewId::kMono});
    }
    StepBuilder(add_step(steps, "apply"))
        .use(r.image(ViewId::kMono, ImageRole::kAo), Use::kSampledFragment)
        .use(r.image(ViewId::kMono, ImageRole::kHdr), Use::kColorBlend);
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

std::vector<Step> ssao_steps(PlanResources& r, bool stereo, bool near_only) {
    std::vector<Step> steps;
    if (stereo) {
        // One step per dispatch: each dispatch binds both eyes' images, and a shader's storage
        // images count as read and written wherever it could touch them.
        for (const char* name : {"visibility", "estimate", "filter-x", "filter-y"}) {
            for (ViewId eye : kEyeViews) {
                add_ssao_compute(r, steps, std::string(name) + "-" + view_name(eye),
                                 {ViewId::kLeft, ViewId::kRight});
            }
        }
    } else {
        for (ViewId eye : kEyeViews) {
            for (const char* name : {".estimate", ".filter-x", ".filter-y"}) {
                add_ssao_compute(r, steps, view_name(eye) + name, {eye});
            }
        }
    }
    for (ViewId eye : kEyeViews) add_ssao_apply(r, steps, eye, near_only);
    return steps;
}

}  // namespace monoplane::plan
