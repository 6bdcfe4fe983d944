// Simulated observers. Each trial's plan is drawn from its own stream of the
// seed, keyed by the trial's index, so a resumed session replays the plans of the interrupted one
// and the order in which trials are planned does not matter.
//
// The "default" model's parameters, and why:
//   P(choose the reference) = 0.5 + 0.5 * kPreference * (1 - exp(-error_px / kErrorScalePx)):
//     at chance for sub-pixel errors, saturating at 0.5 + 0.5 * 0.6 = 0.8 for errors of many
//     pixels (papers/000 reports 59-68 % stereo choices per scene).
//   kViewBothProbability = 0.966: papers/000, 1362 of 1410 decisions had both modes viewed; the
//     others confirm label 1 without switching.
//   extra look-back pairs: geometric, P(k) = 0.4 * 0.6^k, mean 1.5.
//   dwell times: log-normal, median 2.5 s, sigma 0.6, clamped to [0.25 s, 30 s] (a reaction time
//     at least; a wandering participant at most).
//
// "psychometric:threshold=T,slope=B,lapse=L" (issue 21): chooses the reference with the
// probability of study/psychometric.h at the trial's m, whatever the projection error; views
// both labels once, so every decision is valid and moves a staircase.
//
// "gaze:threshold=T,slope=B,lapse=L" (issue 45): the same function of the error where its gaze
// rests (arcmin; docs/gaze.md), rising from chance at no error.
#include "study/observer.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "study/observer_spec.h"
#include "study/random.h"

namespace monoplane::study {
namespace {

constexpr double kPreference = 0.6;
constexpr double kErrorScalePx = 3.0;
constexpr double kViewBothProbability = 0.966;
constexpr double kExtraPairContinue = 0.6;  // geometric: mean 0.6 / (1 - 0.6) = 1.5
constexpr int kMaxExtraPairs = 20;
constexpr double kDwellMedianS = 2.5;
constexpr double kDwellSigma = 0.6;
constexpr double kDwellMinS = 0.25;
constexpr double kDwellMaxS = 30.0;

// Streams apart from the schedule's (study/schedule.cpp uses 1..4): a runner may well pass the
// session's seed to the observer too, and its choices must not echo the label assignment.
constexpr std::uint64_t kTrialStream = 0x0B5E'0000'0000'0000ull;
constexpr std::uint64_t kAnswerStream = 0xA115'0000'0000'0000ull;

std::int64_t draw_dwell_ns(Rng& rng) {
    const double seconds =
        std::clamp(kDwellMedianS * std::exp(kDwellSigma * rng.normal()), kDwellMinS, kDwellMaxS);
    return static_cast<std::int64_t>(std::llround(seconds * 1e9));
}

// Views both labels, looks back and forth `extra_pairs` more times, ends on `label`.
TrialPlan viewing_both(int label, int extra_pairs, Rng& rng) {
    const int dwells = (label == 2 ? 2 : 3) + 2 * extra_pairs;
    TrialPlan plan;
    for (int i = 0; i < dwells; ++i) plan.dwell_ns.push_back(draw_dwell_ns(rng));
    return plan;
}

class ObserverBase : public Observer {
  public:
    explicit ObserverBase(std::uint64_t seed) : seed_(seed) {}

  protected:
    Rng trial_rng(const ScheduledTrial& trial) const {
        return Rng(seed_, kTrialStream + static_cast<std::uint64_t>(trial.index));
    }
    Rng answer_rng(int item) const {
        return Rng(seed_, kAnswerStream + static_cast<std::uint64_t>(item));
    }

