// The plan's table of resources: the handle of each image and buffer a step uses, by view and
// role, made on first use. Every kind of pass is written as a unit
// (renderer/passes/<kind>/<kind>_unit.cpp) that declares its steps' uses through it
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

}  // namespace monoplane::plan
