// The plan's table of resources (PlanResources), and the steps of the two kinds the renderer
// still records itself, the forward passes and the transparency, with how they use the frame's
// resources: what a pass reads and writes, and in which layout and stage. The frame plan
// (frame_plan.cpp) calls these; the renderer records exactly these steps in this order. Every
// other kind is written as a unit (renderer/passes/<kind>/<kind>_unit.cpp) and declares its
// steps beside its recorder instead (renderer/plan/pass_unit.h).
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

std::vector<graph::Step> forward_steps(PlanResources& r, const ForwardUses& uses);
// Hybrid's blended chunks drawn into the eye after the composite: tested against the eye's
// linear depth (sampled), blended into its HDR image.
std::vector<graph::Step> transparency_steps(PlanResources& r, ViewId eye);

}  // namespace monoplane::plan