  private:
    std::uint64_t seed_;
};

class ChanceObserver final : public ObserverBase {
  public:
    using ObserverBase::ObserverBase;
    std::string_view name() const override { return "chance"; }
    TrialPlan plan_trial(const ScheduledTrial& trial, int, double) override {
        Rng rng = trial_rng(trial);
        const int label = 1 + rng.below(2);
        return viewing_both(label, 0, rng);
    }
    int answer(int item, int scale_points) override {
        if (scale_points <= 1) return 1;
        return 1 + answer_rng(item).below(scale_points);
    }
};

class ReferenceObserver final : public ObserverBase {
  public:
    using ObserverBase::ObserverBase;
    std::string_view name() const override { return "reference"; }
    TrialPlan plan_trial(const ScheduledTrial& trial, int reference_label, double) override {
        Rng rng = trial_rng(trial);
        return viewing_both(reference_label == 2 ? 2 : 1, 0, rng);
    }
    int answer(int, int scale_points) override { return std::max(1, (scale_points + 1) / 2); }
};

class DefaultObserver final : public ObserverBase {
  public:
    using ObserverBase::ObserverBase;
    std::string_view name() const override { return "default"; }
    TrialPlan plan_trial(const ScheduledTrial& trial, int reference_label,
                         double error_px) override {
        Rng rng = trial_rng(trial);
        const double error = std::isfinite(error_px) ? std::max(0.0, error_px) : 0.0;
        const double p_reference =
            0.5 + 0.5 * kPreference * (1.0 - std::exp(-error / kErrorScalePx));
        const bool reference = rng.bernoulli(p_reference);
        const int other_label = reference_label == 2 ? 1 : 2;
        const int label = reference ? (reference_label == 2 ? 2 : 1) : other_label;
        if (!rng.bernoulli(kViewBothProbability)) {
            return TrialPlan{{draw_dwell_ns(rng)}};  // confirms label 1 unseen the other
        }
        int extra_pairs = 0;
        while (extra_pairs < kMaxExtraPairs && rng.bernoulli(kExtraPairContinue)) ++extra_pairs;
        return viewing_both(label, extra_pairs, rng);
    }
    // Binomial(scale - 1, 1/2) + 1: centred on the middle, rarely at the ends.
    int answer(int item, int scale_points) override {
        Rng rng = answer_rng(item);
        int value = 1;
        for (int i = 1; i < scale_points; ++i) value += rng.below(2);
        return value;
    }
};

class PsychometricObserver final : public ObserverBase {
  public:
    PsychometricObserver(const PsychometricFunction& function, std::uint64_t seed)
        : ObserverBase(seed), function_(function) {}
    std::string_view name() const override { return "psychometric"; }
    TrialPlan plan_trial(const ScheduledTrial& trial, int reference_label, double) override {
        Rng rng = trial_rng(trial);
        const bool reference = rng.bernoulli(reference_probability(function_, trial.mono_plane));
        const int reference_at = reference_label == 2 ? 2 : 1;
        return viewing_both(reference ? reference_at : 3 - reference_at, 0, rng);
    }
    int answer(int, int scale_points) override { return std::max(1, (scale_points + 1) / 2); }

  private:
    PsychometricFunction function_;
};

// "gaze:threshold=T,slope=B,lapse=L" (issue 45): the error where its gaze rests is its stimulus
// (the runner passes it as error_px: the trial's error at gaze in arcmin, decides_on_gaze_error),
// chosen as the reference the more often the larger it is; views both labels once.
class GazeObserver final : public ObserverBase {
  public:
    GazeObserver(const PsychometricFunction& function, std::uint64_t seed)
        : ObserverBase(seed), function_(function) {}
    std::string_view name() const override { return "gaze"; }
    bool decides_on_gaze_error() const override { return true; }
    TrialPlan plan_trial(const ScheduledTrial& trial, int reference_label,
                         double error_arcmin) override {
        Rng rng = trial_rng(trial);
        const double e = std::isfinite(error_arcmin) ? std::max(0.0, error_arcmin) : 0.0;
        const double r = std::pow(e / function_.threshold, function_.slope);
        const double p_reference = 0.5 + (0.5 - function_.lapse) * (r / (1.0 + r));
        const int reference_at = reference_label == 2 ? 2 : 1;
        return viewing_both(rng.bernoulli(p_reference) ? reference_at : 3 - reference_at, 0, rng);
    }
    int answer(int, int scale_points) override { return std::max(1, (scale_points + 1) / 2); }

  private:
    PsychometricFunction function_;
};

}  // namespace

std::vector<std::string> observer_names() {
    return {"default", "chance", "reference"};
}

Result<std::unique_ptr<Observer>> make_observer(std::string_view name, std::uint64_t seed) {
    if (name.starts_with(kPsychometricPrefix)) {
        Result<PsychometricFunction> function = parse_psychometric_spec(name);
        MONOPLANE_TRY(function);
        return std::unique_ptr<Observer>(new PsychometricObserver(*function, seed));
    }
    if (name.starts_with(kGazePrefix)) {
        Result<PsychometricFunction> function = parse_gaze_spec(name);
        MONOPLANE_TRY(function);
        return std::unique_ptr<Observer>(new GazeObserver(*function, seed));
    }
    if (name == "default") return std::unique_ptr<Observer>(new DefaultObserver(seed));
    if (name == "chance") return std::unique_ptr<Observer>(new ChanceObserver(seed));
    if (name == "reference") return std::unique_ptr<Observer>(new ReferenceObserver(seed));
    std::string known;
    for (const std::string& n : observer_names()) known += (known.empty() ? "" : ", ") + n;
    return Error{"unknown observer '" + std::string(name) + "' (known observers: " + known +
                 "; or " + std::string(kPsychometricPrefix) + "threshold=T,slope=B,lapse=L, " +
                 std::string(kGazePrefix) + "threshold=T,slope=B,lapse=L)"};
}

}  // namespace monoplane::study
