// The report's figures as SVG documents (charts/): the paper's Fig. 7 (choices of the test mode
// per scene over the mono-plane distance, with the 50 % line), decision times and switches per
// scene as boxes. Pure functions of the analysis results.
#pragma once

#include <string>
#include <vector>

#include "analysis/choice_rates.h"
#include "analysis/summaries.h"

namespace monoplane::analysis::report {

// Percent of decisions for `test_mode` per scene (one series each) over m, 95 % Wilson error
// bars, and the 50 % chance line. Scenes are offset by a little along m so their error bars do
// not hide each other (the note under the title says so). `subtitle`: e.g. counts.
std::string choices_svg(const std::vector<ChoiceRate>& by_scene_and_distance,
                        const std::string& test_mode, const std::string& reference_mode,
                        const std::string& subtitle);

// Boxes per scene (quartiles, median, mean, min to max).
std::string decision_times_svg(const std::vector<GroupSummary>& by_scene,
                               const std::string& subtitle);
std::string switches_svg(const std::vector<GroupSummary>& by_scene, const std::string& subtitle);

// A scene name as part of a file name under figures/: scene names may be glTF files' paths
// ("models/room.glb"), whose '/' would name a folder. Letters, digits, '-', '_' and '.' stay;
// anything else becomes '_'.
std::string scene_file_stem(const std::string& scene);

}  // namespace monoplane::analysis::report
