// The report's gaze statistics (docs/gaze.md, "The report's gaze section"), for sessions that
// recorded eye gaze: per scene how much gaze there is, how much of it lay beyond the mono plane
// and hybrid's error where participants looked; the choice regressed on that error; and where
// the gaze fell in each scene's left-eye view from the seat. Pure: no I/O; the app adds the
// scenes' pictures (images) when it can render them.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "analysis/dataset.h"
#include "analysis/gaze_density.h"
#include "analysis/gaze_projection.h"
#include "analysis/logistic_regression.h"

namespace monoplane::analysis::report {

struct GazeSceneRow {
    std::string scene;         // "" for all scenes
    int trials = 0;            // analysed trials
    int trials_with_gaze = 0;  // of them, with a gaze error or a share beyond m
    int samples = 0;           // valid gaze samples on the scene (database input only)
    // Means over the trials that have a value, each trial weighing the same: the share of its
    // gaze points beyond the mono plane, hybrid's mean error at gaze while hybrid was shown.
    std::optional<double> share_beyond_m;
    std::optional<double> error_test_arcmin;
    std::optional<double> fixations_per_trial;  // I-DT fixations while a label was shown
};

// A scene's left eye rendered at the seat, as a PNG file's bytes, for the density's background.
struct SceneImage {
    std::string png;
    int width = 0;
    int height = 0;
};

struct GazeResults {
    // Some trial has gaze, or the inputs hold gaze samples: the report shows the section.
    bool recorded = false;
    std::vector<GazeSceneRow> by_scene;  // scenes alphabetically, then all scenes ("")
    // The choice regressed on gaze_error_test_arcmin (logistic_regression.h), with the distance
    // model's scene terms; unset with the reason when not estimable.
    LogisticOptions options;
    std::optional<LogisticFit> fit;
    std::string fit_error;
    // The view the densities are drawn in, and per scene with samples, its density.
    SeatEye eye;
    std::string hmd = "vive";  // the profile `eye` came from, for captions
    std::vector<GazeDensity> densities;
    // Filled by the app after analyse_gaze(): each scene's left-eye picture where it could be
    // rendered, and why not where it could not (one sentence for the captions; "" when all were).
    std::map<std::string, SceneImage> images;
    std::string image_note;
};

// The gaze statistics of `data`; `kept`: its analysable trials (exclusions.h). Never fails: a
// regression that cannot be estimated leaves fit_error.
GazeResults analyse_gaze(const Dataset& data, const std::vector<TrialRow>& kept, bool scene_terms,
                         const SeatEye& eye, const std::string& hmd);

}  // namespace monoplane::analysis::report
