#include "analysis/summaries.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "analysis/exclusions.h"
#include "common/programming_error.h"

namespace monoplane::analysis {
namespace {

template <class ValueOf>
std::vector<GroupSummary> by_scene(const std::vector<TrialRow>& trials, ValueOf value_of) {
    std::map<std::string, std::vector<double>> groups;
    for (const TrialRow& trial : trials)
        if (is_analysable(trial)) groups[trial.scene].push_back(value_of(trial));
    std::vector<GroupSummary> out;
    for (auto& [scene, values] : groups) out.push_back({scene, summarize(std::move(values))});
    return out;
}

}  // namespace

double quantile_sorted(const std::vector<double>& sorted, double p) {
    MONOPLANE_EXPECTS(!sorted.empty() && p >= 0.0 && p <= 1.0);
    const double position = (static_cast<double>(sorted.size()) - 1.0) * p;
    const auto below = static_cast<std::size_t>(std::floor(position));
    const std::size_t above = std::min(below + 1, sorted.size() - 1);
    const double fraction = position - static_cast<double>(below);
    return sorted[below] + fraction * (sorted[above] - sorted[below]);
}

Summary summarize(std::vector<double> values) {
    Summary s;
    s.n = static_cast<int>(values.size());
    if (values.empty()) return s;
    std::sort(values.begin(), values.end());
    s.mean = std::accumulate(values.begin(), values.end(), 0.0) / s.n;
    if (s.n > 1) {
        double squares = 0.0;  // two-pass: no cancellation from sum(x^2) - n mean^2
        for (double v : values) squares += (v - s.mean) * (v - s.mean);
        s.sd = std::sqrt(squares / (s.n - 1));
    }
    s.min = values.front();
    s.max = values.back();
    s.q1 = quantile_sorted(values, 0.25);
    s.median = quantile_sorted(values, 0.5);
    s.q3 = quantile_sorted(values, 0.75);
    return s;
}

std::vector<GroupSummary> decision_times_by_scene(const std::vector<TrialRow>& trials) {
    return by_scene(trials, [](const TrialRow& t) { return t.decision_time_s; });
}

std::vector<GroupSummary> switches_by_scene(const std::vector<TrialRow>& trials) {
    return by_scene(trials, [](const TrialRow& t) { return static_cast<double>(t.switches); });
}

std::vector<ChoiceRate> rates_by_first_scene(const std::vector<TrialRow>& trials) {
    std::map<std::string, std::vector<TrialRow>> groups;
    for (const TrialRow& trial : trials)
        if (is_analysable(trial)) groups[trial.first_scene].push_back(trial);
    std::vector<ChoiceRate> rates;
    for (const auto& [first_scene, group] : groups)
        rates.push_back(choice_rate(group, first_scene));
    return rates;
}

std::vector<ItemSummary> questionnaire_summaries(const std::vector<AnswerRow>& answers) {
    std::map<int, std::vector<const AnswerRow*>> items;
    for (const AnswerRow& answer : answers) items[answer.item].push_back(&answer);
    std::vector<ItemSummary> out;
    for (const auto& [item, rows] : items) {
        ItemSummary summary;
        summary.item = item;
        summary.text = rows.front()->text;
        summary.scale_points = rows.front()->scale_points;
        summary.counts.assign(static_cast<std::size_t>(std::max(summary.scale_points, 0)), 0);
        std::vector<double> values;
        for (const AnswerRow* row : rows) {
            values.push_back(row->answer);
            if (row->answer >= 1 && row->answer <= summary.scale_points)
                ++summary.counts[static_cast<std::size_t>(row->answer - 1)];
        }
        summary.summary = summarize(std::move(values));
        out.push_back(std::move(summary));
    }
    return out;
}

}  // namespace monoplane::analysis
