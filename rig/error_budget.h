// Choosing m by an error budget (issue 20): the nearest mono plane whose angular error
// (angular_error.h) stays within a number of arcminutes. The error falls as m grows (a and b of
// angular_error.h both shrink towards 1 and 0), so the nearest such m is found by bisection.
// Pure; no Vulkan.
#pragma once

#include <limits>

#include "common/result.h"
#include "rig/angular_error.h"
#include "rig/rig.h"

namespace monoplane::rig {

enum class ErrorMeasure {
    kEye,        // AngularError::eye_arcmin: where each eye sees a point, the pixels' error
    kDisparity,  // AngularError::disparity_arcmin: the change of binocular disparity
};

struct BudgetChoice {
    // The nearest m (to 1e-9 relative) whose error at the depth is within the budget; far when
    // no m below it is (hybrid then cannot meet the budget: render stereo).
    double mono_plane = 0.0;
    AngularError error;   // at that m and depth (zero at far)
    bool stereo = false;  // mono_plane == far
};

// Searches m in (near, far) for inputs' eyes, IPD, near and far (inputs.mono_plane and
// nearest_mono_plane are ignored). depth: the farthest depth the error must hold for (the
// farthest visible content; +infinity for any scene). Refuses (Error) a budget that is not
// finite and positive, a depth that is not above near, and inputs build_rig refuses at m
// (its messages). Any time; pure.
Result<BudgetChoice> nearest_mono_plane_within(
    const RigInputs& inputs, double budget_arcmin, ErrorMeasure measure,
    double depth = std::numeric_limits<double>::infinity());

// The error measure's value in an AngularError.
double measured(const AngularError& error, ErrorMeasure measure);

}  // namespace monoplane::rig
