#include "analysis/contingency.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <utility>

#include <boost/math/distributions/chi_squared.hpp>

#include "analysis/exclusions.h"

namespace monoplane::analysis {
namespace {

std::string distance_label(double metres) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, metres);  // shortest
    return std::string(buffer, result.ptr);
}

}  // namespace

Result<ChiSquareTest> chi_square_independence(std::vector<std::vector<int>> observed,
                                              std::vector<std::string> row_labels,
                                              std::vector<std::string> column_labels) {
    const std::size_t rows = observed.size();
    const std::size_t columns = rows == 0 ? 0 : observed[0].size();
    if (rows < 2 || columns < 2)
        return Error{"chi-square test: the table needs at least 2 rows and 2 columns, it has " +
                     std::to_string(rows) + " x " + std::to_string(columns)};
    std::vector<double> row_sum(rows, 0.0), column_sum(columns, 0.0);
    double n = 0.0;
    for (std::size_t r = 0; r < rows; ++r) {
        if (observed[r].size() != columns)
            return Error{"chi-square test: row " + std::to_string(r + 1) + " has " +
                         std::to_string(observed[r].size()) + " columns, not " +
                         std::to_string(columns)};
        for (std::size_t c = 0; c < columns; ++c) {
            if (observed[r][c] < 0) return Error{"chi-square test: a negative count"};
            row_sum[r] += observed[r][c];
            column_sum[c] += observed[r][c];
            n += observed[r][c];
        }
    }
    const auto label = [](const std::vector<std::string>& labels, std::size_t i) {
        return i < labels.size() ? "'" + labels[i] + "'" : std::to_string(i + 1);
    };
    for (std::size_t r = 0; r < rows; ++r)
        if (row_sum[r] == 0.0)
            return Error{"chi-square test: row " + label(row_labels, r) + " has no counts"};
    for (std::size_t c = 0; c < columns; ++c)
        if (column_sum[c] == 0.0)
            return Error{"chi-square test: column " + label(column_labels, c) +
                         " has no counts, so there is nothing to compare"};

    ChiSquareTest test;
    for (std::size_t r = 0; r < rows; ++r) {
        for (std::size_t c = 0; c < columns; ++c) {
            const double expected = row_sum[r] * column_sum[c] / n;
            const double difference = observed[r][c] - expected;
            test.chi_square += difference * difference / expected;
        }
    }
    test.df = static_cast<int>((rows - 1) * (columns - 1));
    test.p = boost::math::cdf(boost::math::complement(
        boost::math::chi_squared_distribution<double>(test.df), test.chi_square));
    test.n = static_cast<int>(n);
    test.phi = std::sqrt(test.chi_square / n);
    test.cramers_v =
        std::sqrt(test.chi_square / (n * static_cast<double>(std::min(rows, columns) - 1)));
    test.observed = std::move(observed);
    test.row_labels = std::move(row_labels);
    test.column_labels = std::move(column_labels);
    return test;
}

Result<ChiSquareTest> chi_square_by_distance(const std::vector<TrialRow>& trials,
                                             const std::string& scene) {
    std::map<double, std::vector<int>> counts;  // distance -> {test chosen, reference chosen}
    std::string test_mode, reference_mode;
    for (const TrialRow& trial : trials) {
        if (!is_analysable(trial) || (!scene.empty() && trial.scene != scene)) continue;
        std::vector<int>& row = counts.try_emplace(trial.mono_plane, 2, 0).first->second;
        ++row[trial.chose_test ? 0 : 1];
        if (test_mode.empty()) test_mode = trial.test_mode;
        if (reference_mode.empty()) reference_mode = trial.reference_mode;
    }
    const std::string what = scene.empty() ? "all scenes" : "scene '" + scene + "'";
    if (counts.size() < 2)
        return Error{"distance x decision chi-square for " + what + ": " +
                     std::to_string(counts.size()) +
                     " distance(s) with analysable trials; it needs at least 2"};
    std::vector<std::vector<int>> observed;
    std::vector<std::string> row_labels;
    for (auto& [distance, row] : counts) {
        row_labels.push_back(distance_label(distance));
        observed.push_back(std::move(row));
    }
    Result<ChiSquareTest> test =
        chi_square_independence(std::move(observed), std::move(row_labels),
                                {test_mode.empty() ? "test" : test_mode,
                                 reference_mode.empty() ? "reference" : reference_mode});
    if (!test)
        return Error{"distance x decision chi-square for " + what + ": " + test.error().message};
    return test;
}

}  // namespace monoplane::analysis
