// The report's psychometric functions (analysis/psychometric_fits.h): their section of
// report.html, the "psychometric" list of summary.json and psychometric.csv.
#pragma once

#include <string>

#include "analysis/report/report.h"
#include "common/json_writer.h"

namespace monoplane::analysis::report {

// The section from its <h2> on, with the figures named psychometric_<scene> from `figures` and a
// table of every fit. Any time after analyse().
std::string psychometric_section_html(const AnalysisResults& results,
                                      const std::vector<Figure>& figures);

// Writes the "psychometric" array into an open JSON object: per fit {"participant" (code or
// "all"), "scene", "threshold_m", "threshold_ci": [lo, hi], "slope", "n"},
// plus "lapse", "estimable", "reason", "interval_method", "participants", "log_likelihood",
// "bootstrap_replicates" and "levels": [{"m", "reference", "trials"}]. Numbers that do not exist
// (no fit, an open end of the interval) are null. Any time after analyse().
void psychometric_json(JsonWriter& json, const AnalysisResults& results);

// participant,scene,n,participants,estimable,threshold_m,threshold_ci_lower,threshold_ci_upper,
// slope,lapse,log_likelihood,interval_method,reason (empty field: no value). Any time after
// analyse().
std::string psychometric_csv(const AnalysisResults& results);

}  // namespace monoplane::analysis::report
