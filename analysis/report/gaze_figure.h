// The gaze density figure of one scene (docs/gaze.md): the smoothed histogram of where the gaze
// fell (gaze_density.h) as a semi-transparent heat map over the scene's left-eye view from the
// seat, or over a plain grey field where there is no picture of the scene. A self-contained SVG
// document: the picture, where given, is embedded as a PNG data URI.
#pragma once

#include <optional>
#include <string>

#include "analysis/gaze_density.h"
#include "analysis/report/gaze_results.h"

namespace monoplane::analysis::report {

// The figure's SVG. `image`: the background, or none for the density alone (the figure then
// says that no picture was rendered).
std::string gaze_density_svg(const GazeDensity& density, const SeatEye& eye,
                             const std::optional<SceneImage>& image);

// A heat map colour for a density relative to its peak (0..1), from dark purple to pale yellow
// (after matplotlib's "inferno"), as "#rrggbb".
std::string heat_color(double relative);

// `bytes` in base64 (RFC 4648, with padding), for the data URI.
std::string base64(const std::string& bytes);

}  // namespace monoplane::analysis::report
