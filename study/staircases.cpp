#include "study/staircases.h"

#include <cmath>

#include "common/programming_error.h"

namespace monoplane::study {

Staircases::Staircases(const Protocol& protocol)
    : settings_(protocol.staircase), reference_(protocol.alternatives[0]) {
    MONOPLANE_EXPECTS(protocol.procedure == Procedure::Staircase);
    for (const std::string& scene : protocol.scenes) {
        by_scene_[scene] = make_adaptive_procedure(settings_, protocol.mono_planes);
    }
}

const AdaptiveProcedure& Staircases::procedure(const std::string& scene) const {
    const auto found = by_scene_.find(scene);
    MONOPLANE_EXPECTS(found != by_scene_.end());
    return *found->second;
}

void Staircases::record(const ScheduledTrial& trial, const TrialOutcome& outcome) {
    if (!trial.adaptive || !outcome.valid || outcome.choice == 0) return;
    const auto found = by_scene_.find(trial.scene);
    MONOPLANE_EXPECTS(found != by_scene_.end() && std::isfinite(trial.mono_plane));
    found->second->record(trial.mono_plane, outcome.chosen_mode == reference_);
}

bool Staircases::finished(const std::string& scene) const {
    const AdaptiveProcedure& staircase = procedure(scene);
    if (staircase.trials() >= settings_.trials_per_scene) return true;
    if (!settings_.stop_sd_log10 || staircase.trials() < settings_.min_trials_per_scene) {
        return false;
    }
    const std::optional<double> sd = staircase.estimate().sd_log10;
    return sd && *sd <= *settings_.stop_sd_log10;
}

double Staircases::next_mono_plane(const std::string& scene) const {
    return procedure(scene).next_mono_plane();
}

ThresholdEstimate Staircases::estimate(const std::string& scene) const {
    return procedure(scene).estimate();
}

}  // namespace monoplane::study
