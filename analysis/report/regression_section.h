// The report's logistic regression of the choice on the distance (logistic_regression.h): its
// section of report.html, its object in summary.json and the rows of logistic.csv (declared in
// report.h). The section leads with the small-sample CR2 test, which holds its error rate with
// few participants, and keeps the CR1 test beside it for comparison with earlier reports and
// with Stata's and statsmodels' defaults.
#pragma once

#include <string>

#include "analysis/report/report.h"
#include "common/json_writer.h"

namespace monoplane::analysis::report {

// The section from its <h2> on; "not estimable" with the reason when there is no fit. Any time
// after analyse().
std::string regression_section_html(const AnalysisResults& results);

// Writes the "logistic" object into an open JSON object (keys in docs/analysis.md). Any time
// after analyse().
void logistic_json(JsonWriter& json, const AnalysisResults& results);

// Writes a fit's "coefficients" array (CR1 and CR2 columns per term) into an open JSON object:
// the "logistic" object's and the gaze regression's.
void coefficients_json(JsonWriter& json, const LogisticFit& fit);

}  // namespace monoplane::analysis::report
