#include "analysis/report/gaze_results.h"

#include <algorithm>
#include <set>
#include <utility>

namespace monoplane::analysis::report {
namespace {

// Running sums of the trials' values, for a mean over those that have one.
struct Mean {
    double sum = 0.0;
    int n = 0;
    void add(const std::optional<double>& value) {
        if (!value) return;
        sum += *value;
        ++n;
    }
    std::optional<double> value() const {
        return n > 0 ? std::optional<double>(sum / n) : std::nullopt;
    }
};

GazeSceneRow scene_row(const Dataset& data, const std::vector<TrialRow>& kept,
                       const std::string& scene) {
    GazeSceneRow row;
    row.scene = scene;
    Mean share, error, fixations;
    for (const TrialRow& t : kept) {
        if (!scene.empty() && t.scene != scene) continue;
        ++row.trials;
        if (t.gaze_error_test_arcmin || t.gaze_share_beyond_m) ++row.trials_with_gaze;
        share.add(t.gaze_share_beyond_m);
        error.add(t.gaze_error_test_arcmin);
        if (t.gaze_fixations) fixations.add(static_cast<double>(*t.gaze_fixations));
    }
    row.share_beyond_m = share.value();
    row.error_test_arcmin = error.value();
    row.fixations_per_trial = fixations.value();
    for (const GazeSampleRow& s : data.gaze_samples)
        row.samples += scene.empty() || s.scene == scene ? 1 : 0;
    return row;
}

}  // namespace

GazeResults analyse_gaze(const Dataset& data, const std::vector<TrialRow>& kept, bool scene_terms,
                         const SeatEye& eye, const std::string& hmd) {
    GazeResults g;
    g.eye = eye;
    g.hmd = hmd;
    const bool trial_gaze = std::any_of(data.trials.begin(), data.trials.end(), [](const auto& t) {
        return t.gaze_error_test_arcmin || t.gaze_share_beyond_m;
    });
    g.recorded = trial_gaze || !data.gaze_samples.empty();
    if (!g.recorded) return g;

    std::set<std::string> scenes;
    for (const TrialRow& t : kept) scenes.insert(t.scene);
    for (const GazeSampleRow& s : data.gaze_samples) scenes.insert(s.scene);
    for (const std::string& scene : scenes) g.by_scene.push_back(scene_row(data, kept, scene));
    g.by_scene.push_back(scene_row(data, kept, ""));

    g.options.predictor = ChoicePredictor::GazeError;
    g.options.scene_terms = scene_terms;
    Result<LogisticFit> fit = fit_choice_model(kept, g.options);
    if (fit) {
        g.fit = std::move(fit).value();
    } else {
        g.fit_error = fit.error().message;
    }

    std::set<std::string> sampled;
    for (const GazeSampleRow& s : data.gaze_samples) sampled.insert(s.scene);
    for (const std::string& scene : sampled)
        g.densities.push_back(gaze_density(data.gaze_samples, scene, eye));
    return g;
}

}  // namespace monoplane::analysis::report
