// The report's gaze section, "Where participants looked" (docs/gaze.md): its part of report.html,
// its "gaze" object in summary.json and its figures (one gaze density per scene). Shown only when
// some session recorded gaze.
#pragma once

#include <string>
#include <vector>

#include "analysis/report/report.h"
#include "common/json_writer.h"

namespace monoplane::analysis::report {

// The section from its <h2> on; "" when no session recorded gaze. Any time after analyse().
std::string gaze_section_html(const AnalysisResults& results, const std::vector<Figure>& figures);

// Writes the "gaze" object into an open JSON object (keys in docs/gaze.md); {"recorded": false}
// alone when no session recorded gaze.
void gaze_json(JsonWriter& json, const AnalysisResults& results);

// gaze_density_<scene> for each scene with gaze samples, over its picture where the app added
// one (GazeResults::images).
std::vector<Figure> gaze_figures(const AnalysisResults& results);

}  // namespace monoplane::analysis::report
