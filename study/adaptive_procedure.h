// An adaptive procedure (issue 21): one scene's staircase. It
// says where the next trial's mono plane goes and learns from each answer. Its whole state is a
// function of the answers recorded in order, so a resumed session rebuilds it by recording the
// stored decisions again (replay, study/staircases.h); nothing it knows lives only in memory.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "study/protocol_staircase.h"

namespace monoplane::study {

// The procedure's own estimate of the threshold (the m at which the reference is chosen with
// probability 0.75 - lapse / 2 for QUEST+, with the target probability for the up-down rule).
struct ThresholdEstimate {
    double threshold_m = 0.0;  // QUEST+: the posterior median
    // QUEST+: the posterior's standard deviation of log10 threshold and its equal-tailed 95 %
    // credible interval. The up-down rule has no posterior: unset.
    std::optional<double> sd_log10;
    std::optional<double> lower_m, upper_m;
    int trials = 0;
};

class AdaptiveProcedure {
  public:
    virtual ~AdaptiveProcedure() = default;
    // The mono plane of the next trial, inside the ends of the protocol's mono_planes. Any time.
    virtual double next_mono_plane() const = 0;
    // The answer of a trial shown at m (> 0; any m, not only next_mono_plane()'s).
    virtual void record(double m, bool reference_chosen) = 0;
    virtual int trials() const = 0;
    // The estimate from the answers so far (with none: the prior's, or the start).
    virtual ThresholdEstimate estimate() const = 0;
};

// The procedure `settings` name, over `mono_planes` (the protocol's, at least two, each > 0;
// asserted: the protocol was validated).
std::unique_ptr<AdaptiveProcedure> make_adaptive_procedure(const StaircaseSettings& settings,
                                                           const std::vector<double>& mono_planes);

}  // namespace monoplane::study
