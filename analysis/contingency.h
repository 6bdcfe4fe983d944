// Pearson's chi-square test of independence for a contingency table, as Fink et al. 2019 sect.
// 6.2 use it for distance x decision ("a weak correlation (phi = 0.07, p > 0.05)"): without
// Yates' continuity correction, with phi = sqrt(chi2 / n) and Cramér's V =
// sqrt(chi2 / (n (min(rows, columns) - 1))); for a k x 2 table the two are equal.
//
// The test assumes independent observations. A study has every participant decide at every
// distance, so the pooled test is the paper's descriptive figure, not valid inference over
// participants: fit_choice_model() (logistic_regression.h) accounts for the repeated measures.
#pragma once

#include <string>
#include <vector>

#include "analysis/dataset.h"
#include "common/result.h"

namespace monoplane::analysis {

struct ChiSquareTest {
    double chi_square = 0;
    int df = 0;
    double p = 1;  // upper tail of the chi-square distribution with df degrees of freedom
    double phi = 0;
    double cramers_v = 0;
    int n = 0;
    std::vector<std::string> row_labels, column_labels;
    std::vector<std::vector<int>> observed;  // [row][column]
};

// The test on a table of counts. Errors: fewer than two rows or columns, a ragged table, a
// negative count, a row or column without any count (its expected counts would be 0).
Result<ChiSquareTest> chi_square_independence(std::vector<std::vector<int>> observed,
                                              std::vector<std::string> row_labels,
                                              std::vector<std::string> column_labels);

// Distance x decision over the analysable trials (others are skipped) of `scene`, or of all
// scenes with "". Rows: the distances present, ascending, labelled in metres ("1.6"); columns:
// test chosen, reference chosen, labelled with the modes ("hybrid", "stereo"). Errors: fewer
// than two distances, or one decision only (everyone chose the same mode).
Result<ChiSquareTest> chi_square_by_distance(const std::vector<TrialRow>& trials,
                                             const std::string& scene = "");

}  // namespace monoplane::analysis
