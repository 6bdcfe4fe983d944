// The weighted up-down staircase (Kaernbach 1991, Perception & Psychophysics 49:227-229) on
// log m: after a reference choice (the participant told the test from the reference) the next
// m is farther, harder, by step_farther; after a test choice it is nearer, easier, by
// step_nearer. Where P(reference) = p the expected step is p * step_farther - (1 - p) *
// step_nearer, zero at p = step_nearer / (step_farther + step_nearer): the staircase hovers
// around the m at which the reference is chosen with that probability (the target). m stays
// within [low, high].
#pragma once

#include <vector>

#include "study/adaptive_procedure.h"

namespace monoplane::study {

class WeightedUpDown final : public AdaptiveProcedure {
  public:
    // Requires 0 < low <= start <= high, 0.5 < target < 1, step_log10 > 0, skip_reversals >= 0
    // (asserted: the protocol validated them). step_farther = step_log10, step_nearer =
    // step_log10 * target / (1 - target).
    WeightedUpDown(double low, double high, double start, double target, double step_log10,
                   int skip_reversals);

    double next_mono_plane() const override { return next_; }
    void record(double m, bool reference_chosen) override;
    int trials() const override { return trials_; }
    // The geometric mean of m at the reversals after the first skip_reversals; with none yet,
    // the next m.
    ThresholdEstimate estimate() const override;

    const std::vector<double>& reversals() const { return reversals_; }  // m where it turned

  private:
    double low_, high_;
    double step_farther_, step_nearer_;  // log10 m
    int skip_reversals_;
    double next_;
    int last_direction_ = 0;  // +1 farther, -1 nearer, 0 before the first answer
    std::vector<double> reversals_;
    int trials_ = 0;
};

}  // namespace monoplane::study
