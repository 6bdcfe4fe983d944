#include "rig/error_budget.h"

#include <cmath>
#include <string>

namespace monoplane::rig {
namespace {

// The error at `depth` for the rig at m (zero beyond the far plane or for depth <= m).
Result<double> error_at(RigInputs inputs, double m, ErrorMeasure measure, double depth) {
    inputs.mono_plane = m;
    inputs.nearest_mono_plane = 0.0;
    Result<Rig> rig = build_rig(inputs);
    if (!rig) return rig.error();
    return measured(angular_error_at_depth(*rig, depth), measure);
}

}  // namespace

double measured(const AngularError& error, ErrorMeasure measure) {
    return measure == ErrorMeasure::kEye ? error.eye_arcmin : error.disparity_arcmin;
}

Result<BudgetChoice> nearest_mono_plane_within(const RigInputs& inputs, double budget_arcmin,
                                               ErrorMeasure measure, double depth) {
    if (!std::isfinite(budget_arcmin) || budget_arcmin <= 0.0) {
        return Error{"error budget: " + std::to_string(budget_arcmin) +
                     " arcmin is not a positive number"};
    }
    if (!(depth > inputs.near)) {
        return Error{"error budget: the depth it must hold for (" + std::to_string(depth) +
                     " m) is not beyond the near plane"};
    }
    // Bisection on log m between just beyond near and just before far: the error falls with m.
    double lo = inputs.near * (1.0 + 1e-9);
    double hi = inputs.far * (1.0 - 1e-9);
    Result<double> at_lo = error_at(inputs, lo, measure, depth);
    if (!at_lo) return at_lo.error();
    Result<double> at_hi = error_at(inputs, hi, measure, depth);
    if (!at_hi) return at_hi.error();
    BudgetChoice choice;
    if (*at_hi > budget_arcmin) {
        choice.mono_plane = inputs.far;
        choice.stereo = true;
        return choice;
    }
    if (*at_lo > budget_arcmin) {
        while (hi / lo > 1.0 + 1e-9) {
            const double mid = std::sqrt(lo * hi);
            Result<double> error = error_at(inputs, mid, measure, depth);
            if (!error) return error.error();
            (*error > budget_arcmin ? lo : hi) = mid;
        }
    } else {
        hi = lo;
    }
    RigInputs at = inputs;
    at.mono_plane = hi;
    at.nearest_mono_plane = 0.0;
    Result<Rig> rig = build_rig(at);
    if (!rig) return rig.error();
    choice.mono_plane = hi;
    choice.error = angular_error_at_depth(*rig, depth);
    return choice;
}

}  // namespace monoplane::rig
