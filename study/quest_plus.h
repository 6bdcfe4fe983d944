// QUEST+ (Watson 2017, Journal of Vision 17(3):10) for the 2AFC psychometric function of
// study/psychometric.h: a posterior over a grid of (threshold, slope, lapse), starting uniform;
// each next stimulus is the candidate m whose answer is expected to leave the least entropy in
// the posterior. Everything is exact Bayes on the grid: the state after n answers is the prior
// times the n likelihoods, whatever order they are recorded in. The estimate is the median of
// the threshold's marginal posterior with its equal-tailed 95 % credible interval, each from the
// posterior spread evenly over log-m bins around the grid's thresholds.
#pragma once

#include <cstddef>
#include <vector>

#include "study/adaptive_procedure.h"
#include "study/psychometric.h"

namespace monoplane::study {

struct QuestPlusGrid {
    std::vector<double> thresholds;  // metres, > 0, ascending
    std::vector<double> slopes;      // > 0
    std::vector<double> lapses;      // in [0, 0.5)
};

// threshold_steps values evenly spaced in log m from low to high (both included). Requires
// 0 < low < high and steps >= 2.
std::vector<double> log_spaced(double low, double high, int steps);

class QuestPlus final : public AdaptiveProcedure {
  public:
    // stimuli: the candidate mono planes (> 0, any order, no duplicates); grid: non-empty axes.
    // Asserted, as the protocol validated both.
    QuestPlus(std::vector<double> stimuli, QuestPlusGrid grid);

    double next_mono_plane() const override;
    void record(double m, bool reference_chosen) override;
    int trials() const override { return trials_; }
    ThresholdEstimate estimate() const override;

    // The expected entropy (nats) of the posterior after a trial at stimuli()[i].
    double expected_entropy(std::size_t i) const;
    const std::vector<double>& stimuli() const { return stimuli_; }
    // The normalised posterior; index = (lapse * slopes + slope) * thresholds + threshold.
    const std::vector<double>& posterior() const { return posterior_; }
    const QuestPlusGrid& grid() const { return grid_; }
    PsychometricFunction parameters(std::size_t index) const;

  private:
    std::vector<double> stimuli_;
    QuestPlusGrid grid_;
    std::vector<double> posterior_;
    // P(reference | stimuli_[i], parameters j) at [i * parameters + j], and P(test | ...).
    std::vector<double> reference_likelihood_, test_likelihood_;
    int trials_ = 0;
};

}  // namespace monoplane::study
