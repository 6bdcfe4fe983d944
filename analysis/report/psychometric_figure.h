// The report's figure of the psychometric functions of one scene (analysis/psychometric_fits.h):
// the data as the proportion of reference choices per distance (all participants pooled, 95 %
// Wilson bars), the group's fitted curve with its threshold and interval, and each
// participant's fitted curve, thin, behind it. A pure function of the fits.
#pragma once

#include <string>
#include <vector>

#include "analysis/psychometric_fits.h"

namespace monoplane::analysis::report {

// An SVG document for `scene` from those of `fits` that belong to it (the group's fit
// "all" and the participants'); "no data" when the scene has none. `reference_mode`, e.g.
// "stereo", names what was chosen. Any time.
std::string psychometric_svg(const std::vector<PsychometricFit>& fits, const std::string& scene,
                             const std::string& reference_mode);

}  // namespace monoplane::analysis::report
