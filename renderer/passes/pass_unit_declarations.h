// Every registered pass unit's declaration (renderer/passes/pass_unit_list.h), Vulkan-free: the
// plan's half of the units (the library monoplane_pass_declarations), and the frame plan with
// them placed.
//
// When may this be called: any time; pure, no device.
#pragma once

#include <string>
#include <vector>

#include "renderer/plan/frame_plan.h"
#include "renderer/plan/pass_unit.h"

namespace monoplane::passes {

// Every unit's declaration, in the registration's order: what plan_frame places.
const std::vector<plan::PassUnitDeclaration>& pass_unit_declarations();
// The `--debug-view` names the units add ("depth"), in that order.
std::vector<std::string> unit_debug_views();
// The frame plan as the renderer plans it: plan::plan_frame with every registered unit.
plan::FramePlan plan_frame(const plan::PlanOptions& options, const plan::PlanFrame& frame,
                           const plan::PlanDevice& device);

}  // namespace monoplane::passes
