// `monoplane rig --error-budget-arcmin A [--disparity] [--budget-depth Z]`: the nearest mono
// plane whose error in visual angle stays within A arcminutes (issue 20, rig/
// error_budget.h), as a readable line or JSON.
#pragma once

#include <ostream>

#include "hmd/profile.h"
#include "rig/error_budget.h"

namespace monoplane::app {

// Prints the choice; throws UserError for what nearest_mono_plane_within refuses.
void print_error_budget(std::ostream& out, const hmd::HmdProfile& profile,
                        const rig::RigInputs& inputs, double budget_arcmin,
                        rig::ErrorMeasure measure, double depth, bool json);

}  // namespace monoplane::app
