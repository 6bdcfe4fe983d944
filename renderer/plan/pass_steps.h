// The steps of the kinds the renderer records itself and how they use the frame's resources: what
// a pass reads and writes, and in which layout and stage. The frame plan (frame_plan.cpp) calls
// these; the passes (renderer/passes) record exactly these steps in this order, asking the
// executor for each later step's barriers by name (passes::StepSync), and record none themselves.
// A kind written as a unit (TAA, the tone mapping, the depth histogram:
// renderer/passes/<kind>/<kind>_unit.cpp) declares its steps beside its recorder instead
// (renderer/plan/pass_unit.h).
//
// When may this be called: any time; pure, no device.
#pragma once

#include <vector>

#include "renderer/plan/frame_plan.h"

namespace monoplane::plan {

// Handles by key, created on first use: the plan's resource table.
class PlanResources {
  public:
    explicit PlanResources(FramePlan& plan) : plan_(plan) {}
    graph::ImageHandle image(ViewId view, ImageRole role);
    graph::BufferHandle buffer(ViewId view, BufferRole role);
    graph::BufferHandle shared(BufferRole role) { return buffer(ViewId::kNone, role); }
    graph::ImageHandle shared(ImageRole role) { return image(ViewId::kNone, role); }

  private:
    std::uint16_t handle(const ResourceKey& key);
    FramePlan& plan_;
};

// What a forward pass draws into and reads.
struct ForwardUses {
    std::vector<ViewId> views;  // one eye, C, or both eyes (single-pass stereo)
    bool velocity = false;      // TAA
    bool multisampled = false;  // MSAA: drawn into the sample images, resolved into hdr, linear
    bool masks_hidden = false;  // C's mask-hidden draw reads the merged pyramid
};

std::vector<graph::Step> culling_steps(PlanResources& r);
std::vector<graph::Step> forward_steps(PlanResources& r, const ForwardUses& uses);
// "blocks", "merge", "reduce" (repeated once per level after the first).
std::vector<graph::Step> depth_pyramid_steps(PlanResources& r);
std::vector<graph::Step> occlusion_culling_steps(PlanResources& r);
// C's SSAO: estimate, filter-x, filter-y over C alone, then "apply" into C's HDR.
std::vector<graph::Step> mono_ssao_steps(PlanResources& r);
// Hybrid's blended chunks drawn into the eye after the composite: tested against the eye's
// linear depth (sampled), blended into its HDR image.
std::vector<graph::Step> transparency_steps(PlanResources& r, ViewId eye);
// The eyes' SSAO: per eye (estimate, filter-x, filter-y each) or stereo-consistent (visibility,
// estimate, filter-x, filter-y, each once per eye over both eyes' images: "visibility-left",
// "visibility-right", ...), then "left.apply" and
// "right.apply"; near_only: hybrid, the apply is depth-tested against the eye's near content.
std::vector<graph::Step> ssao_steps(PlanResources& r, bool stereo, bool near_only);

}  // namespace monoplane::plan
